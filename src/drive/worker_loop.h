#pragma once
// The worker loop of the driver kit: one worker's side of a run over any Transport, written
// once for threads and MPI (the simulator runs the same Worker state machine in virtual time).
//
//   - The rules (mail waits while the worker computes, heartbeats, the master's silence,
//     injected faults, the events of its summary) are the WorkerReactor's
//     (loops/worker_reactor.h), which the simulator pumps too; this is its pump over a
//     Transport, with an Engine (drive/engine.h) that renders.
//   - The heavy work runs on an EffectThread so that this loop's thread stays free to send
//     heartbeats while the worker renders; a batch expected to be short renders here, with
//     heartbeats and mail taken between its pieces.
//   - After StopMsg the worker sends its summary (events, rays, task count) on the summary
//     channel and returns.

#include <cstdint>
#include <functional>
#include <optional>

#include "drive/transport.h"
#include "drive/engine.h"
#include "loops/worker_reactor.h"

namespace prt {

// What an injected fault does on this transport: `crash` ends the worker abruptly (a local
// thread drops its connection; an MPI rank exits without a word); `hang` never returns while
// the run lasts (it stops answering). Either may return, and the loop then returns too.
struct WorkerFaultActions {
  std::function<void()> crash;
  std::function<void()> hang;
};

// Its `threads` is the engine's.
using WorkerLoopOptions = WorkerReactorOptions;

enum class WorkerExit {
  Stopped,     // the image is complete; the summary was sent
  MasterLost,  // the master went silent
  Faulted,     // an injected fault ended it
};

WorkerExit runWorkerLoop(Transport& net, int id, Engine& engine,
                         const WorkerLoopOptions& options, const WorkerFaultActions& faults);

}  // namespace prt
