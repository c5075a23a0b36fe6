#pragma once
// Reservoir (Madamba and Serina 2017, Section II-A). From the speed indices, the division of
// labour div_s (reservoir_math.h). At the start, limit = ceil(p * n) tasks go out in
// contiguous blocks of ceil(limit * div_s) tasks, worker 0 first; the rest stays in the
// reservoir. A request from worker s takes ceil(div_s * remaining) tasks (at least one) off
// the front of the reservoir; an empty reservoir answers NoMoreWork. No task ever moves
// between workers.
//
// Interleaved (strategy "reservoir-scatter"), the same procedures run over an interleaved task
// sequence (interleaved_order.h) instead of scan-line order. Each contiguous stretch of it —
// an initial block, a hand-out — then samples the whole image, as scatter decomposition
// does, instead of a band of scan lines whose cost may be far from the average (an open sky
// costs a fraction of a cluster of glass). Scan-line order is the paper's.
//
// Lost workers (the paper has none): their tasks go back to the front of the reservoir and
// the division of labour is recomputed over the live workers (see PooledStrategy).

#include <cstdint>
#include <string>
#include <vector>

#include "balance/pooled_strategy.h"

namespace prt {

class ReservoirStrategy final : public PooledStrategy {
 public:
  // initialPercent in (0, 100]; anything else throws InputError.
  explicit ReservoirStrategy(double initialPercent = 80, bool interleaved = false);
  std::string name() const override {
    return interleaved_ ? "reservoir-scatter" : "reservoir";
  }

  // The division of labour in use (after start()); 0 for lost workers.
  const std::vector<double>& division() const { return division_; }

 protected:
  TaskSet initialPool(const StartInfo& info) override;
  void prepare(const StartInfo& info) override;
  uint64_t initialSize(int worker) override;
  uint64_t handOutSize(int worker) override;
  void onLiveWorkersChanged() override { division_ = liveDivisionOfLabor(); }

 private:
  double initialPercent_;
  bool interleaved_;
  std::vector<double> division_;
  std::vector<uint64_t> initialBlocks_;
};

}  // namespace prt
