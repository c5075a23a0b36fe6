#pragma once
// Weighted factoring (Hummel, Schonberg and Flynn 1992; weighted by Hummel et al. 1996, as
// Banicescu's work uses it): tasks go out in batches, each batch ceil(R / 2) of the R tasks
// left, split into one chunk per live worker proportional to its weight. The weights are the
// reservoir's division of labour (weight proportional to 1 / speed index). A request takes the
// requester's chunk of the current batch (the batch's last chunk may be shorter); once the
// batch is used up, the next request computes a new one. Start hands each worker its chunk of
// the first batch.
//
// Lost workers: see PooledStrategy; the weights are recomputed over the live workers and the
// current batch is closed, so the next hand-out starts a new batch that includes the
// recovered tasks.

#include <cstdint>
#include <string>
#include <vector>

#include "balance/pooled_strategy.h"

namespace prt {

// The chunks of one batch: max(1, ceil(batch * weight_w)) for weight_w > 0, else 0.
std::vector<uint64_t> factoringChunks(uint64_t batch, const std::vector<double>& weights);

class FactoringStrategy final : public PooledStrategy {
 public:
  std::string name() const override { return "factoring"; }

  // Sizes of the batches opened so far, in order (for tests and logs).
  const std::vector<uint64_t>& batchSizes() const { return batchSizes_; }

 protected:
  void prepare(const StartInfo& info) override;
  uint64_t handOutSize(int worker) override;
  void onLiveWorkersChanged() override;

 private:
  std::vector<double> weights_;
  std::vector<uint64_t> chunks_;  // of the current batch, per worker
  uint64_t batchLeft_ = 0;        // tasks of the current batch not handed out yet
  std::vector<uint64_t> batchSizes_;
};

}  // namespace prt
