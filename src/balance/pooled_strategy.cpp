#include "balance/pooled_strategy.h"

#include <algorithm>

#include "balance/reservoir_math.h"
#include "core/check.h"

namespace prt {

Decisions PooledStrategy::start(const StartInfo& info) {
  validateStartInfo(info);
  const int workerCount = static_cast<int>(info.speedIndexSeconds.size());
  pool_ = initialPool(info);
  workers_.reset(workerCount);
  throughput_.reset(workerCount);
  idle_.assign(static_cast<size_t>(workerCount), false);
  waiting_.assign(static_cast<size_t>(workerCount), false);
  waitingCount_ = 0;
  inbound_.assign(static_cast<size_t>(workerCount), false);
  victim_.assign(static_cast<size_t>(workerCount), -1);
  taskCount_ = info.taskCount;
  returnedCount_ = 0;
  speedIndexSeconds_ = info.speedIndexSeconds;
  prepare(info);

  Decisions out;
  for (int w = 0; w < workerCount && !pool_.empty(); ++w) {
    const uint64_t count = std::min(initialSize(w), pool_.size());
    if (count > 0) out.push_back(give(w, count));
  }
  return out;
}

Decisions PooledStrategy::onRequest(int worker) {
  if (!workers_.isLive(worker)) return {NoMoreWork{worker}};
  throughput_.chunkDone(worker);
  inbound_[static_cast<size_t>(worker)] = false;
  if (pool_.empty()) {
    if (std::optional<Decision> transfer = steal(worker)) return {*transfer};
    idle_[static_cast<size_t>(worker)] = true;
    if (waitsForSteals() && returnedCount_ < taskCount_) {
      setWaiting(worker, true);
      return {};
    }
    return {NoMoreWork{worker}};
  }
  return {give(worker, handOutSize(worker))};
}

Decisions PooledStrategy::onWorkerLost(int worker, const TaskSet& unfinished) {
  workers_.markLost(worker);
  if (worker >= 0 && worker < workers_.workerCount()) {
    throughput_.lost(worker);
    setWaiting(worker, false);
  }
  TaskSet pool = unfinished;
  pool.append(pool_);
  pool_ = std::move(pool);
  if (workers_.liveCount() == 0) return {};
  // A steal from the lost worker never arrives (the master drops transfers from the lost):
  // its thief is idle again, and is served below like the others.
  for (int w : workers_.liveList()) {
    const auto i = static_cast<size_t>(w);
    if (inbound_[i] && victim_[i] == worker) {
      inbound_[i] = false;
      idle_[i] = true;
    }
  }
  onLiveWorkersChanged();

  Decisions out;
  for (int w : workers_.liveList()) {
    if (pool_.empty()) break;
    if (idle_[static_cast<size_t>(w)]) out.push_back(give(w, handOutSize(w)));
  }
  return out;
}

Decisions PooledStrategy::onWorkerJoined(int worker, double speedIndexSeconds) {
  validateJoin(worker, workers_.workerCount(), speedIndexSeconds);
  workers_.add();
  throughput_.add();
  idle_.push_back(false);
  waiting_.push_back(false);
  inbound_.push_back(false);
  victim_.push_back(-1);
  speedIndexSeconds_.push_back(speedIndexSeconds);
  onLiveWorkersChanged();
  return {};
}

Decisions PooledStrategy::onResults(int worker, const TaskSet& tasks, double computeSeconds) {
  if (!workers_.isLive(worker)) return {};
  throughput_.returned(worker, tasks.size(), computeSeconds);
  returnedCount_ += tasks.size();
  inbound_[static_cast<size_t>(worker)] = false;
  Decisions out;
  if (waitingCount_ == 0) return out;
  if (returnedCount_ >= taskCount_) {  // all back: nothing will ever be worth stealing
    for (int w : workers_.liveList()) {
      if (waiting_[static_cast<size_t>(w)]) out.push_back(NoMoreWork{w});
    }
    waiting_.assign(waiting_.size(), false);
    waitingCount_ = 0;
    return out;
  }
  // The fastest waiting worker first; once one finds nothing worth taking, the slower ones
  // would not either (a steal's size grows with the thief's rate), so stop there.
  std::vector<int> thieves;
  for (int w : workers_.liveList()) {
    if (waiting_[static_cast<size_t>(w)]) thieves.push_back(w);
  }
  std::stable_sort(thieves.begin(), thieves.end(), [&](int a, int b) {
    return throughput_.rate(a) > throughput_.rate(b);
  });
  for (int w : thieves) {
    std::optional<Decision> transfer = steal(w);
    if (!transfer) break;
    out.push_back(*transfer);
  }
  return out;
}

std::optional<Decision> PooledStrategy::steal(int worker) {
  std::optional<Transfer> transfer = stealFor(worker);
  if (!transfer) return std::nullopt;
  PRT_CHECK(transfer->to == worker && transfer->from != worker &&
            workers_.isLive(transfer->from) && transfer->count >= 1);
  throughput_.moved(transfer->from, worker, transfer->count);
  idle_[static_cast<size_t>(worker)] = false;
  setWaiting(worker, false);
  inbound_[static_cast<size_t>(worker)] = true;
  victim_[static_cast<size_t>(worker)] = transfer->from;
  return Decision{*transfer};
}

void PooledStrategy::setWaiting(int worker, bool waiting) {
  const auto w = static_cast<size_t>(worker);
  if (waiting_[w] != waiting) waitingCount_ += waiting ? 1 : -1;
  waiting_[w] = waiting;
}

std::vector<double> PooledStrategy::liveDivisionOfLabor() const {
  const std::vector<int> live = workers_.liveList();
  std::vector<double> speeds;
  speeds.reserve(live.size());
  for (int w : live) speeds.push_back(speedIndexSeconds_[static_cast<size_t>(w)]);
  std::vector<double> division(speedIndexSeconds_.size(), 0.0);
  if (live.empty()) return division;
  const std::vector<double> liveDivision = divisionOfLabor(speeds);
  for (size_t i = 0; i < live.size(); ++i) {
    division[static_cast<size_t>(live[i])] = liveDivision[i];
  }
  return division;
}

Decision PooledStrategy::give(int worker, uint64_t count) {
  PRT_CHECK(workers_.isLive(worker) && !pool_.empty());
  count = std::clamp<uint64_t>(count, 1, pool_.size());
  idle_[static_cast<size_t>(worker)] = false;
  setWaiting(worker, false);
  throughput_.given(worker, count);
  return Assign{worker, pool_.takeFront(count)};
}

}  // namespace prt
