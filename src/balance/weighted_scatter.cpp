#include "balance/weighted_scatter.h"

#include "balance/interleaved_order.h"
#include "balance/reservoir_math.h"
#include "core/check.h"

namespace prt {

std::vector<TaskSet> weightedScatterShares(uint64_t taskCount,
                                           const std::vector<double>& speedIndexSeconds) {
  const std::vector<uint64_t> sizes =
      initialBlockSizes(divisionOfLabor(speedIndexSeconds), taskCount);
  TaskSet order = interleavedOrder(taskCount);
  std::vector<TaskSet> out;
  out.reserve(sizes.size());
  for (uint64_t size : sizes) out.push_back(order.takeFront(size));
  PRT_CHECK(!out.empty());
  out.back().append(order);  // what rounding down near an integer may leave: a task or two
  return out;
}

}  // namespace prt
