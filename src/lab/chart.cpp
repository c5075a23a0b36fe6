#include "lab/chart.h"

#include <cmath>
#include <cstdio>
#include <filesystem>

#include "core/subprocess.h"
#include "image/atomic_file.h"

namespace prt {
namespace {

namespace fs = std::filesystem;

// A gnuplot string literal (double quotes; backslashes and quotes escaped).
std::string literal(const std::string& text) {
  std::string out = "\"";
  for (char c : text) {
    if (c == '"' || c == '\\') out += '\\';
    out += c;
  }
  return out + "\"";
}

std::string number(double v) {
  if (!std::isfinite(v)) return "NaN";
  char buffer[40];
  std::snprintf(buffer, sizeof buffer, "%.9g", v);
  return buffer;
}

// Line styles: distinct colours, so eight strategies stay apart.
constexpr const char* kColours[] = {"#1f77b4", "#d62728", "#2ca02c", "#9467bd", "#ff7f0e",
                                    "#8c564b", "#e377c2", "#17becf", "#7f7f7f", "#bcbd22"};
constexpr size_t kColourCount = sizeof kColours / sizeof kColours[0];

}  // namespace

std::string gnuplotScript(const Chart& chart, const std::string& pngFile) {
  std::string s;
  s += "# Drawn by prt experiment; run `gnuplot " + fs::path(pngFile).stem().string() +
       ".gp` in this directory to redraw.\n";
  s += "set terminal pngcairo noenhanced size 960,600 font \"sans,11\"\n";
  s += "set output " + literal(pngFile) + "\n";
  s += "set title " + literal(chart.title) + "\n";
  s += "set xlabel " + literal(chart.xLabel) + "\n";
  s += "set ylabel " + literal(chart.yLabel) + "\n";
  s += "set grid ytics\nset key outside right top\nset datafile missing \"NaN\"\n";
  if (chart.logX) s += "set logscale x 2\n";
  if (chart.logY) s += "set logscale y\n";
  s += "set yrange [" + (chart.yMin ? number(*chart.yMin) : std::string("*")) + ":" +
       (chart.yMax ? number(*chart.yMax) : std::string("*")) + "]\n";
  for (size_t i = 0; i < chart.referenceLines.size(); ++i) {
    const auto& [label, y] = chart.referenceLines[i];
    s += "set arrow from graph 0, first " + number(y) + " to graph 1, first " + number(y) +
         " nohead dashtype 2 linecolor rgb \"#555555\"\n";
    s += "set label " + literal(label) + " at graph 0.01, first " + number(y) +
         " offset 0,0.6 textcolor rgb \"#555555\"\n";
  }

  if (chart.kind == Chart::Kind::Lines) {
    for (size_t i = 0; i < chart.series.size(); ++i) {
      const ChartSeries& series = chart.series[i];
      s += "$d" + std::to_string(i) + " << EOD\n";
      for (size_t p = 0; p < series.x.size() && p < series.y.size(); ++p) {
        s += number(series.x[p]) + " " + number(series.y[p]) + "\n";
      }
      s += "EOD\n";
    }
    s += "plot";
    for (size_t i = 0; i < chart.series.size(); ++i) {
      const ChartSeries& series = chart.series[i];
      s += i ? ", \\\n    " : " ";
      s += "$d" + std::to_string(i) + " using 1:2 with linespoints linewidth 2 pointtype " +
           std::to_string(5 + 2 * (i % 4)) + " linecolor rgb \"" + kColours[i % kColourCount] +
           "\"" + (series.dashed ? " dashtype 2" : "") + " title " + literal(series.title);
    }
    s += "\n";
    return s;
  }

  // Bars: one row per category, one column per series.
  s += "$bars << EOD\n";
  for (size_t c = 0; c < chart.categories.size(); ++c) {
    s += literal(chart.categories[c]);
    for (const ChartSeries& series : chart.series) {
      s += ' ';
      s += number(c < series.y.size() ? series.y[c] : NAN);
    }
    s += "\n";
  }
  s += "EOD\n";
  s += "set style data histograms\nset style histogram clustered gap 1\n";
  s += "set style fill solid 0.85 border -1\nset boxwidth 0.9\nset xtics nomirror\n";
  s += "set xrange [-0.6:" + number(static_cast<double>(chart.categories.size()) - 0.4) + "]\n";
  if (!chart.yMin && !chart.logY) {
    s += "set yrange [0:";
    s += chart.yMax ? number(*chart.yMax) : "*";
    s += "]\n";
  }
  s += "plot";
  for (size_t i = 0; i < chart.series.size(); ++i) {
    s += i ? ", \\\n    " : " ";
    s += "$bars using " + std::to_string(i + 2) + (i == 0 ? ":xtic(1)" : "") + " linecolor rgb \"" +
         kColours[i % kColourCount] + "\" title " + literal(chart.series[i].title);
  }
  s += "\n";
  return s;
}

std::string drawChart(const Chart& chart, const std::string& pngPath) {
  const fs::path png = fs::absolute(pngPath);
  const fs::path script = fs::path(png).replace_extension(".gp");
  const std::string text = gnuplotScript(chart, png.filename().string());
  writeFileAtomically(script.string(), text);

  const std::string gnuplot = findProgram("gnuplot");
  if (gnuplot.empty()) {
    return "gnuplot is not installed (Debian: apt-get install gnuplot-nox); run gnuplot " +
           script.filename().string() + " later to draw it";
  }
  // The script names the image relative to gnuplot's working folder: drawn in a scratch
  // folder, the image is then put in place atomically.
  const TempDirectory scratch("prt-chart-");
  const fs::path log = scratch.path() / "gnuplot.log";
  const int status = runProgram(gnuplot, {script.string()}, scratch.path(), log);
  if (const std::string how = describeExit(status); !how.empty()) {
    return "gnuplot " + how + ": " + lastLines(readWholeFile(log), 5);
  }
  const std::string image = readWholeFile(scratch.path() / png.filename());
  if (image.empty()) return "gnuplot drew no image: " + lastLines(readWholeFile(log), 5);
  writeFileAtomically(png.string(), image);
  return "";
}

}  // namespace prt
