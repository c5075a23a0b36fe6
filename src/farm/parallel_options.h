#pragma once
// ParallelOptions: how a parallel render is organised, whatever drives it (threads or MPI).

#include <cstdint>
#include <vector>
#include <string>
#include <vector>

#include "balance/registry.h"
#include "cluster/leases.h"
#include "cluster/run_plan.h"
#include "loops/master_reactor.h"
#include "cluster/worker.h"
#include "core/task_set.h"
#include "core/speed_index.h"
#include "core/speed_schedule.h"
#include "cluster/fault_injection.h"
#include "farm/speed_index_kind.h"

namespace prt {

// FaultInjection (--inject-fault): cluster/fault_injection.h.


// A render expected to take longer than this (elapsed + ETA) keeps a checkpoint beside its
// output without being asked (--no-checkpoint: never).
inline constexpr double kAutomaticCheckpointSeconds = 30;

// The plan (strategy, batches, lease, faults, joins: cluster/run_plan.h), shared with the
// simulator, and what only a real run has.
struct ParallelOptions : RunPlan {
  int workers = 4;                     // local driver: worker threads; MPI: ranks - 1
  std::vector<double> slowdowns;       // per worker, each >= 1; empty: all 1
  std::vector<SpeedChange> slowdownChanges;  // --slowdown-at: factors >= 1 from a time on
  double batchSeconds = WorkerOptions::kSmallScaleBatchSeconds;  // batches grow to this much
                                       // work (WorkerOptions; the CLI: defaultBatchSeconds)
  int threads = 1;                     // rendering threads of each worker; 0: all the CPUs
                                       // its affinity allows (mpirun --bind-to sets it)
  SpeedIndexKind speedIndexKind = SpeedIndexKind::Hanoi;  // what each worker measures
  int speedIndexDiscs = kSpeedIndexDiscs;  // size of each worker's Towers of Hanoi run
  // faults (RunPlan): worker W is rank W+1 under MPI. workerTimeoutSeconds: the CLI sets
  // defaultLeaseSeconds for the worker count.
  double verifyPercent = 1;            // --verify: spot checks (cluster/spot_checks.h); 0: off
  uint64_t verifySeed = 0;             // which pixels are checked; 0: drawn at random per run
                                       // (the report gives it: --verify-seed repeats it)
  std::string checkpointPath;          // empty: no checkpoints
  // The path is the automatic one: nothing is written until the run is expected to take
  // more than kAutomaticCheckpointSeconds, or is stopped with pixels done.
  bool checkpointAutomatic = false;
  // The automatic checkpoint is written every checkpointEverySeconds from the start, once
  // pixels are done, not only once the run is expected to be long: for a job that a lost
  // worker ends without warning (mpirun without --enable-recovery kills every rank about a
  // second after one dies, SIGKILL a few milliseconds after SIGTERM), where only what is
  // already on disk survives.
  bool checkpointFromStart = false;
  bool announceCheckpoint = true;      // say on stderr when the automatic one starts
  double checkpointEverySeconds = kDefaultCheckpointEverySeconds;  // between periodic checkpoints
  std::string acceptWorkersPath;       // open doors for `prt join`: addresses and secret in this file
  std::string acceptAddress;           // the TCP door's [ADDRESS][:PORT] ("": every interface, any port)
  // joins (RunPlan): threads only.

  // Every worker of the run: the starting ones and those that join (per-worker lists such as
  // --slowdown cover them all).
  int totalWorkers() const { return workers + joinerCount(); }

  double slowdownOf(int worker) const {
    // A worker past the list (one that joined under MPI, with its own --slowdown) is not
    // slowed by the master's.
    const auto w = static_cast<size_t>(worker);
    return w < slowdowns.size() ? slowdowns[w] : 1.0;
  }
  std::vector<SpeedChange> slowdownChangesOf(int worker) const {
    return changesOf(slowdownChanges, worker);
  }
};

// Throws InputError for options no driver can run: a slowdown list of the wrong length or
// with values below 1, an unknown strategy or bad strategy options, more workers than pixels,
// a join wave at a negative time or of no workers.
void validateParallelOptions(const ParallelOptions& options, uint64_t pixelCount);

}  // namespace prt
