// prt experiment NAME --out DIR [--quick]: the paper's experiments, one command each
// (src/lab). Thin: parse the flags, run, print where the results went.

#include <cstdio>
#include <memory>
#include <string>

#include "cli/commands.h"
#include "lab/experiment.h"

namespace prt::cli {

Action addExperimentCommand(CLI::App& app, const std::string& commandLine) {
  std::string names;
  for (const auto& n : experimentNames()) names += (names.empty() ? "" : ", ") + n;
  auto* cmd = app.add_subcommand(
      "experiment",
      "Reproduce one of the paper's experiments: " + names +
          ". Writes CSV files (the source of truth), gnuplot charts and NAME.md, a summary "
          "that says which figures are real runs and which simulated");
  struct Options {
    std::string name;
    ExperimentOptions experiment;
  };
  auto o = std::make_shared<Options>();
  o->experiment.scenePath = "scenes/complex.scene";
  cmd->add_option("name", o->name, "Experiment: " + names)->required();
  cmd->add_option("--out", o->experiment.outDir, "Folder for the results (created if missing)");
  cmd->add_flag("--quick", o->experiment.quick,
                "A reduced version (small images, one run, a shorter sweep) in seconds");
  cmd->add_option("--scene", o->experiment.scenePath, "The benchmark scene")->capture_default_str();
  cmd->add_option("--runs", o->experiment.runs,
                  "Runs per real configuration, reported as medians (default 3; quick 1)")
      ->check(CLI::Range(1, 100));
  cmd->add_option("--width", o->experiment.width, "Image width (default: the experiment's)")
      ->check(CLI::Range(1, 32768));
  cmd->add_option("--height", o->experiment.height, "Image height (default: the experiment's)")
      ->check(CLI::Range(1, 32768));
  cmd->add_option("--slowdown", o->experiment.slowdowns,
                  "The emulated workers of real runs: k_i >= 1 each (default 2,2,4,4; faithful "
                  "while the sum of 1/k_i fits the free cores)")
      ->delimiter(',');
  cmd->add_option("--strategies", o->experiment.strategies,
                  "compare, scale, joins, faults: the strategies (default: all; faults: adaptive, "
                  "reservoir-scatter, hybrid, stealing)")
      ->delimiter(',');
  cmd->add_option("--cases", o->experiment.cases,
                  "table3, compare: the test cases (default A,B,C,D; compare --quick: A,C)")
      ->delimiter(',');
  cmd->add_option("--case", o->experiment.testCase,
                  "speed-index (default A), initial-percent (default C), scale (default A): "
                  "the test case");
  cmd->add_option("--serial-seconds", o->experiment.serialSeconds,
                  "scale, faults: the serial work the cost map is scaled to, seconds (scale: "
                  "3600, quick 60; faults: an hour of balanced job time, quick ten minutes)");
  cmd->add_flag("-q,--quiet", o->experiment.quiet, "No progress lines");
  return [o, commandLine] {
    o->experiment.commandLine = commandLine;
    const ExperimentOutput out = runExperiment(o->name, o->experiment);
    for (const std::string& w : out.warnings) std::fprintf(stderr, "warning: %s\n", w.c_str());
    if (!o->experiment.quiet) {
      std::printf("%s\n", out.summary.c_str());
      std::printf("wrote %zu files to %s\n", out.files.size(), o->experiment.outDir.c_str());
    }
    return 0;
  };
}

}  // namespace prt::cli
