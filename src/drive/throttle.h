#pragma once
// Throttle: emulates a machine k times slower on the one we have. After each stretch of
// computing that took t seconds of this thread's CPU time it waits (k - 1) * t, so a worker
// with slowdown k takes k times as long for everything it computes, the speed-index run
// included. Faithful only while the workers' combined demand, the sum of 1/k_i, fits in the
// free cores.
//
// Why CPU time rather than wall time: when emulated workers briefly outnumber the cores, a
// stretch's wall time grows with the queueing; stretching the queueing too would feed back
// (longer waits, more overlap, longer stretches) and slow every worker far beyond k. With
// CPU time only the work itself is stretched.
// Reads clocks: used by drivers only. Thread-safe (no state besides k).

#include <time.h>

#include <chrono>
#include <thread>

namespace prt {

class Throttle {
 public:
  explicit Throttle(double slowdown = 1.0) : slowdown_(slowdown) {}
  double slowdown() const { return slowdown_; }

  // Runs fn, then waits (k - 1) times the CPU time it used. Returns the total wall seconds.
  template <typename F>
  double run(F&& fn) const {
    const auto start = std::chrono::steady_clock::now();
    const double cpuStart = threadCpuSeconds();
    fn();
    if (slowdown_ > 1.0) {
      const double cpu = threadCpuSeconds() - cpuStart;
      std::this_thread::sleep_for(std::chrono::duration<double>((slowdown_ - 1.0) * cpu));
    }
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  }

 private:
  static double threadCpuSeconds() {
    timespec ts{};
    clock_gettime(CLOCK_THREAD_CPUTIME_ID, &ts);
    return static_cast<double>(ts.tv_sec) + 1e-9 * static_cast<double>(ts.tv_nsec);
  }

  double slowdown_;
};

}  // namespace prt
