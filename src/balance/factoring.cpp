#include "balance/factoring.h"

#include <algorithm>

#include "balance/reservoir_math.h"

namespace prt {

std::vector<uint64_t> factoringChunks(uint64_t batch, const std::vector<double>& weights) {
  std::vector<uint64_t> chunks;
  chunks.reserve(weights.size());
  for (double weight : weights) {
    chunks.push_back(
        weight > 0 ? std::max<uint64_t>(1, ceilCount(static_cast<double>(batch) * weight)) : 0);
  }
  return chunks;
}

void FactoringStrategy::prepare(const StartInfo& info) {
  weights_ = divisionOfLabor(info.speedIndexSeconds);
  chunks_.clear();
  batchLeft_ = 0;
  batchSizes_.clear();
}

uint64_t FactoringStrategy::handOutSize(int worker) {
  if (batchLeft_ == 0) {
    const uint64_t batch = (remaining() + 1) / 2;
    chunks_ = factoringChunks(batch, weights_);
    batchLeft_ = batch;
    batchSizes_.push_back(batch);
  }
  const uint64_t take = std::clamp<uint64_t>(chunks_[static_cast<size_t>(worker)], 1, batchLeft_);
  batchLeft_ -= take;
  return take;
}

void FactoringStrategy::onLiveWorkersChanged() {
  weights_ = liveDivisionOfLabor();
  batchLeft_ = 0;
}

}  // namespace prt
