#pragma once
// Throttle: emulates a machine k times slower on the one we have. After each stretch of t
// seconds of computing it waits (k - 1) * t, so a worker with slowdown k takes k times as
// long for everything it computes, the speed-index run included. Faithful only while the
// workers' combined demand, the sum of 1/k_i, fits in the free cores.
// Reads the clock: used by drivers only. Thread-safe (no state besides k).

#include <chrono>
#include <thread>

namespace prt {

class Throttle {
 public:
  explicit Throttle(double slowdown = 1.0) : slowdown_(slowdown) {}
  double slowdown() const { return slowdown_; }

  // Runs fn, then waits to stretch its duration k-fold. Returns the total wall seconds.
  template <typename F>
  double run(F&& fn) const {
    const auto start = std::chrono::steady_clock::now();
    fn();
    const auto computed = std::chrono::steady_clock::now() - start;
    if (slowdown_ > 1.0) {
      std::this_thread::sleep_until(
          start + std::chrono::duration_cast<std::chrono::steady_clock::duration>(computed *
                                                                                    slowdown_));
    }
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  }

 private:
  double slowdown_;
};

}  // namespace prt
