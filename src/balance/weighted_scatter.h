#pragma once
// Speed-weighted scatter ("scatter-weighted"): the paper's recommendation, its speed-index
// bias applied to scatter decomposition. Worker w gets a share of ceil(n * div_w) tasks (the
// reservoir's division of labour, reservoir_math.h, the last shares clamped so the total is
// n, any task left by rounding going to the last), cut as consecutive stretches of the interleaved order (interleaved_order.h): each
// share samples the whole image, as a scatter share does, but its size follows the worker's
// speed index. Static: nothing moves afterwards. Lost workers: see StaticStrategy.

#include <string>
#include <vector>

#include "balance/static_strategy.h"

namespace prt {

// The shares above, one per speed index.
std::vector<TaskSet> weightedScatterShares(uint64_t taskCount,
                                           const std::vector<double>& speedIndexSeconds);

class WeightedScatterStrategy final : public StaticStrategy {
 public:
  std::string name() const override { return "scatter-weighted"; }

 protected:
  std::vector<TaskSet> shares(const StartInfo& info) const override {
    return weightedScatterShares(info.taskCount, info.speedIndexSeconds);
  }
};

}  // namespace prt
