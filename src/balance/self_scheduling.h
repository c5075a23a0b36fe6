#pragma once
// Self-scheduling with a fixed chunk: start gives each worker one chunk in worker order, and
// every request takes the next chunk from the front (the last one may be shorter).
// Lost workers: see PooledStrategy.

#include <cstdint>
#include <string>

#include "balance/pooled_strategy.h"

namespace prt {

class SelfSchedulingStrategy final : public PooledStrategy {
 public:
  // chunk >= 1 tasks per hand-out; 0 throws InputError.
  explicit SelfSchedulingStrategy(uint64_t chunk = 64);
  std::string name() const override { return "self"; }

 protected:
  void prepare(const StartInfo& /*info*/) override {}
  uint64_t handOutSize(int /*worker*/) override { return chunk_; }

 private:
  uint64_t chunk_;
};

}  // namespace prt
