#pragma once
// TaskPool: the pooled strategies' tasks not handed out yet, in the order they go out. Taking
// from the front and putting tasks back at the front (a lost worker's) cost what they move,
// never the size of the pool: the runs are kept in reverse order, the front at the back of
// the vector. (A TaskSet taken from the front erases its first runs, which moves every other
// run: with the interleaved order's many runs that was most of a hand-out's time.)
// Plain value; not thread-safe.

#include <cstdint>
#include <vector>

#include "core/task_set.h"

namespace prt {

class TaskPool {
 public:
  TaskPool() = default;
  explicit TaskPool(const TaskSet& tasks);

  uint64_t size() const { return size_; }
  bool empty() const { return size_ == 0; }
  // The first min(n, size()) tasks, in order.
  TaskSet takeFront(uint64_t n);
  // `tasks` go out before everything in the pool, in their order.
  void putFront(const TaskSet& tasks);

 private:
  std::vector<TaskRun> reversed_;  // the front run last
  uint64_t size_ = 0;
};

}  // namespace prt
