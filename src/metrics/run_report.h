#pragma once
// RunReport: the paper's measurements of one parallel run, computed from the event stream.
//   speedup    = serial seconds / elapsed seconds (the SRT's time over the PRT's)
//   efficiency = sum of workers' execution (busy) time / sum of the time each was there
//                (elapsed * workers when none joined late; a joiner counts from its arrival)
//   masu       = sum over workers of speed_SRT / speed_i (speed indices are times; the serial
//                machine's index is the master's)
//   asu        = speedup / masu
// Without a speed-index run (--speed-index none) there are no indices to compute the MASU
// from; it is then computed from the measured throughput instead:
//   measured masu = sum over workers of (pixels_i / busy_i) / (pixels / serial seconds),
// each worker's rendering rate over the serial machine's. Both kinds are kept apart: the
// JSON gives speed_index_masu/asu (null without a speed index), measured_masu/asu (null
// without a serial time), and masu/asu as the one named by masu_basis.
// Busy time is time spent rendering, including the wait a --slowdown adds to emulate a slower
// machine; idle time is the rest of the time the worker was there (from its arrival, for one
// that joined the running render).
//   ideal_s    = the elapsed time of a perfect balance of the run's work over its workers,
//                each counted from its arrival: the T with sum_i s_i max(0, T - arrival_i) = W,
//                where s_i is worker i's relative speed and W = sum_i s_i busy_i the work done
//                (ideal_basis says where the speeds come from: "slowdown", 1/k_i of an
//                emulated cluster; "speed_index", 1/index_i; or "measured_throughput",
//                pixels_i / busy_i with W the pixels). What a run with joiners is measured
//                against: the MASU assumes every worker there from the start.

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "metrics/events.h"

namespace prt {

// The text table shows one row per worker up to kTableWorkers of them, and past that rows
// for about kTableGroups groups of neighbouring workers.
inline constexpr size_t kTableWorkers = 64;
inline constexpr size_t kTableGroups = 32;

struct WorkerReport {
  int worker = 0;
  double speedIndexSeconds = 0;
  double slowdown = 1;
  uint64_t tasks = 0;   // task messages received (assignments and transfers)
  int threads = 1;      // rendering threads (0: unknown, its summary never came)
  uint64_t framesBuilt = 0;  // frames of the sequence it prepared (0: unknown)
  uint64_t nonFiniteSamples = 0;  // samples it found not finite and left out of their pixels
  std::string host;     // the machine it ran on, as it named itself ("": not known)
  std::string kernels;  // the build of the trace kernels it ran ("x86-64-v4"; "": not known)
  uint64_t pixels = 0;  // pixels rendered (from its events; for a worker whose events never
                        // came, a lost one, the pixels the master accepted from it)
  double busySeconds = 0;
  double idleSeconds = 0;
  uint64_t checkPixels = 0;  // rendered for spot checks of others' pixels (busy time, too)
  uint64_t messagesSent = 0, messagesReceived = 0;
  uint64_t bytesSent = 0, bytesReceived = 0;
  bool lost = false;
  std::optional<double> joinedAtSeconds;  // when it joined the running render (master's clock)
};

// A worker the master declared lost, and what it left behind.
struct LostWorkerInfo {
  int worker = 0;
  double atSeconds = 0;     // on the master's clock
  std::string reason;       // "connection dropped", "silent for 5.0 s", ...
  uint64_t unfinished = 0;  // tasks it held, not done, handed back for reissue
  // When the master last heard from it (heartbeats count): the end of its part in the run.
  // The simulator gives the same, from the heartbeats it models.
  double lastHeardSeconds = 0;
};

// A worker whose results were found wrong (a failed spot check, a message that cannot be
// true): stopped, and every pixel it delivered taken back and rendered again.
struct RejectedWorkerInfo {
  int worker = 0;
  double atSeconds = 0;  // on the master's clock
  std::string reason;
  uint64_t pixelsTakenBack = 0;
  std::string host;  // the machine it said it runs on (empty: unknown)
};

// How the run dealt with faults; all zero in a run without any.
struct FaultInfo {
  std::vector<LostWorkerInfo> lostWorkers;
  std::vector<RejectedWorkerInfo> rejectedWorkers;
  std::vector<std::string> refusedJoiners;  // why each joining job was turned away
  double verifyPercent = 0;        // --verify: the spot checks' base rate (0: off)
  double verifyLowestPercent = 0;  // the lowest rate a worker's pixels were sampled at
  uint64_t verifySeed = 0;         // which pixels were checked (--verify-seed repeats it)
  uint64_t verifiedPixels = 0;     // spot checks that matched
  uint64_t refereeChecks = 0;      // spot checks the master rendered itself
  uint64_t reissuedTasks = 0;    // tasks handed back to the strategy from lost workers
  uint64_t duplicatePixels = 0;  // result copies dropped (reissues raced, endgame copies)
  uint64_t endgameCopies = 0;    // tasks sent as endgame duplicates
  uint64_t resumedPixels = 0;    // pixels taken from a checkpoint instead of rendered
  double workerTimeoutSeconds = 0;  // the lease: silence after which a worker is lost
  double heartbeatSeconds = 0;      // how often workers and master say they are there
  std::vector<int> missingSummaries;  // live workers whose end-of-run summary never came
};

// One frame of a sequence, as the master saw it: when its first result came and when its
// last did (seconds from the run's start), and its pixels (those rendered in this run).
struct FrameInfo {
  int64_t number = 0;
  uint64_t pixels = 0;
  std::optional<double> firstSeconds, doneSeconds;  // none: resumed complete, or not reached
};

// What the master itself did: how long it was busy (CPU time of its loop outside its waits in
// a real run; the modelled service time in a simulated one) and how many messages it took in
// and sent out, heartbeats included. Where one master stops keeping up: busy share near 1.
struct MasterLoad {
  double busySeconds = 0;
  uint64_t received = 0, sent = 0;                      // every message, heartbeats included
  uint64_t heartbeatsReceived = 0, heartbeatsSent = 0;  // of those, heartbeats
  std::string basis = "measured_cpu";                   // or "modelled_service"
  // Checkpoints written, and the wall time the master spent writing them (it takes no
  // message meanwhile); in a simulation, modelled (--checkpoint-every).
  uint64_t checkpoints = 0;
  double checkpointSeconds = 0;
};

struct RunInfo {
  std::string driver;    // "local", "mpi", "simulated"
  std::string strategy;
  int width = 0, height = 0;
  int samplesPerPixel = 1, drtRate = 1;
  double masterSpeedIndexSeconds = 0;   // the serial machine's speed index
  std::vector<double> workerSpeedIndexSeconds;
  std::vector<double> slowdowns;        // per worker, 1 = full speed
  std::vector<uint64_t> tasksReceived;  // per worker
  std::vector<int> threads;             // per worker: rendering threads (0: unknown)
  std::vector<uint64_t> framesBuilt;    // per worker: frames it prepared (0: unknown)
  std::vector<uint64_t> nonFiniteSamples;  // per worker: samples not finite, left out
  std::vector<std::string> hosts;       // per worker: its machine's name ("": not known)
  std::vector<std::string> kernels;     // per worker: its trace kernels' build ("": not known)
  std::vector<std::optional<double>> joinedAt;  // per worker: when it joined; none: at start
  std::vector<uint64_t> acceptedPixels;  // per worker, optional: the pixels of the image whose
                                         // result came first from it (the master's count)
  std::optional<double> serialSeconds;  // for speed-up; absent: speed-up not reported
  bool speedIndexRun = true;            // false: the workers' indices are placeholders
  uint64_t rays = 0;
  FaultInfo faults;
  // The frames of a sequence (frames, fps: how frame numbers map to time); empty for a still.
  std::vector<FrameInfo> frames;
  double fps = 0;
  std::optional<MasterLoad> master;  // none: not measured
};

// What the end of a run says of samples found not finite: "N samples were not finite (NaN or
// infinite) and were left out of their pixels' means".
std::string nonFiniteSamplesLine(uint64_t count);

struct RunReport {
  RunInfo info;
  double elapsedSeconds = 0;
  std::optional<double> speedup;
  double efficiency = 0;
  double masu = 0;                 // of masuBasis
  std::optional<double> asu;
  std::string masuBasis = "speed_index";  // or "measured_throughput"
  std::optional<double> speedIndexMasu, speedIndexAsu;  // from the speed indices
  std::optional<double> measuredMasu, measuredAsu;      // from the measured throughput
  uint64_t messages = 0, bytes = 0;
  // The scene's journey: the encoded size of one Scene message (text and meshes), and the
  // seconds from the master's first sending of it to the last worker's receipt.
  uint64_t sceneBytes = 0;
  double sceneTransferSeconds = 0;
  std::optional<double> idealSeconds;  // see ideal_s above; none when nothing was measured
  std::string idealBasis = "slowdown";  // where its speeds come from (see above)
  std::vector<WorkerReport> workers;

  // The master's busy time over the elapsed time (none: not measured).
  std::optional<double> masterBusyShare() const;
  // Samples the workers found not finite, over every worker (non_finite_samples).
  uint64_t nonFiniteSamples() const;

  std::string toJson() const;       // keys: elapsed_s, speedup, efficiency, masu, asu,
                                    // scene_bytes, scene_transfer_s, ...
  std::string toTable() const;      // a readable table for the terminal
};

// `elapsedSeconds` is the master's wall time from sending the scene to writing the image.
RunReport makeReport(const RunInfo& info, const std::vector<Event>& events, double elapsedSeconds);

// The T at which workers of `rates` (pixels per second, 0: absent) present from `arrivals`
// until `departures` (seconds; a shorter list, or infinity: to the end) render `pixels`
// between them when perfectly balanced; none without any rate, or when every worker has left
// before the work is done.
std::optional<double> balancedFinishSeconds(const std::vector<double>& rates,
                                            const std::vector<double>& arrivals, double pixels,
                                            const std::vector<double>& departures = {});

// What the spot checks of a run guarantee, in words: the lowest probability with which each
// pixel a worker delivered was checked, p, and so the chance 1 - (1 - p)^k that a worker that
// returned k wrong pixels was caught; how to make the check exact (--verify 100). The report's
// verify_guarantee and the terminal's spot-check line.
std::string spotCheckGuarantee(const FaultInfo& faults);

// Maximum achievable speed-up: sum of speedIndexSerial / speedIndex_i.
double maximumAchievableSpeedup(double serialSpeedIndex, const std::vector<double>& speedIndices);

}  // namespace prt
