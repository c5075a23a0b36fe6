#pragma once
// Adaptive weighted factoring, in the two variants of Carino and Banicescu ("Dynamic load
// balancing with adaptive factoring methods in scientific applications", J. Supercomputing
// 44, 2008) that weigh each worker by its own measured time per task, as DLS4LB computes
// them (unibas-dmi-hpc/DLS4LB, C/DLS.c, GetChunkSize cases AWF_B and AWF_C):
//
//   weight_i = P * (awap / wap_i) / sum_j (awap / wap_j)   (P live workers; awap cancels)
//   AWF-B: a batch of P * max(minChunk, ceil(R / (2P))) tasks is opened when the last one is
//          used up; each request takes round(weight_i * batch / P) of it (the weights as of
//          that request), and a batch remainder of minChunk or less joins the chunk before it.
//   AWF-C: every request takes round(weight_i * ceil(R / (2P))).
// Every chunk is at least minChunk and at most R, the tasks left. wap_i is the worker's
// weighted average time per task (throughput.h: chunk k weighs k). Start gives every worker
// minChunk tasks, its first measurement; a worker not measured yet is taken to be as fast as
// the fastest measured one (DLS4LB's DLS_StartChunk does the same). Times come from
// onResults(); no speed index is needed (and none is read).
//
// Lost workers: see PooledStrategy; P counts live workers and AWF-B's open batch is closed.

#include <cstdint>
#include <string>
#include <vector>

#include "balance/pooled_strategy.h"
#include "balance/worker_sums.h"

namespace prt {

// The AWF weights over `live` workers from their weighted average times per task (seconds;
// 0 for a worker not measured yet, which gets the smallest measured time; all 0: equal
// weights). Lost workers get 0; the live weights sum to the live count.
std::vector<double> awfWeights(const std::vector<double>& wapSeconds, const std::vector<bool>& live);

class AwfStrategy final : public PooledStrategy {
 public:
  enum class Variant { Batch, Chunk };  // AWF-B, AWF-C
  // minChunk >= 1.
  AwfStrategy(Variant variant, uint64_t minChunk);
  std::string name() const override { return variant_ == Variant::Batch ? "awf-b" : "awf-c"; }

 protected:
  TaskSet initialPool(const StartInfo& info) override;
  void prepare(const StartInfo& info) override;
  uint64_t initialSize(int /*worker*/) override { return minChunk_; }
  uint64_t handOutSize(int worker) override;
  void onLiveWorkersChanged() override { batchLeft_ = 0; }
  void onWorkerChanged(int worker) override;

 private:
  // Indexed so that no hand-out walks the workers: the live workers with a weighted average
  // time per task by that time (the fastest first), and the sum of its inverse over them.
  WorkerMinimum byWap_;
  WorkerSums inverseWap_;
  Variant variant_;
  uint64_t minChunk_;
  uint64_t batch_ = 0;      // AWF-B: the open batch's size
  uint64_t batchLeft_ = 0;  // AWF-B: its tasks not handed out yet
};

}  // namespace prt
