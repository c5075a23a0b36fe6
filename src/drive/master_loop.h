#pragma once
// The master loop of the driver kit: the master's side of a run over any Transport, written
// once for threads and MPI (the simulator drives the same Master in virtual time).
//
//   - Every wait has a deadline: the next heartbeat, the next lease to run out, the next
//     checkpoint. Nothing is collective; a dead peer can never block the loop.
//   - A worker is lost when the transport says so (PeerLost), when it sends bytes that do not
//     decode, or when its lease runs out (no message for `leaseSeconds`); the Master then
//     hands its unfinished tasks to the live workers. A WorkerLost event marks each loss.
//   - A worker that joins (PeerJoined) is admitted (Master::onWorkerJoined) and marked by a
//     WorkerJoined event; one that joins after the end is told to stop.
//   - Every `heartbeatSeconds` the master sends a heartbeat to each worker it has sent nothing
//     to for that long, so a worker can tell when the master itself is gone (any message
//     shows that; a heartbeat stands in for the silence).
//   - It measures its own load (MasterLoad): CPU time outside its waits, and every message in
//     and out, heartbeats included.
//   - `checkpoint` (optional) is called every `checkpointEverySeconds`, after each loss and
//     when the run fails or is interrupted, with the reason.
//   - Once the image is complete, the loop collects the live workers' summaries, waiting at
//     most a lease for each after its last message; a missing one is noted, not waited for.

#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "cluster/leases.h"
#include "cluster/master.h"
#include "drive/transport.h"
#include "drive/worker_summary.h"
#include "metrics/events.h"
#include "metrics/run_report.h"

namespace prt {

struct MasterLoopOptions {
  double leaseSeconds = kDefaultLeaseSeconds;  // --worker-timeout
  double heartbeatSeconds = 1;        // master -> worker keep-alive
  double checkpointEverySeconds = 10; // --checkpoint-every
  std::function<void(const std::string& why)> checkpoint;  // null: no checkpoints
  std::function<int()> interrupted;   // a pending stop signal (0: none); null: never
  std::function<bool()> abandoned;    // true: stop now (the driver reports why); null: never
  // Observers, for progress reports; null: none. `results` hears every results message
  // before the master takes it (duplicates too: their cost was real); `tick` is called after
  // every wait, at most a quarter of a second apart.
  std::function<void(int from, const ResultsMsg& results, double now)> results;
  std::function<void(double now)> tick;
};

struct MasterLoopResult {
  EventLog log;                        // the master's events, on its clock
  double elapsedSeconds = 0;           // from sending the scene to the last result
  std::vector<std::optional<WorkerSummary>> summaries;  // per worker, when it came
  MasterLoad load;                     // the master's own work, up to the last result
  std::string failure;                 // empty when the image is complete
  int interruptSignal = 0;             // the signal that stopped the run, if one did
};

MasterLoopResult runMasterLoop(Transport& net, Master& master, const MasterLoopOptions& options);

}  // namespace prt
