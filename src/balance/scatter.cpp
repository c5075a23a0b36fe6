#include "balance/scatter.h"

#include "core/check.h"

namespace prt {

std::vector<TaskSet> scatterShares(uint64_t taskCount, int workerCount) {
  PRT_CHECK(workerCount >= 1);
  const auto c = static_cast<uint64_t>(workerCount);
  std::vector<TaskSet> out;
  for (uint64_t w = 0; w < c; ++w) {
    const uint64_t count = taskCount / c + (w < taskCount % c ? 1 : 0);
    out.push_back(TaskSet::strided(w, count, c));
  }
  return out;
}

}  // namespace prt
