#pragma once
// TaskSet: a set of pixel tasks (pixel index = y * width + x, scan-line order) held as
// compact runs, so a block of a million pixels or a scatter share is a few bytes, never one
// entry per pixel. Order is preserved: tasks are rendered and handed out front to back.
// Plain value type; not thread-safe.

#include <cstdint>
#include <string>
#include <vector>

namespace prt {

// first, first + stride, ..., first + (count - 1) * stride.
struct TaskRun {
  uint64_t first = 0;
  uint64_t count = 0;
  uint64_t stride = 1;

  uint64_t at(uint64_t i) const { return first + i * stride; }
  uint64_t last() const { return at(count - 1); }
  // Whether every task of the run is below `end`, computed without overflow whatever the
  // fields hold (a run that came over the network).
  bool endsBefore(uint64_t end) const {
    if (count == 0) return true;
    if (first >= end) return false;
    return count == 1 || stride == 0 || count - 1 <= (end - 1 - first) / stride;
  }
  bool operator==(const TaskRun&) const = default;
};

class TaskSet {
 public:
  TaskSet() = default;
  static TaskSet range(uint64_t first, uint64_t count);
  static TaskSet strided(uint64_t first, uint64_t count, uint64_t stride);

  uint64_t size() const { return size_; }
  bool empty() const { return size_ == 0; }
  const std::vector<TaskRun>& runs() const { return runs_; }
  // Whether every task is below `end` (TaskRun::endsBefore for each run).
  bool allBelow(uint64_t end) const {
    for (const TaskRun& r : runs_) {
      if (!r.endsBefore(end)) return false;
    }
    return true;
  }

  // Appends at the back, merging with the last run when it continues it.
  void append(const TaskRun& run);
  void append(const TaskSet& other);

  // Removes and returns the first (or last) n tasks; n is clamped to size().
  TaskSet takeFront(uint64_t n);
  TaskSet takeBack(uint64_t n);

  // The i-th task, i < size(). O(number of runs).
  uint64_t at(uint64_t i) const;

  template <typename F>
  void forEach(F&& f) const {
    for (const TaskRun& r : runs_) {
      for (uint64_t i = 0; i < r.count; ++i) f(r.at(i));
    }
  }
  std::vector<uint64_t> toVector() const;

  bool operator==(const TaskSet&) const = default;
  std::string describe() const;  // e.g. "{0..99, 100..196 step 3}" for logs and test messages

 private:
  std::vector<TaskRun> runs_;
  uint64_t size_ = 0;
};

}  // namespace prt
