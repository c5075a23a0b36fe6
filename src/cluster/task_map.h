#pragma once
// TaskMap: the strategy's tasks as the pixels still to render. A strategy always balances
// tasks 0 .. taskCount-1; on a fresh run task i is pixel i, and on a resumed run (some pixels
// already done, from a checkpoint) task i is the i-th pixel still missing, in scan-line order,
// so every strategy works unchanged on whatever is left. Immutable after construction.

#include <cstdint>
#include <vector>

#include "core/task_set.h"

namespace prt {

class TaskMap {
 public:
  // Every pixel is a task: the identity.
  explicit TaskMap(uint64_t pixelCount);
  // Only the pixels not in `done` are tasks.
  TaskMap(uint64_t pixelCount, const TaskSet& done);

  uint64_t taskCount() const { return taskCount_; }
  bool isIdentity() const { return segments_.empty(); }

  TaskSet toPixels(const TaskSet& tasks) const;
  // How many tasks are pixels below `pixel` (the pixels still missing before it).
  uint64_t tasksBefore(uint64_t pixel) const;
  // Every pixel must be one of the tasks (not done).
  TaskSet toTasks(const TaskSet& pixels) const;

 private:
  struct Segment {
    uint64_t firstPixel = 0;
    uint64_t firstTask = 0;
    uint64_t count = 0;
  };
  uint64_t pixelOf(uint64_t task) const;
  uint64_t taskOf(uint64_t pixel) const;

  uint64_t taskCount_ = 0;
  std::vector<Segment> segments_;  // empty for the identity; else the missing pixels' runs
};

}  // namespace prt
