#pragma once
// Charts for the experiments, drawn by gnuplot (Debian's gnuplot-nox, pngcairo terminal).
// A chart is described here and turned into a gnuplot script that holds its own data, so
// DIR/NAME.gp redraws DIR/NAME.png with `gnuplot NAME.gp` after any edit; the CSV beside it
// stays the source of truth.
// Pure description plus one function that runs gnuplot; not thread-safe.

#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace prt {

struct ChartSeries {
  std::string title;
  std::vector<double> x;  // line charts: one per point; bar charts: unused
  std::vector<double> y;  // one per point (bars: one per category); NaN: missing
  bool dashed = false;    // line charts: e.g. simulated beside real
};

struct Chart {
  enum class Kind { Lines, Bars };
  Kind kind = Kind::Lines;
  std::string title;
  std::string xLabel;
  std::string yLabel;
  bool logX = false;  // lines: base-2 x axis (worker counts)
  bool logY = false;
  std::optional<double> yMin, yMax;     // default: gnuplot's autoscale
  std::vector<std::string> categories;  // bars: one group per category, left to right
  std::vector<ChartSeries> series;
  std::vector<std::pair<std::string, double>> referenceLines;  // labelled horizontal lines
};

// The gnuplot script that draws `chart` into `pngFile` (written as given, relative to the
// directory gnuplot runs in).
std::string gnuplotScript(const Chart& chart, const std::string& pngFile);

// Writes `pngPath` with ".gp" for ".png" (the script, drawing to the PNG's file name, so it
// can be rerun from its directory) and runs gnuplot on it; the PNG appears atomically
// (drawn to a temporary name, then renamed). Returns an empty string on success, else why
// the chart was not drawn (gnuplot missing or failing); the script is written either way.
std::string drawChart(const Chart& chart, const std::string& pngPath);

}  // namespace prt
