#include "balance/static_strategy.h"

#include "core/check.h"

namespace prt {

Decisions StaticStrategy::start(const StartInfo& info) {
  validateStartInfo(info);
  const int workerCount = static_cast<int>(info.speedIndexSeconds.size());
  workers_.reset(workerCount);
  std::vector<TaskSet> split = shares(info);
  PRT_CHECK(split.size() == static_cast<size_t>(workerCount));
  Decisions out;
  for (int w = 0; w < workerCount; ++w) {
    TaskSet& share = split[static_cast<size_t>(w)];
    if (!share.empty()) out.push_back(Assign{w, std::move(share)});
  }
  return out;
}

Decisions StaticStrategy::onRequest(int worker) {
  return {NoMoreWork{worker}};
}

Decisions StaticStrategy::onWorkerLost(int worker, const TaskSet& unfinished) {
  workers_.markLost(worker);
  return spreadOverLiveWorkers(unfinished, workers_);
}

Decisions StaticStrategy::onWorkerJoined(int worker, double speedIndexSeconds) {
  validateJoin(worker, workers_.workerCount(), speedIndexSeconds);
  workers_.add();
  return {};
}

}  // namespace prt
