#pragma once
// The simulator: a discrete-event simulation, in virtual time, of a master and workers of
// given speeds on a network (network_model.h), replaying a per-pixel cost map instead of
// rendering. It drives the very Master, Worker and Strategy objects the thread and MPI
// drivers drive, with the same loop as the local driver (drive/local_driver.cpp):
//   - a worker reads all the mail waiting for it before it computes, and none while it
//     computes (setup or a batch); the master handles one message at a time;
//   - setup lasts the worker's speed index, baseSpeedIndex / speed (the local driver's setup
//     is loading the scene and timing the Towers of Hanoi);
//   - a batch lasts (cost(batch) + batchOverhead) / speed, where cost is the map's full-speed
//     seconds;
//   - results carry no colours, but are counted at the size they would have.
// It emits the same event stream (metrics/events.h), hence the same report and Chrome trace,
// with times in virtual seconds; the run ends when the master holds every pixel, as a real
// run does.
// The master's load is modelled: each message it receives keeps it busy for the service time
// (network_model.h); heartbeats, sent as the driver kit's loops send them — by a worker after
// `heartbeatSeconds` without a word to the master, by the master to a worker it has sent
// nothing for as long — are counted from the silences without an event each, and each costs
// the master half a service time (the measured cost of one message in or out, where a
// service is a message in and its reply). The heartbeats that fall in a silence are worked
// off in the master's idle time first, and delay its next service only when it had none.
// The report's master_busy_share is that busy time over the elapsed time. Workers joining
// mid-run are simulated (--join-at: the master admits each at its time, as the master loop
// does on a PeerJoined notice), and so are workers that fail:
//   - --inject-fault W:PIXELS:crash|hang, as in a real run: the worker fails before its next
//     batch once it has rendered PIXELS; a crash drops its connection (the master hears of it
//     one latency later, as the thread driver's does), a hang goes silent;
//   - --mtbf S: each starting worker's machine fails at a time drawn from an exponential
//     distribution of mean S (--seed), once; --fail-share F --fail-at T: a fraction F of the
//     workers, picked at random, fail together at T (a switch, a rack). Such machines go
//     silent, mid-batch too.
// A silent worker is lost a lease (leaseSeconds, --worker-timeout) after the master last heard
// from it: its last message, or the last heartbeat it sent before it failed. The master then
// hands its unfinished tasks back to the strategy, as in a real run; the report lists the
// losses and the reissued tasks. With repairSeconds (--repair), a machine that failed comes
// back that long after, as a new worker that joins the run (numbered after the others) and
// may fail again (--mtbf); not with --join-at. A run whose every worker is lost at once
// throws, as a real master gives up then, even if machines would come back.
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
