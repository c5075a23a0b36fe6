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
  if (pool_.empty()) {
    if (std::optional<Transfer> steal = stealFor(worker)) {
      PRT_CHECK(steal->to == worker && steal->from != worker && workers_.isLive(steal->from) &&
                steal->count >= 1);
      throughput_.moved(steal->from, worker, steal->count);
      idle_[static_cast<size_t>(worker)] = false;
      return {*steal};
    }
    idle_[static_cast<size_t>(worker)] = true;
    return {NoMoreWork{worker}};
  }
  return {give(worker, handOutSize(worker))};
}

Decisions PooledStrategy::onWorkerLost(int worker, const TaskSet& unfinished) {
  workers_.markLost(worker);
  if (worker >= 0 && worker < workers_.workerCount()) throughput_.lost(worker);
  TaskSet pool = unfinished;
  pool.append(pool_);
  pool_ = std::move(pool);
  if (workers_.liveCount() == 0) return {};
  onLiveWorkersChanged();

  Decisions out;
  for (int w : workers_.liveList()) {
    if (pool_.empty()) break;
    if (idle_[static_cast<size_t>(w)]) out.push_back(give(w, handOutSize(w)));
  }
  return out;
}

void PooledStrategy::onResults(int worker, const TaskSet& tasks, double computeSeconds) {
  if (workers_.isLive(worker)) throughput_.returned(worker, tasks.size(), computeSeconds);
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
  throughput_.given(worker, count);
  return Assign{worker, pool_.takeFront(count)};
}

}  // namespace prt
