#pragma once
// Helpers shared by the strategies: splitting a TaskSet into near-equal contiguous pieces and
// tracking which workers are still alive. Plain values; not thread-safe.

#include <cstdint>
#include <vector>

#include "balance/strategy.h"
#include "core/task_set.h"

namespace prt {

// Splits `tasks` front to back into `parts` >= 1 contiguous pieces whose sizes differ by at
// most one, the larger pieces first. Pieces may be empty when parts > tasks.size().
std::vector<TaskSet> splitEvenly(const TaskSet& tasks, uint64_t parts);

// Which of the c workers are alive. Everyone starts alive; a lost worker never comes back; a
// worker that joins is added live at the end.
class LiveWorkers {
 public:
  void reset(int workerCount) {
    live_.assign(static_cast<size_t>(workerCount), true);
    liveCount_ = workerCount;
  }
  // A worker joins: it is live, with the next index, which is returned.
  int add() {
    live_.push_back(true);
    ++liveCount_;
    return workerCount() - 1;
  }
  int workerCount() const { return static_cast<int>(live_.size()); }
  bool isLive(int worker) const;
  void markLost(int worker);  // ignores unknown workers
  int liveCount() const { return liveCount_; }
  std::vector<int> liveList() const;  // in worker order: O(W), not for every decision

 private:
  std::vector<bool> live_;
  int liveCount_ = 0;
};

// Assign decisions that give `tasks` to the live workers, split evenly in worker order
// (empty pieces are skipped). Returns nothing when no worker is alive.
Decisions spreadOverLiveWorkers(const TaskSet& tasks, const LiveWorkers& workers);

// Throws InputError unless there is at least one worker and every speed index is positive
// and finite.
void validateStartInfo(const StartInfo& info);
// Throws InputError unless `worker` is the next index after `current` workers and its speed
// index is positive and finite (Strategy::onWorkerJoined's contract).
void validateJoin(int worker, int current, double speedIndexSeconds);

}  // namespace prt
