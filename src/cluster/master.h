#pragma once
// Master: the master's side of the protocol as an I/O-free state machine. A driver (threads,
// MPI, the simulator) delivers messages and lost-worker notices and sends whatever comes back;
// the master never touches a transport, a thread or the clock. It owns the strategy and
// carries out its decisions, tracks which worker holds which tasks (so a lost worker's tasks
// can be recovered), and hands each batch of results to the driver's sink.
// Not thread-safe: one driver thread calls it.

#include <cstdint>
#include <functional>
#include <memory>
#include <vector>

#include "balance/strategy.h"
#include "cluster/messages.h"

namespace prt {

// Receives each batch of results once (duplicates from a worker wrongly presumed lost are
// dropped before): `rgb` holds 3 floats per task of `tasks`, in order, or nothing when the
// results come from the simulator, which renders no colours (Worker::batchDone(batch)).
using ResultSink =
    std::function<void(int worker, const TaskSet& tasks, const std::vector<float>& rgb)>;

class Master {
 public:
  Master(std::unique_ptr<Strategy> strategy, int workerCount, uint64_t taskCount,
         SceneMsg scene, ResultSink sink);

  Outbox start();  // the scene, to every worker
  Outbox onMessage(int from, const Message& message);
  // The driver's verdict that `worker` crashed or stopped answering. Its unfinished tasks go
  // back to the strategy; anything it sends later is ignored.
  Outbox onWorkerLost(int worker);

  bool complete() const { return doneCount_ == taskCount_; }
  // Every worker is lost and tasks remain: the run cannot finish.
  bool failed() const { return liveCount_ == 0 && !complete(); }
  bool isLive(int worker) const { return live_[static_cast<size_t>(worker)]; }
  // True while `worker` holds tasks it has not returned: a driver watching for silent workers
  // only needs to watch these.
  bool holdsWork(int worker) const;
  // True while the master is waiting for `worker`: its speed index, results for tasks it
  // holds, or its queue length. A driver declares a worker lost only if it stays silent then.
  bool owesAnswer(int worker) const;

  int workerCount() const { return static_cast<int>(live_.size()); }
  uint64_t taskCount() const { return taskCount_; }
  uint64_t doneCount() const { return doneCount_; }
  const std::vector<double>& speedIndices() const { return speedIndices_; }
  const Strategy& strategy() const { return *strategy_; }

 private:
  void startStrategy(Outbox& out);
  void apply(const Decisions& decisions, Outbox& out);
  void sendToLive(const Message& m, Outbox& out);
  void finishIfComplete(Outbox& out);
  void answerQueryIfComplete(Outbox& out);

  std::unique_ptr<Strategy> strategy_;
  uint64_t taskCount_;
  SceneMsg scene_;
  ResultSink sink_;

  std::vector<bool> live_;
  int liveCount_;
  std::vector<double> speedIndices_;
  int speedIndicesMissing_;
  bool started_ = false;  // strategy started (all speed indices in)
  bool stopped_ = false;  // StopMsg sent

  std::vector<bool> done_;  // per task
  uint64_t doneCount_ = 0;
  std::vector<TaskSet> given_;   // per worker: every task it received (assignments, transfers in)
  std::vector<TaskSet> movedOut_;  // per worker: tasks it sent to peers
  std::vector<uint64_t> returned_;  // per worker: tasks it returned (for holdsWork)

  bool queryOpen_ = false;
  std::vector<bool> answered_;
  std::vector<uint64_t> queueLengths_;
};

}  // namespace prt
