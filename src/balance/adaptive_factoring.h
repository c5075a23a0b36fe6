#pragma once
// Adaptive factoring (Banicescu and Liu, "Analyzing the impact of the AF technique on
// scientific applications", HPC Symposium 2000): the chunk for worker i, from every worker's
// measured mean mu_j and variance sigma_j^2 of the time per task and the R tasks left, is
//
//   D = sum_j sigma_j^2 / mu_j,   T = 1 / sum_j (1 / mu_j),
//   chunk_i = (D + 2 T R - sqrt(D^2 + 4 D T R)) / (2 mu_i),
//
// rounded to nearest, at most ceil(N / (2P)) and at least minChunk, as DLS4LB bounds it
// (unibas-dmi-hpc/DLS4LB, C/DLS.c, GetChunkSize case AF; DLS4LB passes sigma where the paper
// has sigma^2, which leaves D without the unit of a time: we follow the paper). The larger
// the spread of task times, the smaller the chunks, so the last ones cannot run long. mu and
// sigma^2 come from the results' measured times (throughput.h); a worker not measured yet is
// taken to be like the fastest measured one, as DLS4LB does. Start gives every worker
// minChunk tasks. No speed index is needed.
//
// Lost workers: see PooledStrategy; P and the sums count live workers only.

#include <cstdint>
#include <string>
#include <vector>

#include "balance/pooled_strategy.h"
#include "balance/worker_sums.h"

namespace prt {

// The formula above, before rounding and bounds; mu and variance per live worker (mu > 0).
double adaptiveFactoringChunk(const std::vector<double>& mu, const std::vector<double>& variance,
                              size_t worker, double remaining);
// The same from the sums it needs: d = sum_j sigma_j^2 / mu_j, inverseSum = sum_j 1 / mu_j.
double adaptiveFactoringChunk(double d, double inverseSum, double muWorker, double remaining);

class AdaptiveFactoringStrategy final : public PooledStrategy {
 public:
  explicit AdaptiveFactoringStrategy(uint64_t minChunk);
  std::string name() const override { return "af"; }

 protected:
  TaskSet initialPool(const StartInfo& info) override;
  void prepare(const StartInfo& info) override;
  uint64_t initialSize(int /*worker*/) override { return minChunk_; }
  uint64_t handOutSize(int worker) override;
  void onWorkerChanged(int worker) override;

 private:
  // Indexed so that no hand-out walks the workers: the live measured workers by mean time per
  // task (the fastest first), and the sums of sigma^2 / mu and 1 / mu over them.
  WorkerMinimum byMu_;
  WorkerSums varianceOverMu_, inverseMu_;
  uint64_t minChunk_;
  uint64_t taskCount_ = 0;
};

}  // namespace prt
