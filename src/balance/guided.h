#pragma once
// Guided self-scheduling (Polychronopoulos and Kuck 1987): each hand-out is ceil(R / c) of
// the R tasks still in the pool, c the number of live workers, so chunks shrink as the image
// nears completion. Start serves each worker in turn, recomputing R each time.
// Lost workers: see PooledStrategy; c counts live workers only.

#include <cstdint>
#include <string>

#include "balance/pooled_strategy.h"

namespace prt {

// ceil(remaining / workers), at least 1 while tasks remain; workers >= 1.
uint64_t guidedChunk(uint64_t remaining, uint64_t workers);

class GuidedStrategy final : public PooledStrategy {
 public:
  std::string name() const override { return "guided"; }

 protected:
  void prepare(const StartInfo& /*info*/) override {}
  uint64_t handOutSize(int worker) override;
};

}  // namespace prt
