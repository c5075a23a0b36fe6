#include "balance/task_pool.h"

#include <algorithm>

namespace prt {

TaskPool::TaskPool(const TaskSet& tasks) {
  putFront(tasks);
}

TaskSet TaskPool::takeFront(uint64_t n) {
  n = std::min(n, size_);
  TaskSet out;
  uint64_t left = n;
  while (left > 0) {
    TaskRun& r = reversed_.back();
    if (r.count <= left) {
      out.append(r);
      left -= r.count;
      reversed_.pop_back();
    } else {
      out.append(TaskRun{r.first, left, r.stride});
      r.first = r.at(left);
      r.count -= left;
      left = 0;
    }
  }
  size_ -= n;
  return out;
}

void TaskPool::putFront(const TaskSet& tasks) {
  const std::vector<TaskRun>& runs = tasks.runs();
  for (auto it = runs.rbegin(); it != runs.rend(); ++it) {
    if (it->count > 0) reversed_.push_back(*it);
  }
  size_ += tasks.size();
}

}  // namespace prt
