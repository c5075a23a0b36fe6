#pragma once
// The paper's experiments, reproduced one command each (prt experiment NAME --out DIR):
//   table3          serial times of test cases A-D (Table III)                    real
//   speed-index     Towers of Hanoi against a ray-tracing probe as speed index,
//                   with the MASU and ASU each gives (Fig. 17)                     real
//   initial-percent reservoir speed-up and efficiency against the initial
//                   percentage, 5 to 100 (Fig. 18)                                 real + simulated
//   compare         speed-up, efficiency and ASU of every strategy, cases A-D
//                   (Figs. 19-21)                                                  real + simulated
//   scale           the comparison from 4 to 1,024 workers, Arvo and Heirich's
//                   claim about static schemes checked                             simulated
//   joins           one slow worker starts, faster ones join later: every strategy
//                   against the ideal for that schedule (beyond the paper)         real + simulated
//   faults          1,024 workers whose machines fail (MTBF) and come back: job
//                   time against the lease, every strategy beside the ideal        simulated
// Each writes CSV files (the source of truth; a `source` column says real or simulated),
// charts drawn by gnuplot from scripts kept beside them, and NAME.md, a summary saying what
// ran, on what, and which numbers are real runs and which simulated.
//
// Real runs use the local driver with emulated slow workers (--slowdown), which is faithful
// only while the workers' combined demand, the sum of 1/k_i, fits the free cores; the
// summary states the demand against this machine's cores.
// Not thread-safe; runs one configuration at a time.

#include <optional>
#include <string>
#include <vector>

namespace prt {

struct ExperimentOptions {
  std::string outDir;        // created if missing
  bool quick = false;        // a reduced version (small images, one run)
  std::string scenePath;     // the benchmark scene (scenes/complex.scene)
  int runs = 0;              // runs per real configuration; 0: 3, or 1 if quick
  std::optional<int> width;  // image size; default: the experiment's
  std::optional<int> height;
  std::vector<double> slowdowns;        // the emulated workers; empty: 2,2,4,4
  std::vector<std::string> strategies;  // compare, scale; empty: every strategy
  std::vector<std::string> cases;       // table3, compare; empty: A-D (quick: A, C)
  std::string testCase;                 // speed-index (default A), initial-percent (C)
  std::optional<double> serialSeconds;  // scale: the simulated serial time (default 3600 s);
                                        // faults: default an hour of balanced job time
  bool quiet = false;                   // no progress lines on stderr
  std::string commandLine;              // recorded in the summary
};

struct ExperimentOutput {
  std::vector<std::string> files;     // written, relative to outDir, in order
  std::vector<std::string> warnings;  // e.g. a chart gnuplot could not draw
  std::string summary;                // Markdown, also written to outDir/NAME.md
};

std::vector<std::string> experimentNames();

// Runs the named experiment. Throws InputError for an unknown name (listing the valid ones),
// bad options, or an unreadable scene; std::runtime_error if a run fails.
ExperimentOutput runExperiment(const std::string& name, const ExperimentOptions& options);

}  // namespace prt
