#pragma once
// The flags of a RunPlan (cluster/run_plan.h) — --strategy and its options, --batch,
// --worker-timeout, --endgame, --inject-fault, --join-at — registered once for `prt render`
// and `prt simulate`, with the same names, checks and defaults, and turned into the plan in
// one place. RenderOptions and SimulateOptions are RunPlanFlags plus their own flags.

#include <optional>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>

#include "cli/strategy_flags.h"
#include "cluster/run_plan.h"
#include "cluster/worker.h"

namespace prt::cli {

struct RunPlanFlags {
  StrategyFlags strategyFlags;  // --strategy and the strategies' options (addStrategyFlags)
  unsigned long long batchPixels = WorkerOptions::kDefaultBatchPixels;  // --batch
  std::optional<double> workerTimeoutSeconds;  // --worker-timeout; none: defaultLeaseSeconds
  std::string endgame = "off";                 // --endgame on | off
  std::vector<std::string> faults;             // --inject-fault W:PIXELS:crash|hang|corrupt
  std::string joinAt;                          // --join-at T:K,...
};

// Where each flag is listed in --help, and which command it is for: a simulation's times are
// virtual seconds, and it refuses corrupt workers.
struct RunPlanFlagGroups {
  std::string batches;   // --batch, --worker-timeout, --endgame
  std::string joins;     // --join-at
  std::string failures;  // --inject-fault
  bool simulated = false;
};

// Registers --batch, --worker-timeout, --endgame, --join-at and --inject-fault (the strategy
// flags are registered by addStrategyFlags, where each command lists them).
void addRunPlanFlags(CLI::App& cmd, RunPlanFlags& flags, const RunPlanFlagGroups& groups);

// The plan the flags give for a run that starts `startingWorkers` workers (the lease's
// default grows with every worker, those that join included). Throws InputError for a
// malformed --inject-fault or --join-at; validateRunPlan checks the rest.
RunPlan runPlanFrom(const RunPlanFlags& flags, int startingWorkers);

// --inject-fault's W:PIXELS:crash|hang|corrupt, one per spec.
std::vector<FaultInjection> parseFaults(const std::vector<std::string>& specs);

}  // namespace prt::cli
