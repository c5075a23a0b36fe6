#pragma once
// The master loop of the driver kit: the master's side of a run over any Transport, written
// once for threads and MPI (the simulator drives the same Master in virtual time).
//
//   - The rules (leases, losses, joins, heartbeats, checkpoints) are the MasterReactor's
//     (loops/master_reactor.h), which the simulator pumps too; this is its pump over a
//     Transport: decode what arrives, send what it asks, wait until its next deadline.
//   - Every wait has a deadline: the next heartbeat, the next lease to run out, the next
//     checkpoint, at most a quarter of a second. Nothing is collective; a dead peer can never
//     block the loop.
//   - It measures the master's CPU time outside its waits (MasterLoad::busySeconds).
//   - Once the image is complete, the loop collects the live workers' summaries, waiting at
//     most a lease for each from the Stop, whatever it sends meanwhile, and not at all once a
//     stop signal is pending; a missing one is noted, not waited for.

#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "cluster/master.h"
#include "drive/transport.h"
#include "loops/master_reactor.h"
#include "loops/worker_summary.h"
#include "metrics/events.h"
#include "metrics/run_report.h"

namespace prt {

struct MasterLoopOptions : MasterReactorOptions {
  std::function<int()> interrupted;   // a pending stop signal (0: none); null: never
  // Once the image is complete: whether a stop signal is pending, asked without a word (the
  // image is written, nothing is left to save); null: `interrupted` is asked.
  std::function<bool()> stopPending;
  std::function<bool()> abandoned;    // true: stop now (the driver reports why); null: never
  // Called after every wait, at most a quarter of a second apart, for progress; null: none.
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
