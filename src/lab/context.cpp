#include "lab/context.h"

#include <cstdio>
#include <filesystem>

#include "core/input_error.h"
#include "core/parallel.h"
#include "farm/speed_probe.h"
#include "lab/csv_table.h"
#include "metrics/run_report.h"
#include "scene/scene_file.h"

namespace prt {

ExperimentContext::ExperimentContext(std::string name, const ExperimentOptions& options)
    : name_(std::move(name)), options_(options) {}

int ExperimentContext::runs() const {
  if (options_.runs > 0) return options_.runs;
  return options_.quick ? 1 : 3;
}

std::vector<double> ExperimentContext::slowdowns() const {
  if (!options_.slowdowns.empty()) return options_.slowdowns;
  return {2, 2, 4, 4};
}

Scene ExperimentContext::scene(int quickWidth, int quickHeight, int fullWidth,
                               int fullHeight) const {
  Scene scene = loadSceneFile(options_.scenePath);
  for (const std::string& w : scene.warnings) std::fprintf(stderr, "warning: %s\n", w.c_str());
  if (options_.quick) {
    scene.image.width = quickWidth;
    scene.image.height = quickHeight;
  } else if (fullWidth > 0 && fullHeight > 0) {
    scene.image.width = fullWidth;
    scene.image.height = fullHeight;
  }
  if (options_.width) scene.image.width = *options_.width;
  if (options_.height) scene.image.height = *options_.height;
  return scene;
}

RenderSettings testCaseSettings(const std::string& name) {
  const auto s = paperTestCase(name);
  if (!s) throw InputError("unknown test case '" + name + "'; valid: A, B, C, D");
  return *s;
}

std::string ExperimentContext::testCase(const std::string& fallback) const {
  const std::string c = options_.testCase.empty() ? fallback : options_.testCase;
  testCaseSettings(c);
  return c;
}

double ExperimentContext::emulatedMasu() const {
  return maximumAchievableSpeedup(1.0, slowdowns());  // worker i's index: k_i times the serial
}

std::pair<std::string, double> ExperimentContext::emulatedMasuLine() const {
  const double masu = emulatedMasu();
  char label[64];
  std::snprintf(label, sizeof label, "emulated MASU %.2f", masu);
  return {label, masu};
}

double ExperimentContext::masterSpeedIndex(const Scene& scene) const {
  return serialSpeedIndexSeconds(SpeedIndexKind::Hanoi, scene, RenderSettings{});
}

void ExperimentContext::progress(const std::string& line) const {
  if (options_.quiet) return;
  std::fprintf(stderr, "[%s] %s\n", name_.c_str(), line.c_str());
  std::fflush(stderr);
}

void ExperimentContext::write(const CsvTable& table, const std::string& file) {
  table.write((std::filesystem::path(options_.outDir) / file).string());
  output_.files.push_back(file);
}

void ExperimentContext::draw(const Chart& chart, const std::string& file) {
  const std::string why =
      drawChart(chart, (std::filesystem::path(options_.outDir) / file).string());
  const std::string script = std::filesystem::path(file).replace_extension(".gp").string();
  output_.files.push_back(script);
  if (why.empty()) {
    output_.files.push_back(file);
  } else {
    output_.warnings.push_back(file + " not drawn: " + why);
  }
}

std::string ExperimentContext::emulationNote() const {
  return emulationNote(slowdowns());
}

std::string ExperimentContext::emulationNote(const std::vector<double>& k) const {
  double demand = 0;  // cores the workers keep busy
  for (double s : k) demand += 1.0 / s;
  std::string list;
  for (double s : k) {
    if (!list.empty()) list += ',';
    list += csvNumber(s);
  }
  const int cores = hardwareThreads();
  char text[512];
  std::snprintf(text, sizeof text,
                "%zu emulated workers (--slowdown %s) need %.2f cores; this machine has %d. ",
                k.size(), list.c_str(), demand, cores);
  std::string note = text;
  if (demand <= static_cast<double>(cores) - 0.25) {
    note +=
        "The emulation is faithful while nothing else runs: the master and the workers' "
        "combined demand fit the free cores.";
  } else {
    note +=
        "**The demand does not fit the cores with room for the master: the slow workers "
        "run slower than emulated and the real figures are pessimistic.**";
  }
  return note;
}

std::string markdownTable(const CsvTable& table, const std::vector<std::string>& columns) {
  std::vector<size_t> index;
  if (columns.empty()) {
    for (size_t i = 0; i < table.columns().size(); ++i) index.push_back(i);
  } else {
    for (const std::string& c : columns) index.push_back(table.column(c));
  }
  std::string out = "|";
  for (size_t i : index) out += " " + table.columns()[i] + " |";
  out += "\n|";
  for (size_t n = 0; n < index.size(); ++n) out += "---|";
  out += "\n";
  for (const auto& row : table.rows()) {
    out += "|";
    for (size_t i : index) out += " " + row[i] + " |";
    out += "\n";
  }
  return out;
}

}  // namespace prt
