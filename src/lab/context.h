#pragma once
// ExperimentContext: what every experiment needs besides its own logic: options with their
// defaults resolved, the scene at the experiment's size, progress lines, and writing CSV
// files, charts and the summary into the output directory. Internal to the lab library.

#include <string>
#include <utility>
#include <vector>

#include "lab/chart.h"
#include "lab/csv_table.h"
#include "lab/experiment.h"
#include "trace/render_settings.h"
#include "trace/scene.h"

namespace prt {

// The paper's test case `name` (A-D); InputError listing the valid ones otherwise.
RenderSettings testCaseSettings(const std::string& name);

class ExperimentContext {
 public:
  ExperimentContext(std::string name, const ExperimentOptions& options);

  const ExperimentOptions& options() const { return options_; }
  bool quick() const { return options_.quick; }
  int runs() const;                       // options.runs, or 3 (quick: 1)
  std::vector<double> slowdowns() const;  // options.slowdowns, or 2,2,4,4
  // The scene at the requested size (--width, --height), else quickWidth x quickHeight in a
  // quick run, else fullWidth x fullHeight if given, else the scene's own.
  Scene scene(int quickWidth, int quickHeight, int fullWidth = 0, int fullHeight = 0) const;
  // The test case `fallback` unless --case was given; InputError for an unknown case.
  std::string testCase(const std::string& fallback) const;
  RenderSettings settings(const std::string& testCase) const { return testCaseSettings(testCase); }

  // A line on stderr, unless quiet.
  void progress(const std::string& line) const;

  // Writes into the output directory and records the file.
  void write(const CsvTable& table, const std::string& file);
  void draw(const Chart& chart, const std::string& file);
  // Appends Markdown to the summary.
  void say(const std::string& markdown) { output_.summary += markdown; }

  // The MASU a perfect speed index would give the emulated workers: the sum of 1/k_i.
  double emulatedMasu() const;
  // A chart's reference line at emulatedMasu(), labelled "emulated MASU 1.50".
  std::pair<std::string, double> emulatedMasuLine() const;
  // The serial machine's speed index: the fastest of five Towers of Hanoi runs here.
  double masterSpeedIndex(const Scene& scene) const;
  // "4 emulated workers (--slowdown 2,2,4,4) need 1.5 cores; this machine has 2: ...".
  std::string emulationNote() const;
  std::string emulationNote(const std::vector<double>& slowdowns) const;  // of these workers

  ExperimentOutput& output() { return output_; }

 private:
  std::string name_;
  ExperimentOptions options_;
  ExperimentOutput output_;
};

// Markdown table from a CSV table's columns (all, or the named ones in that order).
std::string markdownTable(const CsvTable& table, const std::vector<std::string>& columns = {});

}  // namespace prt
