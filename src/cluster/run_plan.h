#pragma once
// RunPlan: what a parallel run and its simulation share — how the work is balanced, how a
// worker batches its results, which workers join and which fail, and the lease — with each
// default written once and each value validated in one place. ParallelOptions (the thread and
// MPI drivers, farm/parallel_options.h) and SimulationOptions (sim/simulator.h) are a
// RunPlan plus what only they have; the command line fills the same fields under the same
// flags for `prt render` and `prt simulate`.

#include <cstdint>
#include <string>
#include <vector>

#include "balance/registry.h"
#include "cluster/fault_injection.h"
#include "cluster/leases.h"
#include "cluster/worker.h"
#include "core/speed_schedule.h"

namespace prt {

// --worker-timeout's accepted range, seconds.
inline constexpr double kMinLeaseSeconds = 0.1;
inline constexpr double kMaxLeaseSeconds = 86400;

struct RunPlan {
  std::string strategy = kDefaultStrategy;  // --strategy; see strategyNames()
  StrategyOptions strategyOptions;          // --initial-percent, --chunk, ...
  uint64_t batchPixels = WorkerOptions::kDefaultBatchPixels;  // --batch: pixels per returned
                                                              // batch of results (per thread)
  bool endgame = false;                // --endgame: copies of the last tasks for idle workers
  double workerTimeoutSeconds = kDefaultLeaseSeconds;  // --worker-timeout: the lease, silence
                                       // (not even a heartbeat) after which a worker is lost;
                                       // also the master's, for the workers
  std::vector<FaultInjection> faults;  // --inject-fault
  std::vector<JoinWave> joins;         // --join-at: workers that join mid-render, numbered
                                       // after the others, waves in time order

  int joinerCount() const { return prt::joinerCount(joins); }
  // The heartbeat interval both sides keep for this lease (cluster/leases.h).
  double heartbeatSeconds() const { return heartbeatSecondsFor(workerTimeoutSeconds); }
};

// Throws InputError for a plan no run could use, among `totalWorkers` workers (those that join
// included): an unknown strategy or strategy options out of range, a zero batch, a lease
// outside [kMinLeaseSeconds, kMaxLeaseSeconds], a fault on a worker that is not there, or
// join waves at a negative time or of no workers.
void validateRunPlan(const RunPlan& plan, int totalWorkers);

}  // namespace prt
