#include "balance/blocks.h"

namespace prt {

std::vector<TaskSet> BlocksStrategy::shares(uint64_t taskCount, int workerCount) const {
  return splitEvenly(TaskSet::range(0, taskCount), static_cast<uint64_t>(workerCount));
}

}  // namespace prt
