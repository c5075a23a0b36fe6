#include "lab/experiment.h"

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <ctime>
#include <filesystem>

#include "balance/registry.h"
#include "balance/strategy.h"
#include "core/input_error.h"
#include "core/machine.h"
#include "core/parallel.h"
#include "image/atomic_file.h"
#include "lab/context.h"
#include "lab/experiments.h"
#include "lab/index_page.h"

namespace prt {
namespace {

struct Entry {
  const char* name;
  const char* title;
  void (*run)(ExperimentContext&);
};

constexpr Entry kExperiments[] = {
    {"table3", "Table III: serial times of test cases A-D", runTable3},
    {"speed-index", "Fig. 17: Towers of Hanoi against a ray-tracing probe as speed index",
     runSpeedIndex},
    {"initial-percent", "Fig. 18: reservoir speed-up and efficiency against the initial percentage",
     runInitialPercent},
    {"compare", "Figs. 19-21: speed-up, efficiency and ASU of every strategy, cases A-D",
     runCompare},
    {"scale", "Scaling from 4 to 1,024 simulated workers", runScale},
    {"joins", "Machines that join mid-render: every strategy against the schedule's ideal",
     runJoins},
    {"faults", "Machines that fail in a large farm: job time against the lease and the MTBF",
     runFaults},
};

const Entry& find(const std::string& name) {
  for (const Entry& e : kExperiments) {
    if (name == e.name) return e;
  }
  std::string list;
  for (const Entry& e : kExperiments) list += (list.empty() ? "" : ", ") + std::string(e.name);
  throw InputError("unknown experiment '" + name + "'; valid: " + list);
}

// The 1-minute load average, as a reminder of how busy the machine was; negative if unknown.
double loadAverage() {
  double load[1] = {-1};
  return ::getloadavg(load, 1) == 1 ? load[0] : -1;
}

std::string loadNote(const char* when) {
  char text[160];
  std::snprintf(text, sizeof text, "load average %.2f %s", loadAverage(), when);
  return text;
}

std::string today() {
  const std::time_t now = std::time(nullptr);
  char buffer[32];
  std::tm tm{};
  gmtime_r(&now, &tm);
  std::strftime(buffer, sizeof buffer, "%Y-%m-%d %H:%M UTC", &tm);
  return buffer;
}

void validate(const ExperimentOptions& o) {
  if (o.outDir.empty()) throw InputError("--out DIR is required: where the results go");
  if (o.runs < 0) throw InputError("--runs must be at least 1");
  for (double k : o.slowdowns) {
    if (!(k >= 1) || !std::isfinite(k)) {
      throw InputError("--slowdown values must be finite and at least 1");
    }
  }
  if (o.serialSeconds && !(*o.serialSeconds > 0 && std::isfinite(*o.serialSeconds))) {
    throw InputError("--serial-seconds must be positive");
  }
  for (const std::string& s : o.strategies) strategyRow(s);  // InputError listing the valid names
  for (const std::string& c : o.cases) testCaseSettings(c);
  if (!o.testCase.empty()) testCaseSettings(o.testCase);
  if (!std::filesystem::exists(o.scenePath)) {
    throw InputError("no scene file '" + o.scenePath +
                     "': run from the PRT source folder or pass --scene FILE");
  }
}

}  // namespace

std::vector<std::string> experimentNames() {
  std::vector<std::string> names;
  for (const Entry& e : kExperiments) names.push_back(e.name);
  return names;
}

ExperimentOutput runExperiment(const std::string& name, const ExperimentOptions& options) {
  const Entry& entry = find(name);
  validate(options);
  std::error_code error;
  std::filesystem::create_directories(options.outDir, error);
  if (error || !std::filesystem::is_directory(options.outDir)) {
    throw InputError("cannot create the output folder '" + options.outDir +
                     "': " + (error ? error.message() : "a file of that name is in the way"));
  }

  ExperimentContext cx(name, options);
  cx.say("# " + std::string(entry.title) + "\n\n");
  cx.say("`" + (options.commandLine.empty() ? "prt experiment " + name : options.commandLine) +
         "`, " + today() + ", on " + cpuModel() + " (" +
         std::to_string(hardwareThreads()) + " cores)" +
         (options.quick ? "; **quick version** (small images, reduced sweep)" : "") + ".\n\n");
  const std::string loadBefore = loadNote("at the start");
  entry.run(cx);

  ExperimentOutput& out = cx.output();
  out.summary += "\nMachine load: " + loadBefore + ", " + loadNote("at the end") + " (" +
                 std::to_string(hardwareThreads()) +
                 " cores; real runs are only faithful on an otherwise idle machine).\n";
  out.summary += "\nFiles: ";
  for (size_t i = 0; i < out.files.size(); ++i) {
    out.summary += (i ? ", " : "") + out.files[i];
  }
  out.summary += ".\n";
  for (const std::string& w : out.warnings) out.summary += "\nWarning: " + w + "\n";
  const std::string md = (std::filesystem::path(options.outDir) / (name + ".md")).string();
  writeFileAtomically(md, out.summary);
  out.files.push_back(name + ".md");
  writeExperimentIndex(options.outDir);  // gathers every summary in the folder, this one too
  out.files.push_back("index.html");
  return out;
}

}  // namespace prt
