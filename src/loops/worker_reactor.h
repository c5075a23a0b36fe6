#pragma once
// WorkerReactor: one worker's side of a run as a non-blocking state machine around the
// protocol's Worker. It never waits, reads no clock, renders nothing and touches no
// transport: the pump hands it what arrives and when its work ends, asks it what to do next
// (set up, render a batch, fail, stop) and sends what it leaves in its outbox. The pumps: the
// worker loop over a Transport (drive/worker_loop.h), which renders on the worker's threads,
// and the simulator (sim/simulator.h), which takes a batch's time from a cost map. So the
// rules below are written once:
//
//   - Mail that arrives while the worker computes (setup, or a batch) waits, and is all read
//     before the next computation starts; mail that arrives while it is idle is read at once.
//   - A HeartbeatMsg goes to the master after `heartbeatSeconds` without a word to it; any
//     message renews the master's lease on the worker, so results sent often make heartbeats
//     unnecessary. A worker that hears nothing from the master for `masterTimeoutSeconds`
//     stops (the master is gone: nothing it renders can be used). Infinite: the transport
//     keeps the peers alive (the simulator counts heartbeats from silences).
//   - An injected fault (--inject-fault): crash or hang before the next batch once the
//     worker has rendered its pixels; corrupt flips bits of every batch from then on.
//   - The Setup and Compute events (a spot check's labelled apart), the messages sent and
//     received, the rays: its summary for the master at the end.

#include <cstdint>
#include <limits>
#include <optional>
#include <string>
#include <vector>

#include "cluster/fault_injection.h"
#include "cluster/leases.h"
#include "cluster/worker.h"
#include "loops/worker_summary.h"
#include "metrics/events.h"

namespace prt {

struct WorkerReactorOptions {
  uint64_t batchPixels = WorkerOptions::kDefaultBatchPixels;  // pixels per returned batch of
                                                              // results, per thread
  double batchSeconds = 0;            // batches grow to this much work (WorkerOptions)
  int threads = 1;                    // a batch keeps every thread busy
  // A message to the master at least this often.
  double heartbeatSeconds = heartbeatSecondsFor(kDefaultLeaseSeconds);
  double masterTimeoutSeconds = kDefaultLeaseSeconds;  // silence from the master after which
                                                       // the worker stops
  std::optional<FaultInjection> fault;
  bool colours = true;                // false: batches come back without colours (simulated)
};

// What the worker does next (WorkerReactor::next).
enum class WorkerStep {
  Wait,    // nothing to do until mail comes
  Setup,   // load the scene (worker().scene()) and measure the speed index; then onSetupDone
  Batch,   // render batch(); then onBatchDone
  Crash,   // the injected fault: end abruptly
  Hang,    // the injected fault: go silent
  Stop,    // the image is complete: send summary() and end
};

class WorkerReactor {
 public:
  // `log`: where its events go; null: its own log, sent with its summary (a pump that keeps
  // many reactors in one process, the simulator, may keep one log for all).
  WorkerReactor(int id, const WorkerReactorOptions& options, EventLog* log = nullptr);
  WorkerReactor(const WorkerReactor&) = delete;  // its log may be its own
  WorkerReactor& operator=(const WorkerReactor&) = delete;

  // Inputs.
  void begin(double now);  // the worker starts listening
  // A message (from the master or a peer); it waits while the worker computes.
  void onMessage(int from, Message message, uint64_t bytes, double now);
  // Bytes that did not decode: a peer's are dropped and counted; the master's throw.
  void onMalformed(int from, const std::string& what);
  void onSetupDone(double now, double speedIndexSeconds, std::optional<uint64_t> taskLimit,
                   WorkerIdentity identity);
  void onBatchDone(double now, std::vector<float> rgb, double computeSeconds, uint64_t rays);
  void onDeadline(double now);  // a heartbeat, if one is due

  // Outputs.
  WorkerStep next(double now);  // only while not computing; a Setup or Batch starts at `now`
  bool computing() const { return computing_; }
  const TaskSet& batch() const { return batch_; }
  bool batchIsCheck() const { return worker_.batchIsCheck(); }
  bool masterSilent(double now) const {
    return now - lastFromMaster_ > options_.masterTimeoutSeconds;
  }
  double nextDeadline() const { return std::min(nextBeat_, lastFromMaster_ +
                                                               options_.masterTimeoutSeconds); }
  Outbox takeOutbox();
  bool takeHeartbeat();  // true once for each HeartbeatMsg due to the master (not logged)
  WorkerSummary summary(int threads, double slowdown, uint64_t framesBuilt = 0,
                        uint64_t nonFiniteSamples = 0);

  const Worker& worker() const { return worker_; }
  EventLog& log() { return *log_; }
  uint64_t rendered() const { return rendered_; }
  double lastBatchSeconds() const { return lastBatchSeconds_; }

 private:
  struct Mail {
    int from;
    Message message;
    uint64_t bytes;
  };
  void handle(const Mail& mail, double now);
  void take(Outbox out, double now);
  void readMail(double now);

  int id_;
  const WorkerReactorOptions options_;  // its own copy: a pump may keep many reactors
  Worker worker_;
  EventLog own_;
  EventLog* log_;
  Outbox outbox_;
  std::vector<Mail> inbox_;
  bool computing_ = false;
  bool heartbeat_ = false;
  double lastFromMaster_ = 0;
  double nextBeat_ = 0;  // the first heartbeat goes out at once
  double workStart_ = 0;
  TaskSet batch_;
  uint64_t rendered_ = 0;
  uint64_t rays_ = 0;
  double lastBatchSeconds_ = 1e9;  // the last batch's time (none yet: assume a long one)
};

}  // namespace prt
