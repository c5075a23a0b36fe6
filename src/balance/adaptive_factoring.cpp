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
  return adaptiveFactoringChunk(d, inverseSum, mu[worker], remaining);
}

double adaptiveFactoringChunk(double d, double inverseSum, double muWorker, double remaining) {
  const double t = 1.0 / inverseSum;
  return (d + 2 * t * remaining - std::sqrt(d * d + 4 * d * t * remaining)) / (2 * muWorker);
}

void AdaptiveFactoringStrategy::prepare(const StartInfo& info) {
  taskCount_ = info.taskCount;
  byMu_.clear();
  varianceOverMu_.clear();
  inverseMu_.clear();
}

void AdaptiveFactoringStrategy::onWorkerChanged(int worker) {
  const double mu = workers().isLive(worker) ? throughput().meanTaskSeconds(worker) : 0;
  byMu_.set(worker, mu);
  varianceOverMu_.set(worker, mu > 0 ? throughput().taskSecondsVariance(worker) / mu : 0);
  inverseMu_.set(worker, mu > 0 ? 1.0 / mu : 0);
}

AdaptiveFactoringStrategy::AdaptiveFactoringStrategy(uint64_t minChunk) : minChunk_(minChunk) {
  PRT_CHECK(minChunk_ >= 1);
}

TaskSet AdaptiveFactoringStrategy::initialPool(const StartInfo& info) {
  return interleavedOrder(info);
}

uint64_t AdaptiveFactoringStrategy::handOutSize(int worker) {
  // The fastest measured worker stands in for those not measured yet.
  if (byMu_.empty()) return minChunk_;  // nothing measured (results without times)
  const int fastest = byMu_.least();
  const double fastestMu = throughput().meanTaskSeconds(fastest);
  const double fastestVariance = throughput().taskSecondsVariance(fastest);
  const auto unmeasured = static_cast<double>(static_cast<size_t>(workers().liveCount()) - byMu_.count());
  const double d = varianceOverMu_.total() + unmeasured * (fastestVariance / fastestMu);
  const double inverseSum = inverseMu_.total() + unmeasured * (1.0 / fastestMu);
  const double own = throughput().meanTaskSeconds(worker);
  const double muWorker = own > 0 ? own : fastestMu;
  const double chunk =
      adaptiveFactoringChunk(d, inverseSum, muWorker, static_cast<double>(remaining())) + 0.5;
  const auto p = static_cast<uint64_t>(workers().liveCount());
  const uint64_t maxChunk = std::max<uint64_t>(1, (taskCount_ + 2 * p - 1) / (2 * p));
  const auto rounded = chunk >= static_cast<double>(maxChunk) ? maxChunk
                                                               : static_cast<uint64_t>(chunk);
  return std::clamp(rounded, minChunk_, std::max(minChunk_, maxChunk));
}

}  // namespace prt
