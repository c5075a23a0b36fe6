#include "balance/adaptive_factoring.h"

#include <algorithm>
#include <cmath>

#include "balance/interleaved_order.h"
#include "core/check.h"

namespace prt {

double adaptiveFactoringChunk(const std::vector<double>& mu, const std::vector<double>& variance,
                              size_t worker, double remaining) {
  PRT_CHECK(mu.size() == variance.size() && worker < mu.size());
  double d = 0;
  double inverseSum = 0;
  for (size_t j = 0; j < mu.size(); ++j) {
    PRT_CHECK(mu[j] > 0);
    d += variance[j] / mu[j];
    inverseSum += 1.0 / mu[j];
  }
  const double t = 1.0 / inverseSum;
  return (d + 2 * t * remaining - std::sqrt(d * d + 4 * d * t * remaining)) / (2 * mu[worker]);
}

AdaptiveFactoringStrategy::AdaptiveFactoringStrategy(uint64_t minChunk) : minChunk_(minChunk) {
  PRT_CHECK(minChunk_ >= 1);
}

TaskSet AdaptiveFactoringStrategy::initialPool(const StartInfo& info) {
  return interleavedOrder(info.taskCount, info.frameTasks);
}

uint64_t AdaptiveFactoringStrategy::handOutSize(int worker) {
  // The fastest measured worker stands in for those not measured yet.
  const std::vector<int> live = workers().liveList();
  int fastest = -1;
  for (int w : live) {
    const double mu = throughput().meanTaskSeconds(w);
    if (mu > 0 && (fastest < 0 || mu < throughput().meanTaskSeconds(fastest))) fastest = w;
  }
  if (fastest < 0) return minChunk_;  // nothing measured (results without times)
  std::vector<double> mu;
  std::vector<double> variance;
  size_t index = 0;
  for (int w : live) {
    const int from = throughput().meanTaskSeconds(w) > 0 ? w : fastest;
    if (w == worker) index = mu.size();
    mu.push_back(throughput().meanTaskSeconds(from));
    variance.push_back(throughput().taskSecondsVariance(from));
  }
  const double chunk =
      adaptiveFactoringChunk(mu, variance, index, static_cast<double>(remaining())) + 0.5;
  const auto p = static_cast<uint64_t>(live.size());
  const uint64_t maxChunk = std::max<uint64_t>(1, (taskCount_ + 2 * p - 1) / (2 * p));
  const auto rounded = chunk >= static_cast<double>(maxChunk) ? maxChunk
                                                               : static_cast<uint64_t>(chunk);
  return std::clamp(rounded, minChunk_, std::max(minChunk_, maxChunk));
}

}  // namespace prt
