#pragma once
// Worker: a worker's side of the protocol as an I/O-free state machine. It keeps the task
// queue and decides what to send; the driver does the effects it asks for — loading the scene
// and measuring the speed index (needsSetup), rendering batches (nextBatch) — and sends what
// comes back. The same object runs under threads, MPI and the simulator.
// Not thread-safe: one driver thread calls it.

#include <algorithm>
#include <cstdint>
#include <optional>
#include <vector>

#include "cluster/leases.h"
#include "cluster/messages.h"

namespace prt {

struct WorkerOptions {
  static constexpr uint64_t kDefaultBatchPixels = 128;  // --batch's default
  uint64_t batchPixels = kDefaultBatchPixels;  // pixels rendered between returning results and
                                               // reading mail
  // > 0: batches grow past batchPixels to what the worker renders in this many seconds at
  // its last batch's rate, up to kMaxBatchGrowth times batchPixels. Each batch costs a
  // message and, on a thread driver, wake-ups: on a 2-core machine, 128-pixel batches of a
  // 4-sample scene cost a worker about 7 % of its time in them alone.
  double batchSeconds = 0;
  // A batch grows to at most kMaxBatchGrowth times batchPixels, and proportionally more for a
  // batchSeconds longer than kSmallScaleBatchSeconds (the default of a cluster whose master
  // is far from busy): a longer batch is asked for to send fewer messages.
  static constexpr uint64_t kMaxBatchGrowth = 64;
  static constexpr double kSmallScaleBatchSeconds = 0.03;
};

// The master's CPU time for one results message and its reply (leases.h), and the share of
// the master's time that the results of all workers may take.
inline constexpr double kMasterSecondsPerResult = 2 * kMasterSecondsPerMessage;
inline constexpr double kMasterResultsShare = 0.2;

// --batch-seconds' default for `workers` workers: kSmallScaleBatchSeconds, or longer where that
// many workers each returning a batch so often would keep one master more than
// kMasterResultsShare busy (25 us per worker: 0.1 s at 4,096 workers, 1.6 s at 65,536).
inline double defaultBatchSeconds(int workers) {
  const double scaled =
      static_cast<double>(workers) * kMasterSecondsPerResult / kMasterResultsShare;
  return std::max(scaled, WorkerOptions::kSmallScaleBatchSeconds);
}

class Worker {
 public:
  Worker(int id, WorkerOptions options);

  int id() const { return id_; }
  // Acts on the master's messages and on tasks a peer transfers (diffusion). What only the
  // master may send (scene, queries, transfer orders, Stop) from anyone else, a second scene,
  // tasks from a peer before this worker is set up, and tasks beyond limitTasks are dropped
  // and counted: a message relayed to a worker costs at most itself. A peer's transfer that
  // cannot be a queue's tail (peerTransferFits) is refused too, and that peer is refused
  // from then on.
  Outbox onMessage(int from, const Message& message);
  // The render's task count, once the scene is loaded: tasks at or beyond it are refused.
  void limitTasks(uint64_t count) { taskLimit_ = count; }
  // Messages dropped: those refused here, and bytes from peers that did not decode
  // (countRefused, from the driver that decodes them).
  void countRefused() { ++refused_; }
  uint64_t refusedMessages() const { return refused_; }

  // After the scene arrives: the driver loads it, measures the speed index, then reports.
  bool needsSetup() const { return scene_.has_value() && !setUp_; }
  const SceneMsg& scene() const { return *scene_; }
  Outbox setupDone(double speedIndexSeconds, WorkerIdentity identity = {});

  // Rendering: take the next batch off the front of the queue, render it, hand it back. Spot
  // checks the master asked for (CheckMsg) come first, as a batch of their own, and go back
  // as CheckResultsMsg: they are not this worker's tasks.
  bool hasWork() const { return setUp_ && (!queue_.empty() || !checks_.empty()) && !stopped_; }
  TaskSet nextBatch();
  bool batchIsCheck() const { return checking_; }  // the batch out is a spot check
  // computeSeconds: the measured time the batch took, for adaptive strategies (0: unmeasured).
  Outbox batchDone(const TaskSet& batch, std::vector<float> rgb, double computeSeconds = 0);
  // The simulator renders nothing: it returns the batch's results without colours (an empty
  // ResultsMsg::rgb) and counts the bytes they would take. Otherwise the same as above.
  Outbox batchDone(const TaskSet& batch, double computeSeconds = 0) {
    return finishBatch(batch, {}, computeSeconds);
  }

  bool stopped() const { return stopped_; }
  uint64_t queueLength() const { return queue_.size(); }
  uint64_t tasksReceived() const { return tasksReceived_; }  // task messages received
  // Whether a peer's transfer of `tasks` could be the tail of its queue: no more tasks than
  // the render has, no task repeated within a run (a stride of 0: no queue holds one), and
  // this worker's queue no longer than twice the render with them. Bounds what a relayed
  // message can make a worker render to itself, whatever its runs say.
  bool peerTransferFits(const TaskSet& tasks) const;

 private:
  void requestIfIdle(Outbox& out);
  Outbox finishBatch(const TaskSet& batch, std::vector<float> rgb, double computeSeconds);

  int id_;
  WorkerOptions options_;
  std::optional<SceneMsg> scene_;
  bool setUp_ = false;
  bool stopped_ = false;
  bool requestOutstanding_ = false;
  TaskSet queue_;
  TaskSet checks_;         // pixels to render for the master's spot checks
  bool checking_ = false;  // the batch out is a check
  uint64_t tasksReceived_ = 0;
  uint64_t taskLimit_ = UINT64_MAX;
  uint64_t refused_ = 0;
  std::vector<int> refusedPeers_;  // peers that sent a transfer that cannot be true
  double pixelsPerSecond_ = 0;  // the last measured batch's rate (0: none yet)
};

}  // namespace prt
