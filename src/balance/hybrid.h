#pragma once
// Hybrid: scatter decomposition first, then diffusion (Heirich and Arvo, as the paper uses
// it). When a worker's queue empties and it asks for
// more, the master asks every live worker for its queue length; workers above the average
// send their excess straight to workers below it (in a fully connected network every worker
// is a neighbour).
//
// Termination: each request is answered by one query, and each answer gives every waiting
// worker either at least one Transfer or NoMoreWork. Nothing moves unless some queue holds
// more than ceil(average), so tiny queues end the diffusion instead of looping. Requests
// that arrive while a query is outstanding wait for that query's answer.
//
// Lost workers: their tasks are assigned at once to the live workers (see StaticStrategy)
// and they are left out of averages and transfers. Not thread-safe.

#include <cstdint>
#include <string>
#include <vector>

#include "balance/static_strategy.h"

namespace prt {

// One round of diffusion. target = ceil(total / L) over the L live workers; a live worker
// holding more than target may send the excess, one holding less may receive up to the
// deficit. Greedy matching: the largest excess goes to the largest deficit first (ties: the
// `waiting` workers first, then lower index). Transfers move at most the total excess.
std::vector<Transfer> diffusionTransfers(const std::vector<uint64_t>& lengths,
                                         const std::vector<bool>& live,
                                         const std::vector<bool>& waiting);

class HybridStrategy final : public StaticStrategy {
 public:
  std::string name() const override { return "hybrid"; }
  Decisions start(const StartInfo& info) override;
  Decisions onRequest(int worker) override;
  Decisions onQueueLengths(const std::vector<uint64_t>& lengths) override;
  Decisions onWorkerLost(int worker, const TaskSet& unfinished) override;

 protected:
  std::vector<TaskSet> shares(uint64_t taskCount, int workerCount) const override;

 private:
  std::vector<bool> waiting_;  // asked for more, not answered yet
  bool queryOutstanding_ = false;
};

}  // namespace prt
