#include "balance/reservoir.h"

#include "balance/reservoir_math.h"
#include "core/check.h"

namespace prt {

ReservoirStrategy::ReservoirStrategy(double initialPercent, uint64_t strata)
    : initialPercent_(initialPercent), strata_(strata) {
  validateStrategyOptions(StrategyOptions{.initialPercent = initialPercent});
  PRT_CHECK(strata_ >= 1);
}

TaskSet ReservoirStrategy::initialPool(uint64_t taskCount) const {
  TaskSet pool;
  for (uint64_t s = 0; s < strata_ && s < taskCount; ++s) {
    pool.append(TaskRun{s, (taskCount - s + strata_ - 1) / strata_, strata_});
  }
  return pool;
}

void ReservoirStrategy::prepare(const StartInfo& info) {
  division_ = divisionOfLabor(info.speedIndexSeconds);
  initialBlocks_ = initialBlockSizes(division_, initialLimit(initialPercent_, info.taskCount));
}

uint64_t ReservoirStrategy::initialSize(int worker) {
  return initialBlocks_[static_cast<size_t>(worker)];
}

uint64_t ReservoirStrategy::handOutSize(int worker) {
  return reservoirHandout(division_[static_cast<size_t>(worker)], remaining());
}

}  // namespace prt
