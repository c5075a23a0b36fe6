#include "core/parallel.h"

#include "core/cpu_allocation.h"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>
#include <tbb/task_arena.h>

#include <map>
#include <memory>
#include <thread>

namespace prt {

int hardwareThreads() {
  const unsigned n = std::thread::hardware_concurrency();
  return n == 0 ? 1 : static_cast<int>(n);
}

void parallelFor(uint64_t count, int threads, const std::function<void(uint64_t)>& fn) {
  if (threads <= 0) threads = allocatedCpuCount();  // the mask, and a Slurm job's share
  if (threads == 1 || count <= 1) {
    for (uint64_t i = 0; i < count; ++i) fn(i);
    return;
  }
  // One arena per calling thread and thread count, kept: making one for every call costs a
  // worker that renders many small batches on several threads a tenth of its time.
  thread_local std::map<int, std::unique_ptr<tbb::task_arena>> arenas;
  std::unique_ptr<tbb::task_arena>& arena = arenas[threads];
  if (!arena) arena = std::make_unique<tbb::task_arena>(threads);
  arena->execute([&] {
    // Grain 1: items are tiles of many pixels, already coarse; dynamic stealing evens out
    // tiles of very different cost.
    tbb::parallel_for(tbb::blocked_range<uint64_t>(0, count, 1),
                      [&](const tbb::blocked_range<uint64_t>& r) {
                        for (uint64_t i = r.begin(); i != r.end(); ++i) fn(i);
                      });
  });
}

}  // namespace prt
