#include "balance/pooled_strategy.h"

#include <algorithm>

#include "balance/reservoir_math.h"
#include "core/check.h"

namespace prt {

Decisions PooledStrategy::start(const StartInfo& info) {
  validateStartInfo(info);
  const int workerCount = static_cast<int>(info.speedIndexSeconds.size());
  pool_ = TaskPool(initialPool(info));
  workers_.reset(workerCount);
  throughput_.reset(workerCount);
  idle_.clear();
  waiting_.assign(static_cast<size_t>(workerCount), false);
  waitingByRate_.clear();
  waitingRate_.assign(static_cast<size_t>(workerCount), 0.0);
  inbound_.assign(static_cast<size_t>(workerCount), false);
  victim_.assign(static_cast<size_t>(workerCount), -1);
  thievesOf_.assign(static_cast<size_t>(workerCount), {});
  taskCount_ = info.taskCount;
  returnedCount_ = 0;
  speedIndexSeconds_ = info.speedIndexSeconds;
  prepare(info);

  Decisions out;
  for (int w = 0; w < workerCount && !pool_.empty(); ++w) {
    const uint64_t count = std::min(initialSize(w), pool_.size());
    if (count > 0) out.push_back(give(w, count));
  }
  for (int w = 0; w < workerCount; ++w) onWorkerChanged(w);
  return out;
}

Decisions PooledStrategy::onRequest(int worker) {
  if (!workers_.isLive(worker)) return {NoMoreWork{worker}};
  throughput_.chunkDone(worker);
  setInbound(worker, -1);
  onWorkerChanged(worker);
  if (pool_.empty()) {
    if (std::optional<Decision> transfer = steal(worker)) return {*transfer};
    setIdle(worker, true);
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
  const bool known = worker >= 0 && worker < workers_.workerCount();
  if (known) {
    throughput_.lost(worker);
    setWaiting(worker, false);
    setIdle(worker, false);
    setInbound(worker, -1);
    onWorkerChanged(worker);
  }
  pool_.putFront(unfinished);
  if (workers_.liveCount() == 0) return {};
  // A steal from the lost worker never arrives (the master drops transfers from the lost):
  // its thief is idle again, and is served below like the others.
  if (known) {
    std::vector<int> thieves = std::move(thievesOf_[static_cast<size_t>(worker)]);
    thievesOf_[static_cast<size_t>(worker)].clear();
    for (int w : thieves) {
      const auto i = static_cast<size_t>(w);
      if (workers_.isLive(w) && inbound_[i] && victim_[i] == worker) {
        setInbound(w, -1);
        setIdle(w, true);
        onWorkerChanged(w);
      }
    }
  }
  onLiveWorkersChanged();

  Decisions out;
  while (!pool_.empty() && !idle_.empty()) {
    const int w = *idle_.begin();  // in worker order; give() takes it out of the set
    out.push_back(give(w, handOutSize(w)));
  }
  return out;
}

Decisions PooledStrategy::onWorkerJoined(int worker, double speedIndexSeconds) {
  validateJoin(worker, workers_.workerCount(), speedIndexSeconds);
  workers_.add();
  throughput_.add();
  waiting_.push_back(false);
  waitingRate_.push_back(0.0);
  inbound_.push_back(false);
  victim_.push_back(-1);
  thievesOf_.emplace_back();
  speedIndexSeconds_.push_back(speedIndexSeconds);
  onWorkerChanged(worker);
  onLiveWorkersChanged();
  return {};
}

Decisions PooledStrategy::onResults(int worker, const TaskSet& tasks, double computeSeconds) {
  if (!workers_.isLive(worker)) return {};
  throughput_.returned(worker, tasks.size(), computeSeconds);
  returnedCount_ += tasks.size();
  setInbound(worker, -1);
  if (waiting_[static_cast<size_t>(worker)]) {  // its place among the waiting follows its rate
    setWaiting(worker, false);
    setWaiting(worker, true);
  }
  onWorkerChanged(worker);
  Decisions out;
  if (waitingByRate_.empty()) return out;
  if (returnedCount_ >= taskCount_) {  // all back: nothing will ever be worth stealing
    std::vector<int> waiting;
    for (const auto& [rate, w] : waitingByRate_) waiting.push_back(w);
    std::sort(waiting.begin(), waiting.end());
    for (int w : waiting) {
      setWaiting(w, false);
      out.push_back(NoMoreWork{w});
    }
    return out;
  }
  // The fastest waiting worker first; once one finds nothing worth taking, the slower ones
  // would not either (a steal's size grows with the thief's rate), so stop there.
  while (!waitingByRate_.empty()) {
    std::optional<Decision> transfer = steal(waitingByRate_.begin()->second);
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
  setIdle(worker, false);
  setWaiting(worker, false);
  setInbound(worker, transfer->from);
  onWorkerChanged(transfer->from);
  onWorkerChanged(worker);
  return Decision{*transfer};
}

void PooledStrategy::setWaiting(int worker, bool waiting) {
  const auto w = static_cast<size_t>(worker);
  if (waiting_[w] == waiting) return;
  waiting_[w] = waiting;
  if (waiting) {
    waitingRate_[w] = throughput_.rate(worker);
    waitingByRate_.emplace(-waitingRate_[w], worker);
  } else {
    waitingByRate_.erase({-waitingRate_[w], worker});
  }
}

void PooledStrategy::setIdle(int worker, bool idle) {
  if (idle) {
    idle_.insert(worker);
  } else {
    idle_.erase(worker);
  }
}

void PooledStrategy::setInbound(int worker, int victim) {
  const auto w = static_cast<size_t>(worker);
  inbound_[w] = victim >= 0;
  victim_[w] = victim;
  if (victim >= 0) thievesOf_[static_cast<size_t>(victim)].push_back(worker);
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
  setIdle(worker, false);
  setWaiting(worker, false);
  throughput_.given(worker, count);
  Decision out = Assign{worker, pool_.takeFront(count)};
  onWorkerChanged(worker);
  return out;
}

}  // namespace prt
