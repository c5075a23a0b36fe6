#include "cluster/task_map.h"

#include <algorithm>

#include "core/check.h"

namespace prt {

TaskMap::TaskMap(uint64_t pixelCount) : taskCount_(pixelCount) {}

TaskMap::TaskMap(uint64_t pixelCount, const TaskSet& done) {
  std::vector<bool> isDone(pixelCount, false);
  done.forEach([&](uint64_t p) {
    PRT_CHECK(p < pixelCount);
    isDone[p] = true;
  });
  for (uint64_t p = 0; p < pixelCount; ++p) {
    if (isDone[p]) continue;
    uint64_t end = p;
    while (end < pixelCount && !isDone[end]) ++end;
    segments_.push_back(Segment{p, taskCount_, end - p});
    taskCount_ += end - p;
    p = end;
  }
  // Nothing done: keep the identity's fast path. All done: a map with no segments and no tasks
  // would read as the identity, so keep one empty segment to say otherwise.
  if (done.empty()) {
    segments_.clear();
  } else if (segments_.empty()) {
    segments_.push_back(Segment{pixelCount, 0, 0});
  }
}

uint64_t TaskMap::pixelOf(uint64_t task) const {
  PRT_CHECK(task < taskCount_);
  auto it = std::upper_bound(segments_.begin(), segments_.end(), task,
                             [](uint64_t t, const Segment& s) { return t < s.firstTask; });
  --it;
  return it->firstPixel + (task - it->firstTask);
}

uint64_t TaskMap::taskOf(uint64_t pixel) const {
  auto it = std::upper_bound(segments_.begin(), segments_.end(), pixel,
                             [](uint64_t p, const Segment& s) { return p < s.firstPixel; });
  PRT_CHECK(it != segments_.begin());
  --it;
  PRT_CHECK(pixel < it->firstPixel + it->count);
  return it->firstTask + (pixel - it->firstPixel);
}

uint64_t TaskMap::tasksBefore(uint64_t pixel) const {
  if (isIdentity()) return std::min(pixel, taskCount_);
  auto it = std::upper_bound(segments_.begin(), segments_.end(), pixel,
                             [](uint64_t p, const Segment& s) { return p < s.firstPixel; });
  if (it == segments_.begin()) return 0;
  --it;
  return it->firstTask + std::min(pixel - it->firstPixel, it->count);
}

TaskSet TaskMap::toPixels(const TaskSet& tasks) const {
  if (isIdentity()) return tasks;
  TaskSet out;
  for (const TaskRun& r : tasks.runs()) {
    if (r.stride != 1) {
      for (uint64_t i = 0; i < r.count; ++i) out.append(TaskRun{pixelOf(r.at(i)), 1, 1});
      continue;
    }
    // A contiguous run of tasks is contiguous within each segment it crosses.
    uint64_t task = r.first;
    uint64_t left = r.count;
    while (left > 0) {
      auto it = std::upper_bound(segments_.begin(), segments_.end(), task,
                                 [](uint64_t t, const Segment& s) { return t < s.firstTask; });
      --it;
      const uint64_t offset = task - it->firstTask;
      const uint64_t take = std::min(left, it->count - offset);
      out.append(TaskRun{it->firstPixel + offset, take, 1});
      task += take;
      left -= take;
    }
  }
  return out;
}

TaskSet TaskMap::toTasks(const TaskSet& pixels) const {
  if (isIdentity()) return pixels;
  TaskSet out;
  pixels.forEach([&](uint64_t p) { out.append(TaskRun{taskOf(p), 1, 1}); });
  return out;
}

}  // namespace prt
