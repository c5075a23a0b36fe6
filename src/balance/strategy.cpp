#include "balance/strategy.h"

namespace prt {

Decisions Strategy::onQueueLengths(const std::vector<uint64_t>& /*lengths*/) {
  return {};
}

void Strategy::onResults(int /*worker*/, const TaskSet& /*tasks*/, double /*computeSeconds*/) {}

}  // namespace prt
