#include "balance/strategy.h"

namespace prt {

Decisions Strategy::onQueueLengths(const std::vector<uint64_t>& /*lengths*/) {
  return {};
}

Decisions Strategy::onResults(int /*worker*/, const TaskSet& /*tasks*/,
                              double /*computeSeconds*/) {
  return {};
}

}  // namespace prt
