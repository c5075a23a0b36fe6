#pragma once
// Scatter decomposition: task i goes to worker i mod c, so every worker gets an even sample
// of the whole image (a strided TaskSet each). Static: nothing moves afterwards. Lost
// workers: see StaticStrategy.

#include <cstdint>
#include <string>
#include <vector>

#include "balance/static_strategy.h"

namespace prt {

// Worker w's share: w, w + c, w + 2c, ... below taskCount.
std::vector<TaskSet> scatterShares(uint64_t taskCount, int workerCount);

class ScatterStrategy final : public StaticStrategy {
 public:
  std::string name() const override { return "scatter"; }

 protected:
  std::vector<TaskSet> shares(const StartInfo& info) const override {
    return scatterShares(info.taskCount, static_cast<int>(info.speedIndexSeconds.size()));
  }
};

}  // namespace prt
