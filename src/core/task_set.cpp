#include "core/task_set.h"

#include <algorithm>

#include "core/check.h"

namespace prt {

TaskSet TaskSet::range(uint64_t first, uint64_t count) { return strided(first, count, 1); }

TaskSet TaskSet::strided(uint64_t first, uint64_t count, uint64_t stride) {
  TaskSet s;
  s.append(TaskRun{first, count, stride});
  return s;
}

void TaskSet::append(const TaskRun& run) {
  if (run.count == 0) return;
  TaskRun r = run;
  if (r.count == 1) r.stride = 1;  // canonical form for singletons
  if (!runs_.empty()) {
    TaskRun& back = runs_.back();
    // A singleton at the back can adopt any stride that continues it.
    if (back.count == 1 && r.first > back.first) {
      const uint64_t step = r.first - back.first;
      if (r.count == 1 || r.stride == step) {
        back.stride = step;
        back.count += r.count;
        size_ += r.count;
        return;
      }
    } else if (back.count > 1 && r.first == back.last() + back.stride &&
               (r.count == 1 || r.stride == back.stride)) {
      back.count += r.count;
      size_ += r.count;
      return;
    }
  }
  runs_.push_back(r);
  size_ += r.count;
}

void TaskSet::append(const TaskSet& other) {
  for (const TaskRun& r : other.runs_) append(r);
}

TaskSet TaskSet::takeFront(uint64_t n) {
  n = std::min(n, size_);
  TaskSet out;
  size_t whole = 0;
  uint64_t left = n;
  while (left > 0 && whole < runs_.size() && runs_[whole].count <= left) {
    out.append(runs_[whole]);
    left -= runs_[whole].count;
    ++whole;
  }
  runs_.erase(runs_.begin(), runs_.begin() + static_cast<std::ptrdiff_t>(whole));
  if (left > 0) {
    TaskRun& r = runs_.front();
    out.append(TaskRun{r.first, left, r.stride});
    r.first = r.at(left);
    r.count -= left;
  }
  size_ -= n;
  return out;
}

TaskSet TaskSet::takeBack(uint64_t n) {
  n = std::min(n, size_);
  std::vector<TaskRun> taken;  // in reverse order
  uint64_t left = n;
  while (left > 0) {
    TaskRun& r = runs_.back();
    if (r.count <= left) {
      taken.push_back(r);
      left -= r.count;
      runs_.pop_back();
    } else {
      taken.push_back(TaskRun{r.at(r.count - left), left, r.stride});
      r.count -= left;
      left = 0;
    }
  }
  size_ -= n;
  TaskSet out;
  for (auto it = taken.rbegin(); it != taken.rend(); ++it) out.append(*it);
  return out;
}

uint64_t TaskSet::at(uint64_t i) const {
  PRT_CHECK(i < size_);
  for (const TaskRun& r : runs_) {
    if (i < r.count) return r.at(i);
    i -= r.count;
  }
  PRT_CHECK(false);
  return 0;
}

std::vector<uint64_t> TaskSet::toVector() const {
  std::vector<uint64_t> v;
  v.reserve(size_);
  forEach([&](uint64_t t) { v.push_back(t); });
  return v;
}

std::string TaskSet::describe() const {
  std::string s = "{";
  for (size_t i = 0; i < runs_.size(); ++i) {
    const TaskRun& r = runs_[i];
    if (i) s += ", ";
    s += std::to_string(r.first);
    if (r.count > 1) {
      s += ".." + std::to_string(r.last());
      if (r.stride != 1) s += " step " + std::to_string(r.stride);
    }
  }
  return s + "}";
}

}  // namespace prt
