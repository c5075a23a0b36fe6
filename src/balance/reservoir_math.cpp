#include "balance/reservoir_math.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "core/check.h"

namespace prt {

uint64_t ceilCount(double x) {
  if (!(x > 0)) return 0;
  constexpr double kMax = 18446744073709549568.0;  // largest double below 2^64
  if (x >= kMax) return std::numeric_limits<uint64_t>::max();
  const double nearest = std::nearbyint(x);
  const double rounded =
      std::fabs(x - nearest) <= 1e-12 * std::max(1.0, x) ? nearest : std::ceil(x);
  return static_cast<uint64_t>(rounded);
}

std::vector<double> divisionOfLabor(const std::vector<double>& speedIndexSeconds) {
  PRT_CHECK(!speedIndexSeconds.empty());
  double slowest = speedIndexSeconds[0];
  for (double s : speedIndexSeconds) {
    PRT_CHECK(s > 0);
    slowest = std::max(slowest, s);
  }
  std::vector<double> ratio;
  double ratioTotal = 0;
  for (double s : speedIndexSeconds) {
    ratio.push_back(slowest / s);
    ratioTotal += ratio.back();
  }
  for (double& r : ratio) r /= ratioTotal;
  return ratio;
}

uint64_t initialLimit(double initialPercent, uint64_t taskCount) {
  const double limit = initialPercent * static_cast<double>(taskCount) / 100.0;
  return std::min(taskCount, ceilCount(limit));
}

std::vector<uint64_t> initialBlockSizes(const std::vector<double>& division, uint64_t limit) {
  std::vector<uint64_t> blocks;
  uint64_t given = 0;
  for (double div : division) {
    const uint64_t block = std::min(limit - given, ceilCount(static_cast<double>(limit) * div));
    blocks.push_back(block);
    given += block;
  }
  return blocks;
}

uint64_t reservoirHandout(double div, uint64_t remaining) {
  if (remaining == 0) return 0;
  const uint64_t want = std::max<uint64_t>(1, ceilCount(div * static_cast<double>(remaining)));
  return std::min(remaining, want);
}

}  // namespace prt
