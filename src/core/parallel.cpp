#include "core/parallel.h"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>
#include <tbb/task_arena.h>

#include <thread>

namespace prt {

int hardwareThreads() {
  const unsigned n = std::thread::hardware_concurrency();
  return n == 0 ? 1 : static_cast<int>(n);
}

void parallelFor(uint64_t count, int threads, const std::function<void(uint64_t)>& fn) {
  if (threads <= 0) threads = hardwareThreads();
  if (threads == 1 || count <= 1) {
    for (uint64_t i = 0; i < count; ++i) fn(i);
    return;
  }
  tbb::task_arena arena(threads);
  arena.execute([&] {
    // Grain 1: items are tiles of many pixels, already coarse; dynamic stealing evens out
    // tiles of very different cost.
    tbb::parallel_for(tbb::blocked_range<uint64_t>(0, count, 1),
                      [&](const tbb::blocked_range<uint64_t>& r) {
                        for (uint64_t i = r.begin(); i != r.end(); ++i) fn(i);
                      });
  });
}

}  // namespace prt
