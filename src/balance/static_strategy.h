#pragma once
// StaticStrategy: the skeleton of strategies that split every task at the start and hand
// out nothing afterwards (scatter, blocks; hybrid adds diffusion on top). A request gets
// NoMoreWork. A lost worker's unfinished tasks are assigned at once to the live workers,
// split evenly into contiguous pieces in worker order: nothing is held back, so no live
// worker needs to ask for them. A worker that joins gets nothing but such leftovers.
// Not thread-safe.

#include <cstdint>
#include <vector>

#include "balance/strategy.h"
#include "balance/task_split.h"

namespace prt {

class StaticStrategy : public Strategy {
 public:
  Decisions start(const StartInfo& info) override;
  Decisions onRequest(int worker) override;
  Decisions onWorkerLost(int worker, const TaskSet& unfinished) override;
  // The newcomer gets nothing (the image was divided at the start); it is live, so the
  // tasks of a worker lost later are spread over it too.
  Decisions onWorkerJoined(int worker, double speedIndexSeconds) override;

 protected:
  // Every task, split over the workers (one per speed index): element w goes to worker w.
  virtual std::vector<TaskSet> shares(const StartInfo& info) const = 0;
  const LiveWorkers& workers() const { return workers_; }

 private:
  LiveWorkers workers_;
};

}  // namespace prt
