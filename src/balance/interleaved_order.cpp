#include "balance/interleaved_order.h"

#include <algorithm>
#include <cmath>

namespace prt {
namespace {

bool isPrime(uint64_t n) {
  if (n < 2) return false;
  for (uint64_t d = 2; d * d <= n; ++d) {
    if (n % d == 0) return false;
  }
  return true;
}

}  // namespace

uint64_t interleavedCells(uint64_t taskCount) {
  if (taskCount <= 1) return 1;
  uint64_t c = std::max<uint64_t>(2, taskCount / (kStratumTasks * kCellStrata));
  while (!isPrime(c)) ++c;
  return c;
}

uint64_t interleavedStrata(uint64_t taskCount) {
  if (taskCount <= 1) return 1;
  return std::min(interleavedCells(taskCount) * kCellStrata, taskCount);
}

TaskSet interleavedOrder(const std::vector<uint64_t>& frameTaskCounts) {
  TaskSet order;
  uint64_t start = 0;
  for (const uint64_t count : frameTaskCounts) {
    if (count == 0) continue;
    const TaskSet frame = interleavedOrder(count);
    for (TaskRun run : frame.runs()) {
      run.first += start;
      order.append(run);
    }
    start += count;
  }
  return order;
}

TaskSet interleavedOrder(const StartInfo& info) {
  if (!info.frameTaskCounts.empty()) return interleavedOrder(info.frameTaskCounts);
  return interleavedOrder(info.taskCount, info.frameTasks);
}

TaskSet interleavedOrder(uint64_t taskCount, uint64_t frameTasks) {
  if (frameTasks > 0 && frameTasks < taskCount) {
    std::vector<uint64_t> counts;
    for (uint64_t start = 0; start < taskCount; start += frameTasks) {
      counts.push_back(std::min(frameTasks, taskCount - start));
    }
    return interleavedOrder(counts);
  }
  const uint64_t strata = interleavedStrata(taskCount);
  if (strata <= 1) return TaskSet::range(0, taskCount);
  const uint64_t cells = interleavedCells(taskCount);
  // The golden-ratio step over the cells, coprime with their prime number.
  const double golden = (std::sqrt(5.0) - 1) / 2;
  const uint64_t step = std::clamp<uint64_t>(
      static_cast<uint64_t>(std::llround(golden * static_cast<double>(cells))), 1, cells - 1);
  TaskSet order;
  uint64_t cell = 0;
  for (uint64_t i = 0; i < cells; ++i) {
    for (uint64_t k = 0; k < kCellStrata; ++k) {
      const uint64_t first = cell * kCellStrata + k;
      if (first < strata) {
        order.append(TaskRun{first, (taskCount - first + strata - 1) / strata, strata});
      }
    }
    cell = (cell + step) % cells;
  }
  return order;
}

}  // namespace prt
