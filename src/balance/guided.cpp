#include "balance/guided.h"

#include <algorithm>

#include "core/check.h"

namespace prt {

uint64_t guidedChunk(uint64_t remaining, uint64_t workers) {
  PRT_CHECK(workers >= 1);
  return std::min(remaining, std::max<uint64_t>(1, (remaining + workers - 1) / workers));
}

uint64_t GuidedStrategy::handOutSize(int /*worker*/) {
  return guidedChunk(remaining(), static_cast<uint64_t>(workers().liveCount()));
}

}  // namespace prt
