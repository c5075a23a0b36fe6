#pragma once
// MasterReactor: the master's side of a run as a non-blocking state machine around the
// protocol's Master. It never waits, reads no clock and touches no transport: each input
// (a message, a loss or join notice, a deadline) comes with the time, and what it wants done
// is taken from it (messages to send, heartbeats, the next deadline). The pumps feed it:
// the blocking loop over a Transport (drive/master_loop.h, threads and MPI) and the
// simulator in virtual time (sim/simulator.h). So the rules below are written once:
//
//   - Every message renews the sender's lease (Master). A worker is lost when the transport
//     says so (onPeerLost), when it sends bytes that do not decode (onMalformed), or when its
//     lease runs out (onDeadline, no message for `leaseSeconds`); the Master then hands its
//     unfinished tasks to the live workers. A WorkerLost event marks each loss, a
//     WorkerJoined event each joiner (onPeerJoined).
//   - Every `heartbeatSeconds` (onDeadline) a heartbeat goes to each worker the master has
//     sent nothing to for that long, lost ones included (one wrongly presumed lost must not
//     conclude that the master is gone). With heartbeatSeconds infinite none is sent: the
//     transport keeps its peers alive itself (the simulator counts heartbeats from silences
//     and renews leases with onKeepAlive).
//   - `checkpoint` (optional) is called every `checkpointEverySeconds`, after each loss and
//     each rejection, and by the pump when a run fails; it returns when it ended, and the next
//     periodic one is due an interval after that.
//   - It counts its messages in and out, heartbeats included (MasterLoad); the CPU time is the
//     pump's to measure.
//   - After the image is complete it takes the workers' summaries (onSummary).

#include <cstdint>
#include <functional>
#include <limits>
#include <optional>
#include <string>
#include <vector>

#include "cluster/leases.h"
#include "cluster/master.h"
#include "loops/worker_summary.h"
#include "metrics/events.h"
#include "metrics/run_report.h"

namespace prt {

// --checkpoint-every's default: seconds between periodic checkpoints.
inline constexpr double kDefaultCheckpointEverySeconds = 10;

struct MasterReactorOptions {
  double leaseSeconds = kDefaultLeaseSeconds;  // --worker-timeout
  // Master -> worker keep-alive; infinite: the transport's.
  double heartbeatSeconds = heartbeatSecondsFor(kDefaultLeaseSeconds);
  double checkpointEverySeconds = kDefaultCheckpointEverySeconds;  // --checkpoint-every
  // Writes a checkpoint for the reason given; returns the time it ended. Null: none.
  std::function<double(const std::string& why, double now)> checkpoint;
  // Hears every results message before the master takes it (duplicates too: their cost was
  // real), for progress reports; null: none.
  std::function<void(int from, const ResultsMsg& results, double now)> results;
};

class MasterReactor {
 public:
  // `log`: where its events go; null: its own (a pump with the workers' events in the same
  // process, the simulator, may keep one log for all).
  MasterReactor(Master& master, const MasterReactorOptions& options, EventLog* log = nullptr);
  MasterReactor(const MasterReactor&) = delete;  // its log may be its own
  MasterReactor& operator=(const MasterReactor&) = delete;

  // Inputs. Each may leave messages in the outbox.
  void start(double now);
  void onMessage(int from, const Message& message, uint64_t bytes, double now);
  void onMalformed(int from, const std::string& what, double now);
  void onPeerLost(int from, double now);
  // A worker connected; only the next in turn (workerCount()) is admitted.
  void onPeerJoined(int from, double now);
  void onSummary(int from, const Bytes& bytes);
  void onSummary(int from, WorkerSummary summary);
  // The transport heard from `from` at `at` without a message (a simulated keep-alive).
  void onKeepAlive(int from, double at) { master_.renewLease(from, at); }
  // Leases, heartbeats, losses and rejections noted (with their checkpoints), the periodic
  // checkpoint: whatever is due at `now`.
  void onDeadline(double now);
  // Once the run is over: StopMsg to all if the image is complete, the last losses logged,
  // and a checkpoint if it failed (`failure` not empty).
  void finish(const std::string& failure, double now);

  // Outputs.
  double nextDeadline() const;
  Outbox takeOutbox();                // protocol messages to send, in order
  std::vector<int> takeHeartbeats();  // workers to send a HeartbeatMsg (not logged)

  Master& master() { return master_; }
  EventLog& log() { return *log_; }
  MasterLoad& load() { return load_; }
  std::vector<std::optional<WorkerSummary>>& summaries() { return summaries_; }
  bool isWorker(int from) const { return from >= 0 && from < master_.workerCount(); }

 private:
  void take(Outbox out, double now);
  void logLosses();
  void logRejections();
  void checkpoint(const std::string& why, double now);
  void heartbeat(double now);
  double& lastSentTo(int worker);

  Master& master_;
  const MasterReactorOptions& options_;
  EventLog own_;
  EventLog* log_;
  MasterLoad load_;
  Outbox outbox_;
  std::vector<int> heartbeats_;
  std::vector<std::optional<WorkerSummary>> summaries_;
  std::vector<double> lastSent_;  // per worker: when the master last sent it anything
  size_t lossesLogged_ = 0;
  size_t rejectionsLogged_ = 0;
  double nextBeat_ = std::numeric_limits<double>::infinity();
  double nextCheckpoint_ = std::numeric_limits<double>::infinity();
};

}  // namespace prt
