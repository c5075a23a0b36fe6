#pragma once
// The worker loop of the driver kit: one worker's side of a run over any Transport, written
// once for threads and MPI (the simulator runs the same Worker state machine in virtual time).
//
//   - All mail waiting is read before the worker computes, and none is handed to the state
//     machine while it computes (setup, or a batch), as the simulator models it. The heavy
//     work runs on an EffectThread so that this loop's thread stays free to send a
//     HeartbeatMsg after `heartbeatSeconds` of silence towards the master while the worker
//     renders or waits: the master's lease on the worker is renewed by any message,
//     heartbeats included, so results sent often make heartbeats unnecessary.
//   - The master heartbeats too; a worker that hears nothing from the master for
//     `masterTimeoutSeconds` stops (the master is gone: nothing it renders can be used).
//   - After StopMsg the worker sends its summary (events, rays, task count) on the summary
//     channel and returns.
//   - The batch wrapper is here, once: fault injection, the Compute/Setup events and the
//     ray count. Throttling is the WorkerEngine's.

#include <cstdint>
#include <functional>
#include <optional>

#include "cluster/leases.h"
#include "cluster/worker.h"
#include "drive/parallel_options.h"
#include "drive/transport.h"
#include "drive/worker_engine.h"

namespace prt {

// What an injected fault does on this transport: `crash` ends the worker abruptly (a local
// thread drops its connection; an MPI rank exits without a word); `hang` never returns while
// the run lasts (it stops answering). Either may return, and the loop then returns too.
struct WorkerFaultActions {
  std::function<void()> crash;
  std::function<void()> hang;
};

struct WorkerLoopOptions {
  uint64_t batchPixels = WorkerOptions::kDefaultBatchPixels;  // pixels per returned batch of
                                                              // results (per thread)
  double batchSeconds = 0;            // batches grow to this much work (WorkerOptions)
  double heartbeatSeconds = 1.0;      // a message to the master at least this often
  double masterTimeoutSeconds = kDefaultLeaseSeconds;  // silence from the master after which
                                                       // the worker stops
  std::optional<FaultInjection> fault;
};

enum class WorkerExit {
  Stopped,     // the image is complete; the summary was sent
  MasterLost,  // the master went silent
  Faulted,     // an injected fault ended it
};

WorkerExit runWorkerLoop(Transport& net, int id, WorkerEngine& engine,
                         const WorkerLoopOptions& options, const WorkerFaultActions& faults);

}  // namespace prt
