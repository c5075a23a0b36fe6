#pragma once
// The adaptive reservoir ("adaptive"): the reservoir's idea — hand out part of the image at
// once and keep a reserve for the end — with each worker's speed learnt as it works instead
// of measured before the start.
//
//  - Start: firstPercent of the image goes out at once, split by the speed index's division
//    of labour when one was run (the indices differ), else evenly. No speed-index wait is
//    needed: run with --speed-index none and it starts with the scene.
//  - Learning: each worker's rate is its tasks per second over its recent results
//    (throughput.h); a worker not measured yet (at the start, or just joined) is assumed to
//    run as the slowest measured one does per unit of speed index: the least of their
//    rate x speed index, over its own index (the slowest measured rate when the indices are
//    equal). Pessimism is the cheap error: a newcomer assumed too slow asks again soon, one
//    assumed too fast (the mean, as this once was) takes a share it finishes long after the
//    others near the end — a slow machine that rejoined in the last minutes of an hour's job
//    on 1,024 workers held it up by 100 s in the simulator (prt experiment faults).
//    The pool is in interleaved order (interleaved_order.h), so every hand-out samples the
//    whole image and rates measured on one hand-out hold for the next. A rate counts once the
//    worker has returned a stratum's worth of tasks (kMeasuredTasks): a newcomer's first few
//    pixels may all be sky or all glass, hundreds of times apart in cost.
//  - Sizing, so that all finish together: a request from worker w finds the common finishing
//    time T at which the pool and every queue would be done, each worker i at rate r_i,
//    holding h_i: sum over i of max(0, r_i T - h_i) = R (a worker whose queue already lasts
//    past T gets nothing more). Worker w gets (1 - reservePercent/100) of its part, r_w T,
//    at least minChunk: the rest stays in the reserve, so hand-outs shrink as the end nears
//    (with reservePercent 50 each lasts half the expected remaining time, factoring's rule in
//    time rather than tasks, weighted by measured speed).
//  - The end: once the reserve is empty, a requester steals from the worker expected to
//    finish last (h_v / r_v largest), taking h_v r_w / (r_v + r_w) tasks so that both finish
//    together, but no more than its own part r_w H / sum_i r_i of the H tasks all hold,
//    since the other idle workers will take theirs — at least
//    minChunk; a worker with tasks stolen for it on their way is no
//    victim. A requester with nothing worth stealing waits, and every later result looks
//    again (PooledStrategy::waitsForSteals), so the fast workers stay available to the end.
//    A worker that slows down after its last hand-out is thus relieved by the others
//    instead of finishing alone.
//
// Lost and joining workers: see PooledStrategy. A newcomer's first request is sized from its
// speed index as above, or steals once the reserve is empty.
//
// Cost: no decision walks the workers. The live workers with a rate are kept in two
// FinishOrders (finish_order.h): the measured ones by their finishing time h_i / r_i (summing
// r_i, h_i and r_i x index_i), the unmeasured ones by h_i x index_i, their finishing time
// times the common factor K of their assumed rate K / index_i (summing 1 / index_i and h_i).
// T is found by descending one order while asking the other for its sums below the same
// time: O(log^2 W) per hand-out; the victim is the last eligible entry of either order,
// O(log W). The answers are those of commonFinishSeconds() up to the rounding of sums taken
// in another order.

#include <cstdint>
#include <optional>
#include <set>
#include <string>
#include <vector>

#include "balance/finish_order.h"
#include "balance/interleaved_order.h"
#include "balance/pooled_strategy.h"

namespace prt {

// The common finishing time T (seconds from now) with sum_i max(0, rates_i T - held_i) =
// remaining, over the workers with a positive rate. rates and held per worker.
double commonFinishSeconds(const std::vector<double>& rates, const std::vector<uint64_t>& held,
                           uint64_t remaining);

class AdaptiveReservoirStrategy final : public PooledStrategy {
 public:
  // A worker's rate counts once its results hold this many tasks, one stratum of the
  // interleaved order (interleaved_order.h): fewer have seen only part of the image, and pixel
  // costs differ by hundreds of times across it. Until then it is sized as unmeasured.
  static constexpr uint64_t kMeasuredTasks = kStratumTasks;

  // firstPercent in (0, 100], reservePercent in [0, 100), minChunk >= 1.
  AdaptiveReservoirStrategy(double firstPercent, double reservePercent, uint64_t minChunk);
  std::string name() const override { return "adaptive"; }

 protected:
  TaskSet initialPool(const StartInfo& info) override;
  void prepare(const StartInfo& info) override;
  uint64_t initialSize(int worker) override;
  uint64_t handOutSize(int worker) override;
  std::optional<Transfer> stealFor(int worker) override;
  bool waitsForSteals() const override { return true; }
  void onWorkerChanged(int worker) override;

 private:
  // The factor K of the unmeasured workers' rates K / index_i: the least over the measured of
  // rate x speed index. 0 when nothing is measured yet (then every rate is 0).
  double unmeasuredFactor() const;
  void setFactor(size_t worker, double factor);  // NaN: none
  // Worker's rate as the sizing uses it (measured, or K / index); 0 for lost workers.
  double rateOf(int worker) const;
  // The common finishing time T for `remaining` tasks in the pool (commonFinishSeconds()).
  double finishSeconds(uint64_t remaining) const;

  FinishOrder measured_;    // key h / r; a = r, b = h, c = r x index
  FinishOrder unmeasured_;  // key h x index; a = 1 / index, b = h
  std::multiset<double> factors_;  // r x index of each measured worker (K is the least)
  std::vector<double> factorOf_;   // per worker: its entry in factors_, NaN if none
  std::vector<uint64_t> held_;  // what each live worker holds, as indexed
  uint64_t heldSum_ = 0;        // over the live workers

  double firstPercent_;
  double reservePercent_;
  uint64_t minChunk_;
  std::vector<uint64_t> firstBlocks_;
};

}  // namespace prt
