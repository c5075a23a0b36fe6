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
// Joining: a worker may join the running render (onWorkerJoined), numbered in arrival order
// after the others. It gets the scene; once its speed index is in, the strategy hears of it
// (Strategy::onWorkerJoined, in index order) and its request is entered. One that joins
// before the strategy started counts as one of the starting workers; one that joins after the
// image is complete is told to stop.
// Not thread-safe: one driver thread calls it.

#include <cstdint>
#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "balance/strategy.h"
#include "cluster/ledger.h"
#include "cluster/messages.h"
#include "cluster/task_map.h"

namespace prt {

// Receives each pixel's result once: `rgb` holds 3 floats per task of `tasks`, in order, or
// nothing when the results come from the simulator, which renders no colours.
using ResultSink =
    std::function<void(int worker, const TaskSet& tasks, const std::vector<float>& rgb)>;

struct MasterOptions {
  TaskSet resumedDone;  // pixels finished by an earlier run (a checkpoint): never handed out
  bool endgame = false;  // when nothing is left, a worker that asks gets a copy of the tasks
                         // expected to finish last (see Master::endgameCopy)
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
  // Declares lost every live worker silent for more than `leaseSeconds`.
  Outbox expireLeases(double now, double leaseSeconds);
  // A worker joins at `now`; `worker` must be workerCount() (drivers number joiners in
  // arrival order). Its lease starts now.
  Outbox onWorkerJoined(int worker, double now);

  bool complete() const { return ledger_.complete(); }
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
  const std::vector<double>& speedIndices() const { return speedIndices_; }
  const Strategy& strategy() const { return *strategy_; }
  uint64_t endgameCopies() const { return endgameCopies_; }  // tasks sent as duplicates

 private:
  void startStrategy(Outbox& out);
  void apply(const Decisions& decisions, Outbox& out);
  void assign(int worker, const TaskSet& pixels, Outbox& out);
  void lose(int worker, double now, const std::string& reason, Outbox& out);
  void sendToAll(const Message& m, Outbox& out);
  void finishIfComplete(Outbox& out);
  void answerQueryIfComplete(Outbox& out);
  void endgameCopy(int worker, Outbox& out);
  void introduceJoiners(Outbox& out);
  bool plausible(const Message& message) const;
  double slowestSpeedIndex() const;
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
  int speedIndicesMissing_;
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
  uint64_t endgameCopies_ = 0;
};

}  // namespace prt
