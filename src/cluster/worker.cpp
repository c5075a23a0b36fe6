#include "cluster/worker.h"

#include <algorithm>

#include "core/check.h"

namespace prt {

Worker::Worker(int id, WorkerOptions options) : id_(id), options_(options) {
  PRT_CHECK(options_.batchPixels >= 1);
  PRT_CHECK(options_.batchSeconds >= 0);
}

Outbox Worker::setupDone(double speedIndexSeconds, WorkerIdentity identity) {
  PRT_CHECK(needsSetup());
  setUp_ = true;
  return {Envelope{kMaster, SpeedIndexMsg{speedIndexSeconds, std::move(identity)}}};
}

TaskSet Worker::nextBatch() {
  PRT_CHECK(hasWork());
  checking_ = !checks_.empty();
  if (checking_) {
    TaskSet checks = std::move(checks_);
    checks_ = TaskSet{};
    return checks;
  }
  uint64_t size = options_.batchPixels;
  if (options_.batchSeconds > 0 && pixelsPerSecond_ > 0) {
    const double wanted = pixelsPerSecond_ * options_.batchSeconds;
    const double longer = options_.batchSeconds / WorkerOptions::kSmallScaleBatchSeconds;
    const double most =
        static_cast<double>(size) * WorkerOptions::kMaxBatchGrowth * std::max(1.0, longer);
    if (wanted > static_cast<double>(size)) size = static_cast<uint64_t>(std::min(wanted, most));
  }
  return queue_.takeFront(size);
}

Outbox Worker::batchDone(const TaskSet& batch, std::vector<float> rgb, double computeSeconds) {
  PRT_CHECK(rgb.size() == 3 * batch.size());
  return finishBatch(batch, std::move(rgb), computeSeconds);
}

Outbox Worker::finishBatch(const TaskSet& batch, std::vector<float> rgb, double computeSeconds) {
  if (checking_) {
    checking_ = false;
    return {Envelope{kMaster, CheckResultsMsg{batch, std::move(rgb)}}};
  }
  if (computeSeconds > 0 && !batch.empty()) {
    pixelsPerSecond_ = static_cast<double>(batch.size()) / computeSeconds;
  }
  Outbox out;
  if (!batch.empty()) {
    out.push_back({kMaster, ResultsMsg{batch, std::move(rgb), computeSeconds}});
  }
  requestIfIdle(out);
  return out;
}

// "Request for more" once the queue is empty, never twice for the same emptiness: a request
// answered with nothing leaves the worker waiting until new tasks (or Stop) arrive. A worker
// the strategy never gave anything does not ask: that was the strategy's decision.
void Worker::requestIfIdle(Outbox& out) {
  if (queue_.empty() && !requestOutstanding_ && !stopped_ && setUp_ && tasksReceived_ > 0) {
    requestOutstanding_ = true;
    out.push_back({kMaster, RequestMsg{}});
  }
}

bool Worker::peerTransferFits(const TaskSet& tasks) const {
  const uint64_t limit = taskLimit_ == UINT64_MAX ? UINT64_MAX / 2 : taskLimit_;
  if (tasks.size() > limit || queue_.size() > 2 * limit - tasks.size()) return false;
  for (const TaskRun& r : tasks.runs()) {
    if (r.stride == 0 && r.count > 1) return false;
  }
  return true;
}

Outbox Worker::onMessage(int from, const Message& message) {
  Outbox out;
  if (stopped_) return out;
  const auto* transfer = std::get_if<TasksMsg>(&message);
  const auto* check = std::get_if<CheckMsg>(&message);
  const bool peer = from != kMaster;
  if (peer && std::find(refusedPeers_.begin(), refusedPeers_.end(), from) != refusedPeers_.end()) {
    ++refused_;
    return out;
  }
  if (peer && transfer != nullptr && setUp_ && !peerTransferFits(transfer->tasks)) {
    refusedPeers_.push_back(from);
    ++refused_;
    return out;
  }
  const bool refused =
      (peer && (transfer == nullptr || !setUp_)) ||
      (transfer != nullptr && !transfer->tasks.allBelow(taskLimit_)) ||
      (check != nullptr && !check->tasks.allBelow(taskLimit_)) ||
      (std::holds_alternative<SceneMsg>(message) && scene_.has_value());
  if (refused) {
    ++refused_;
    return out;
  }
  if (const auto* s = std::get_if<SceneMsg>(&message)) {
    scene_ = *s;
  } else if (const auto* t = transfer) {
    ++tasksReceived_;
    queue_.append(t->tasks);
    requestOutstanding_ = false;
    // An empty transfer (the sender's queue drained meanwhile) leaves us idle: ask again.
    requestIfIdle(out);
  } else if (check != nullptr) {
    checks_.append(check->tasks);
  } else if (std::holds_alternative<QueryQueueMsg>(message)) {
    out.push_back({kMaster, QueueLengthMsg{queue_.size()}});
  } else if (const auto* order = std::get_if<TransferOrderMsg>(&message)) {
    if (order->to < 0 || order->to == id_) {
      ++refused_;
      return out;
    }
    TaskSet moved = queue_.takeBack(order->count);
    out.push_back({order->to, TasksMsg{moved}});
    out.push_back({kMaster, TransferNoticeMsg{order->to, std::move(moved)}});
    requestIfIdle(out);
  } else if (std::holds_alternative<StopMsg>(message)) {
    stopped_ = true;
  }
  return out;
}

}  // namespace prt
