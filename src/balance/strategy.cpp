#include "balance/strategy.h"

namespace prt {

Decisions Strategy::onQueueLengths(const std::vector<uint64_t>& /*lengths*/) {
  return {};
}

}  // namespace prt
