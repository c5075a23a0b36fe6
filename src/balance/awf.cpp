#include "balance/awf.h"

#include <algorithm>

#include "balance/interleaved_order.h"
#include "core/check.h"

namespace prt {

std::vector<double> awfWeights(const std::vector<double>& wapSeconds, const std::vector<bool>& live) {
  PRT_CHECK(wapSeconds.size() == live.size());
  double fastest = 0;
  for (size_t i = 0; i < wapSeconds.size(); ++i) {
    if (live[i] && wapSeconds[i] > 0 && (fastest == 0 || wapSeconds[i] < fastest)) {
      fastest = wapSeconds[i];
    }
  }
  std::vector<double> inverse(wapSeconds.size(), 0.0);
  double sum = 0;
  double count = 0;
  for (size_t i = 0; i < wapSeconds.size(); ++i) {
    if (!live[i]) continue;
    const double wap = wapSeconds[i] > 0 ? wapSeconds[i] : fastest;
    inverse[i] = wap > 0 ? 1.0 / wap : 1.0;
    sum += inverse[i];
    count += 1;
  }
  for (double& w : inverse) w = sum > 0 ? count * w / sum : 0.0;
  return inverse;
}

AwfStrategy::AwfStrategy(Variant variant, uint64_t minChunk)
    : variant_(variant), minChunk_(minChunk) {
  PRT_CHECK(minChunk_ >= 1);
}

// Each chunk samples the whole image (interleaved_order.h), so a worker's measured time per
// task does not depend on which band of the image its chunks happened to fall in.
TaskSet AwfStrategy::initialPool(const StartInfo& info) {
  return interleavedOrder(info);
}

void AwfStrategy::prepare(const StartInfo& /*info*/) {
  batchLeft_ = 0;
  byWap_.clear();
  inverseWap_.clear();
}

void AwfStrategy::onWorkerChanged(int worker) {
  const double wap = workers().isLive(worker) ? throughput().weightedAverageTaskSeconds(worker) : 0;
  byWap_.set(worker, wap);
  inverseWap_.set(worker, wap > 0 ? 1.0 / wap : 0);
}

uint64_t AwfStrategy::handOutSize(int worker) {
  // awfWeights() for one worker, from the indexed sums: the unmeasured count as the fastest.
  const double fastest = byWap_.empty() ? 0 : byWap_.leastValue();
  const double standIn = fastest > 0 ? 1.0 / fastest : 1.0;
  const auto unmeasured = static_cast<double>(static_cast<size_t>(workers().liveCount()) - byWap_.count());
  const double sum = inverseWap_.total() + unmeasured * standIn;
  const double own = throughput().weightedAverageTaskSeconds(worker);
  const double inverse = own > 0 ? 1.0 / own : standIn;
  const double weight = sum > 0 ? workers().liveCount() * inverse / sum : 0.0;
  const auto p = static_cast<uint64_t>(workers().liveCount());
  const uint64_t r = remaining();
  const uint64_t half = (r + 2 * p - 1) / (2 * p);  // ceil(R / (2P))
  if (variant_ == Variant::Chunk) {
    const auto chunk = static_cast<uint64_t>(weight * static_cast<double>(half) + 0.55);
    return std::clamp<uint64_t>(chunk, minChunk_, std::max<uint64_t>(r, 1));
  }
  if (batchLeft_ == 0) {
    batch_ = p * std::max(minChunk_, half);
    batchLeft_ = std::min(batch_, r);
  }
  auto chunk = static_cast<uint64_t>(weight * static_cast<double>(batch_ / p) + 0.55);
  chunk = std::min({std::max(chunk, minChunk_), r, batchLeft_});
  batchLeft_ -= chunk;
  if (batchLeft_ > 0 && batchLeft_ <= minChunk_) {  // too small a remainder: join it
    chunk += batchLeft_;
    batchLeft_ = 0;
  }
  return chunk;
}

}  // namespace prt
