#include "balance/blocks.h"

namespace prt {

std::vector<TaskSet> BlocksStrategy::shares(const StartInfo& info) const {
  return splitEvenly(TaskSet::range(0, info.taskCount), info.speedIndexSeconds.size());
}

}  // namespace prt
