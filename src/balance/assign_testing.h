#pragma once
// For the strategies' unit tests: the Assign of `count` consecutive tasks from `first`.

#include <cstdint>

#include "balance/strategy.h"

namespace prt::testing_support {

inline Assign assignRange(int worker, uint64_t first, uint64_t count) {
  return Assign{worker, TaskSet::range(first, count)};
}

}  // namespace prt::testing_support
