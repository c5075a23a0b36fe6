#pragma once
// CPU time of the calling thread, in seconds: what a worker's throttle paces to, summed over
// the threads that render a batch.

#include <time.h>

namespace prt {

inline double threadCpuSeconds() {
  timespec ts{};
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &ts);
  return static_cast<double>(ts.tv_sec) + 1e-9 * static_cast<double>(ts.tv_nsec);
}

// The CPUs this process may run on (its affinity mask, which `mpirun --bind-to` sets); at
// least 1.
int affinityCpuCount();

}  // namespace prt
