#include "balance/reservoir.h"

#include "balance/interleaved_order.h"
#include "balance/reservoir_math.h"

namespace prt {

ReservoirStrategy::ReservoirStrategy(double initialPercent, bool interleaved)
    : initialPercent_(initialPercent), interleaved_(interleaved) {
  validateStrategyOptions(StrategyOptions{.initialPercent = initialPercent});
}

TaskSet ReservoirStrategy::initialPool(const StartInfo& info) {
  return interleaved_ ? interleavedOrder(info) : TaskSet::range(0, info.taskCount);
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
