#pragma once
// Work stealing: every task is handed out at the start, an even share of the interleaved
// order (interleaved_order.h) to each worker, so each share samples the whole image. A worker
// whose queue empties steals: it takes half of a victim's queue, from the back, through a
// Transfer decision (the victim sends the tasks straight to the thief, as in diffusion).
//
// The victim is the live worker that holds the most tasks by the master's count (given and
// transferred in, less returned and transferred out; throughput.h), ties to the lower index:
// no queue query and no random probing, as the master already knows who holds the most. A
// victim is only robbed while half its count is at least minChunk tasks, and not while tasks
// stolen for it may still be on their way (PooledStrategy::awaitingSteal). A thief that finds
// no victim waits (PooledStrategy::waitsForSteals): each later result looks again, and once
// every task is back it gets NoMoreWork. The count includes the batch the victim is
// rendering, so the transfer may move fewer tasks than ordered (the worker sends what its
// queue holds); an empty transfer makes the thief ask again.
//
// Lost workers: see PooledStrategy (their tasks go to the pool, which serves requests before
// any stealing, each hand-out ceil(R / P)).

#include <cstdint>
#include <optional>
#include <functional>
#include <set>
#include <string>
#include <utility>
#include <vector>

#include "balance/pooled_strategy.h"

namespace prt {

class StealingStrategy final : public PooledStrategy {
 public:
  explicit StealingStrategy(uint64_t minChunk);
  std::string name() const override { return "stealing"; }

 protected:
  TaskSet initialPool(const StartInfo& info) override;
  void prepare(const StartInfo& info) override;
  uint64_t initialSize(int worker) override;
  uint64_t handOutSize(int worker) override;
  std::optional<Transfer> stealFor(int worker) override;
  bool waitsForSteals() const override { return true; }
  void onWorkerChanged(int worker) override;

 private:
  // The live workers with no steal on their way to them, fullest first, then by worker: the
  // victim is the first that is not the thief (O(log W) per change, no walk).
  std::set<std::pair<uint64_t, int>, std::greater<>> victims_;  // (held, -worker)
  std::vector<uint64_t> indexed_;  // each worker's held as entered in victims_
  uint64_t minChunk_;
  uint64_t taskCount_ = 0;
  uint64_t workerCount_ = 1;
};

}  // namespace prt
