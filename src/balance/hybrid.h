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
// Speed-weighted ("hybrid-weighted", the paper's recommendation of its speed-index bias for
// other techniques): the start is the speed-weighted scatter (weighted_scatter.h) and each
// diffusion round balances towards shares proportional to the live workers' division of
// labour instead of the plain average: worker w's target is ceil(total * div_w).
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

// The same towards per-worker targets (the queue length each should hold; lost workers'
// are ignored): senders hold more than their target, receivers less.
std::vector<Transfer> diffusionTransfersTowards(const std::vector<uint64_t>& lengths,
                                                const std::vector<bool>& live,
                                                const std::vector<bool>& waiting,
                                                const std::vector<uint64_t>& targets);

class HybridStrategy final : public StaticStrategy {
 public:
  explicit HybridStrategy(bool speedWeighted = false) : speedWeighted_(speedWeighted) {}
  std::string name() const override { return speedWeighted_ ? "hybrid-weighted" : "hybrid"; }
  Decisions start(const StartInfo& info) override;
  Decisions onRequest(int worker) override;
  Decisions onQueueLengths(const std::vector<uint64_t>& lengths) override;
  Decisions onWorkerLost(int worker, const TaskSet& unfinished) override;
  Decisions onWorkerJoined(int worker, double speedIndexSeconds) override;

 protected:
  std::vector<TaskSet> shares(const StartInfo& info) const override;

 private:
  bool speedWeighted_;
  std::vector<double> speedIndexSeconds_;
  std::vector<bool> waiting_;  // asked for more, not answered yet
  bool queryOutstanding_ = false;
};

}  // namespace prt
