#pragma once
// Master: the master's side of the protocol as an I/O-free state machine. A driver (the driver
// kit's MasterLoop over threads or MPI, or the simulator) delivers messages, lost-worker
// verdicts and the time, and sends whatever comes back; the master never touches a transport,
// a thread or the clock (times are passed in, in seconds on the driver's clock). It owns the
// strategy and carries out its decisions, keeps the Ledger of who holds what, and hands each
// batch of new results to the driver's sink.
//
// Faults: a worker is lost when the driver says so (its connection dropped, its thread
// ended) or when its lease runs out (expireLeases: no message, not even a heartbeat, for the
// lease). Its unfinished tasks go back through the strategy to the live workers — also when
// no live worker holds anything, since every worker the strategy gave nothing at the start is
// entered as having asked. A result is accepted once: a late or duplicate copy is dropped.
//
// Task leases (cluster/task_leases.h, on with MasterOptions::taskLease): a worker that holds
// unfinished tasks and returns no result for its task lease is lost as well, heartbeats or
// not, and what it holds is reissued.
//
// Transfers: a worker's transfer notice must answer the master's oldest open order to it
// (the same receiver, no more tasks than ordered), and move only tasks it holds (beyond what
// peers were ordered to send it and may be on the way). A notice that cannot be true rejects
// its sender, as any implausible message does.
//
// Joining: a worker may join the running render (onWorkerJoined), numbered in arrival order
// after the others. It gets the scene; once its speed index is in, the strategy hears of it
// (Strategy::onWorkerJoined, in index order) and its request is entered. One that joins
// before the strategy started counts as one of the starting workers, unless it has not
// reported its speed index a lease after they all have: the strategy then starts without it
// (while a starting worker is live), and hears of it as of any joiner once it reports. One
// that joins after the image is complete is told to stop.
//
// Spot checks: with MasterOptions::checks on, a sample of every worker's accepted pixels is
// rendered again by another worker (or by the referee, the master's own render) and compared
// bit for bit. A mismatch between two workers is settled by the referee; a worker that
// differs from it is rejected: told to stop, ignored from then on, and every pixel it
// delivered is taken back and reissued. The image is complete only once every check is in.
// Not thread-safe: one driver thread calls it.

#include <algorithm>
#include <cstdint>
#include <functional>
#include <limits>
#include <memory>
#include <string>
#include <vector>

#include "balance/strategy.h"
#include "cluster/endgame_order.h"
#include "cluster/ledger.h"
#include "cluster/messages.h"
#include "cluster/spot_checks.h"
#include "cluster/task_leases.h"
#include "cluster/task_map.h"

namespace prt {

// Receives each pixel's result once: `rgb` holds 3 floats per task of `tasks`, in order, or
// nothing when the results come from the simulator, which renders no colours.
using ResultSink =
    std::function<void(int worker, const TaskSet& tasks, const std::vector<float>& rgb)>;

// A worker whose results were found wrong: told to stop, its pixels taken back.
struct RejectedWorker {
  int worker = 0;
  double atSeconds = 0;
  std::string reason;
  uint64_t pixelsTakenBack = 0;
  std::string host;  // the machine it said it runs on (empty: unknown)
};

// Renders pixels on the master itself (3 floats a pixel), for spot checks no other worker
// can do and to settle a disagreement between two workers.
using Referee = std::function<std::vector<float>(const TaskSet& pixels)>;

struct MasterOptions {
  TaskSet resumedDone;  // pixels finished by an earlier run (a checkpoint): never handed out
  bool endgame = false;  // when nothing is left, a worker that asks gets a copy of the tasks
                         // expected to finish last (see Master::endgameCopy)
  // Spot checks (cluster/spot_checks.h): on with a referee and a sink (colours to compare).
  SpotCheckOptions checks = {0, 0};
  Referee referee;
  // The pixels of a rejected worker, taken back: they leave the image (the driver clears them)
  // and are rendered again.
  std::function<void(int worker, const TaskSet& pixels)> takenBack;
  // Whether a worker may take part, by what it says of itself (its build): empty to admit it,
  // else why not (it is then rejected). Null: everyone is admitted (the simulator).
  std::function<std::string(const WorkerIdentity&)> admit;
  // Told of each rejection as it happens (a driver's blocklist for later joiners).
  std::function<void(const RejectedWorker&)> rejected;
  // Leases on the tasks each worker holds (cluster/task_leases.h); off by default.
  TaskLeaseOptions taskLease;
};


class Master {
 public:
  Master(std::unique_ptr<Strategy> strategy, int workerCount, uint64_t pixelCount,
         SceneMsg scene, ResultSink sink, MasterOptions options = {});

  Outbox start(double now);  // the scene, to every worker; every lease starts now
  // StopMsg to every worker if the image is complete and they were not told yet: a run
  // resumed from a checkpoint that holds every pixel has nothing to hand out.
  Outbox stopIfComplete();
  Outbox onMessage(int from, const Message& message, double now);
  // The driver's verdict that `worker` is gone. Its unfinished tasks go back to the strategy;
  // a later result from it is still accepted where it is the first.
  Outbox onWorkerLost(int worker, double now, const std::string& reason);
  // The transport heard from `worker` at `at` without a message for the protocol (a
  // simulated keep-alive): its lease is renewed, nothing else changes.
  void renewLease(int worker, double at) {
    if (ledger_.isLive(worker)) ledger_.heard(worker, at);
  }
  // Declares lost every live worker silent for more than `leaseSeconds`, and every one whose
  // task lease ran out.
  Outbox expireLeases(double now, double leaseSeconds);
  // When the next lease or task lease runs out (a driver's poll deadline).
  double nextExpiry(double leaseSeconds) const {
    const double start = !started_ && startingMissing_ == 0
                             ? startingReadyAt_ + leaseSeconds
                             : std::numeric_limits<double>::infinity();
    return std::min({ledger_.nextExpiry(leaseSeconds), taskLeases_.nextExpiry(), start});
  }
  // A worker joins at `now`; `worker` must be workerCount() (drivers number joiners in
  // arrival order). Its lease starts now.
  Outbox onWorkerJoined(int worker, double now);

  // Every pixel is in and every spot check of them passed.
  bool complete() const { return ledger_.complete() && checks_.idle(); }
  // Every worker is lost and tasks remain: the run cannot finish.
  bool failed() const { return ledger_.liveCount() == 0 && !complete(); }
  bool stopped() const { return stopped_; }
  bool isLive(int worker) const { return ledger_.isLive(worker); }
  bool holdsWork(int worker) const { return ledger_.isLive(worker) && ledger_.holdsWork(worker); }

  int workerCount() const { return ledger_.workerCount(); }
  uint64_t taskCount() const { return ledger_.taskCount(); }
  uint64_t doneCount() const { return ledger_.doneCount(); }
  uint64_t resumedCount() const { return resumed_; }
  const Ledger& ledger() const { return ledger_; }
  // The pixels a checkpoint may keep: every one done whose spot check is not still open.
  TaskSet checkedDoneSet() const { return ledger_.doneSet(checks_.openPixels()); }
  const std::vector<double>& speedIndices() const { return speedIndices_; }
  const Strategy& strategy() const { return *strategy_; }
  uint64_t endgameCopies() const { return endgameCopies_; }  // tasks sent as duplicates
  const SpotChecks& spotChecks() const { return checks_; }
  const std::vector<RejectedWorker>& rejections() const { return rejections_; }
  // What a worker said of itself with its speed index (empty until then).
  const WorkerIdentity& identity(int worker) const { return identities_[static_cast<size_t>(worker)]; }

 private:
  void startIfReady(Outbox& out, bool force);
  void measured(int worker, double now);
  void startStrategy(int known, Outbox& out);
  void apply(const Decisions& decisions, Outbox& out);
  void assign(int worker, const TaskSet& pixels, Outbox& out);
  void lose(int worker, double now, const std::string& reason, Outbox& out);
  void sendToAll(const Message& m, Outbox& out);
  void finishIfComplete(Outbox& out);
  void answerQueryIfComplete(Outbox& out);
  void endgameCopy(int worker, Outbox& out);
  void introduceJoiners(Outbox& out);
  bool plausible(const Message& message) const;
  std::string unordered(int from, const TransferNoticeMsg& notice);
  ResultsMsg onlyHandedOut(const ResultsMsg& results) const;
  double slowestSpeedIndex() const;
  void check(int author, const TaskSet& fresh, const std::vector<float>& rgb);
  void dispatchChecks(int heardFrom, double now, Outbox& out);
  void settle(const std::vector<Disagreement>& disagreements, double now, Outbox& out);
  void reject(int worker, double now, const std::string& reason, Outbox& out);
  bool rejected(int worker) const;
  void returnToStrategy(int worker, const TaskSet& tasks, Outbox& out);
  std::vector<uint64_t> strategyQueueLengths() const;

  std::unique_ptr<Strategy> strategy_;
  SceneMsg scene_;
  ResultSink sink_;
  MasterOptions options_;
  Ledger ledger_;
  TaskMap map_;  // the strategy's tasks as pixels
  uint64_t resumed_ = 0;

  std::vector<double> speedIndices_;
  int speedIndicesMissing_;  // of the workers there, joiners before the start included
  int startingMissing_;      // of the workers the run started with
  int startingWorkers_;      // the workers the run started with
  double startingReadyAt_ = 0;  // when the last of those reported (or was lost)
  bool started_ = false;  // strategy started (all speed indices in)
  int strategyWorkers_ = 0;  // workers the strategy knows of: 0 .. strategyWorkers_-1
  TaskSet orphans_;          // lost workers' tasks waiting for a joiner (returnToStrategy)
  int orphanOf_ = -1;        // the last worker lost with tasks among them
  bool stopped_ = false;  // StopMsg sent

  bool queryOpen_ = false;
  std::vector<bool> answered_;
  std::vector<uint64_t> queueLengths_;
  std::vector<bool> untrusted_;  // per worker: sent a message that cannot be true; ignored since
  std::vector<bool> endgameServed_;  // per worker: its queue's tail has been copied to another
  EndgameOrder endgameOrder_;        // the candidates for a copy (kept only with options.endgame)
  uint64_t endgameCopies_ = 0;
  SpotChecks checks_;
  std::vector<RejectedWorker> rejections_;
  std::vector<WorkerIdentity> identities_;
  bool dispatching_ = false;
  TaskLeases taskLeases_;
  double now_ = 0;  // the time of the input being handled
  // Per worker: the transfer orders sent to it that it has not answered, oldest first; and
  // how many tasks peers were ordered to send it (less those their notices gave it).
  std::vector<std::vector<TransferOrderMsg>> openOrders_;
  std::vector<uint64_t> inbound_;
};

}  // namespace prt
