#pragma once
// The simulator: a discrete-event simulation, in virtual time, of a master and workers of
// given speeds on a network (network_model.h), replaying a per-pixel cost map instead of
// rendering. It pumps the very MasterReactor and WorkerReactors (loops/) that the thread and
// MPI drivers pump over a transport, around the same Master, Worker and Strategy objects, so
// every rule of a run (mail that waits while a worker computes, leases, losses, joins,
// injected faults, checkpoints, the events) is the drivers' own. What the simulator supplies
// is what a machine and a network would:
//   - setup lasts the worker's speed index, baseSpeedIndex / speed (a real worker's setup is
//     loading the scene and timing the Towers of Hanoi);
//   - a batch lasts (cost(batch) + batchOverhead) / speed, where cost is the map's full-speed
//     seconds; results carry no colours, but are counted at the size they would have;
//   - messages take the network model's time; the master handles one at a time, busy for the
//     service time (network_model.h) before its replies leave;
//   - heartbeats are not sent as events: those a silence holds (one per interval, by a worker
//     without a word to the master, by the master to a worker it has sent nothing) are
//     counted when the silence ends, each costing the master half a service time (worked off
//     in its idle time first), and the live machines' leases are renewed as their heartbeats
//     would renew them (MasterReactor::onKeepAlive). So a machine that fails silently is lost
//     by the reactor's own rule, a lease after it was last heard from, and work stays
//     proportional to messages, not to time;
//   - a checkpoint keeps the master from taking messages for checkpointSecondsPerPixel per
//     pixel done (a real master writes on its own thread, between messages).
// Failures: --inject-fault W:PIXELS:crash|hang as in a real run (a crash drops the connection,
// heard one latency later; a hang goes silent); --mtbf S: each starting machine fails at an
// exponentially distributed time of mean S (--seed); --fail-share F --fail-at T: a fraction F
// fails together at T (a switch, a rack). With repairSeconds (--repair) a failed machine comes
// back that long after as a new worker that joins the run (numbered after the others) and may
// fail again; not with --join-at. --join-at adds workers as PeerJoined notices do. A run whose
// every worker is lost throws, as a real master gives up then, even if machines would come back.
// It emits the same event stream (metrics/events.h) and report (loops/run_info.h), with times
// in virtual seconds; the run ends when the master holds every pixel.
//
// Work is proportional to messages and batches, never to pixels beyond one pass over the
// map (tasks travel as compact runs), so 1,024 workers on a 3840x2160 image take seconds.
// Deterministic: the same inputs give the same report. Single-threaded.

#include <cstdint>
#include <string>
#include <vector>

#include "balance/registry.h"
#include "cluster/fault_injection.h"
#include "cluster/leases.h"
#include "cluster/run_plan.h"
#include "cluster/worker.h"
#include "core/speed_schedule.h"
#include "metrics/events.h"
#include "metrics/run_report.h"
#include "sim/cost_map.h"
#include "sim/network_model.h"

namespace prt {

// The plan (cluster/run_plan.h: strategy, --batch, --endgame, --worker-timeout, faults,
// --join-at), as a real run has it, and what only a simulation has. Joiners: the last
// joinerCount() workers of `speeds`. The lease: silence after which a worker is lost.
// Faults: crash or hang (corrupt is refused).
// A checkpoint's cost to the master per pixel done: writing a 3840x2160 checkpoint took 0.77 s
// with every pixel done and 0.54 s with half of them (in the default's interleaved order, so
// its done set is 0.9 million runs) on the 2-core machine of docs/results.md: about 0.1 us a
// pixel.
inline constexpr double kCheckpointSecondsPerPixel = 1e-7;

struct SimulationOptions : RunPlan {
  std::vector<double> speeds;             // one per worker, those that join included
  double batchSeconds = 0;                // > 0: batches grow to this much work, as a real
                                          // run's do (WorkerOptions); 0: fixed batches
  double batchOverheadSeconds = 0;        // full-speed seconds a batch costs besides its
                                          // pixels (the per-chunk overhead h of the
                                          // scheduling literature: packing results, cold
                                          // caches); scaled by 1 / speed like the pixels
  double baseSpeedIndexSeconds = 0.08;    // the speed index of a speed-1 worker, seconds; also
                                          // the serial machine's (the cost map's recorder)
  std::vector<double> speedIndexSeconds;  // optional, one per worker: the speed indices the
                                          // workers report and set up for, as measured in a
                                          // real run to replay; empty: base / speed
  std::vector<SpeedChange> speedChanges;  // --speed-at: worker W runs at speed X from T s on
  bool speedIndexRun = true;              // false: workers set up at once and report equal
                                          // indices (for strategies that need none)
  bool oracleSpeedIndex = false;          // with speedIndexRun: workers set up at once and
                                          // report their true index (base / speed), as real
                                          // workers do with --speed-index slowdown
  double mtbfSeconds = 0;    // > 0: each starting worker fails once, exponentially distributed
  double failShare = 0;      // with failAtSeconds: this fraction of the workers fails at once
  double failAtSeconds = 0;
  double repairSeconds = 0;  // > 0: a machine that failed (--mtbf, --fail-share) comes back
                             // this long after, as a new worker joining the run
  uint64_t seed = 1;         // for --mtbf and --fail-share
  // --checkpoint-every: every this many seconds (0: never) the master writes a checkpoint, and
  // takes no message for checkpointSecondsPerPixel times the pixels done (a real master writes
  // its checkpoints on its own thread, between messages).
  double checkpointEverySeconds = 0;
  double checkpointSecondsPerPixel = kCheckpointSecondsPerPixel;
  NetworkOptions network;
  uint64_t sceneBytes = 4096;  // the scene text the master sends to each worker
  // A frame sequence: the cost map holds this many frames one above the other (its pixels are
  // the tasks of every frame, as a real sequence's are); 1: a still.
  uint64_t frames = 1;
};

struct SimulatedRun {
  std::vector<Event> events;      // the run's event stream, virtual seconds
  RunReport report;               // driver "simulated"; serial time = the map's total
  uint64_t simulationEvents = 0;  // discrete events processed (a measure of the work done)
  std::vector<int32_t> owner;     // per pixel: the worker that rendered it (the ownership map)
};

// Throws InputError for options no run could use: no workers, more workers than pixels, a
// bad speed list, unknown strategy or bad strategy options, a zero batch, a bad network or a
// speed index that is not positive (or a speed-index list of the wrong length).
void validateSimulationOptions(const SimulationOptions& options, uint64_t pixelCount);

// Validates (as above), then simulates the run to completion.
SimulatedRun simulate(const CostMap& costs, const SimulationOptions& options);

}  // namespace prt
