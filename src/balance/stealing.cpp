#include "balance/stealing.h"

#include "balance/interleaved_order.h"
#include "core/check.h"

namespace prt {

StealingStrategy::StealingStrategy(uint64_t minChunk) : minChunk_(minChunk) {
  PRT_CHECK(minChunk_ >= 1);
}

TaskSet StealingStrategy::initialPool(const StartInfo& info) {
  return interleavedOrder(info);
}

void StealingStrategy::prepare(const StartInfo& info) {
  victims_.clear();
  indexed_.clear();
  taskCount_ = info.taskCount;
  workerCount_ = info.speedIndexSeconds.size();
}

uint64_t StealingStrategy::initialSize(int worker) {
  const auto w = static_cast<uint64_t>(worker);
  return taskCount_ / workerCount_ + (w < taskCount_ % workerCount_ ? 1 : 0);
}

uint64_t StealingStrategy::handOutSize(int /*worker*/) {
  const auto p = static_cast<uint64_t>(workers().liveCount());
  return (remaining() + p - 1) / p;
}

void StealingStrategy::onWorkerChanged(int worker) {
  const auto w = static_cast<size_t>(worker);
  if (w >= indexed_.size()) indexed_.resize(w + 1, 0);
  victims_.erase({indexed_[w], -worker});
  indexed_[w] = throughput().held(worker);
  if (workers().isLive(worker) && !awaitingSteal(worker)) victims_.emplace(indexed_[w], -worker);
}

std::optional<Transfer> StealingStrategy::stealFor(int worker) {
  // The fullest queue (ties: the lowest-numbered worker), not the thief's own.
  int victim = -1;
  for (const auto& [held, negated] : victims_) {
    if (-negated != worker) {
      victim = -negated;
      break;
    }
  }
  if (victim < 0) return std::nullopt;
  const uint64_t half = throughput().held(victim) / 2;
  if (half < minChunk_) return std::nullopt;
  return Transfer{victim, worker, half};
}

}  // namespace prt
