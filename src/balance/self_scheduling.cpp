#include "balance/self_scheduling.h"

namespace prt {

SelfSchedulingStrategy::SelfSchedulingStrategy(uint64_t chunk) : chunk_(chunk) {
  validateStrategyOptions(StrategyOptions{.chunk = chunk});
}

}  // namespace prt
