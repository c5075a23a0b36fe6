#pragma once
// Throttle: emulates a machine k times slower on the one we have. A stretch of computing that
// used c seconds of this thread's CPU time is made to last k * c seconds of wall time: after
// it the thread waits k * c minus the wall time the stretch already took. A worker with
// slowdown k thus takes k times as long for everything it computes, the speed-index run
// included. Faithful only while the workers' combined demand, the sum of 1/k_i, fits in the
// free cores.
//
// Why pace to CPU time, and count the wall time already spent:
//  - stretching wall time k-fold would stretch queueing too: when emulated workers briefly
//    outnumber the cores, longer waits make more overlap and longer stretches, and every
//    worker ends far slower than k;
//  - waiting (k - 1) * c after the stretch, on top of its wall time, charges the queueing to
//    the worker: four workers starting their speed-index runs together on two cores each run
//    at half a core, and a k = 2 worker measured 3c instead of 2c.
// Pacing the end of the stretch to k * c absorbs the queueing into the wait, as long as the
// stretch's wall time stays under k * c.
//
// A wait also ends late: the timer's slack, and on a busy machine the wait for a core once
// the thread is runnable again, a millisecond at times against waits of one to three. Each
// late wake-up would add to the worker's time, so the lateness is carried as a lag into the next
// stretch, whose wait is shortened by it: over back-to-back stretches a worker keeps to k times its
// CPU time, and it is never ahead of that schedule. A stretch that starts more than a millisecond
// after the last one ended (the worker waited for work) starts afresh, with no lag.
//
// What the emulated machine would have measured of a stretch is k * c: a real machine k times
// slower runs it alone, with no queueing for a core. Speed indices are measured that way
// (Stretch::emulatedSeconds), so that a burst of workers starting their speed-index runs at
// once on too few cores does not make them look slower than they are; rendering is timed by
// the wall clock, since the image really waits for it. Without a slowdown (k = 1) the worker
// is the machine itself, and its wall time is what it measures, other load included.
// The slowdown may change mid-run (--slowdown-at): a schedule of changes, in seconds from the
// throttle's construction (the worker's start), gives the factor in force; each stretch is
// paced by the factor at its start, so a change takes effect from the next batch.
//
// A worker that renders with several threads is paced by the CPU time of all of them
// (measureParallel): the emulated machine has as many cores, each k times slower.
//
// Reads clocks: used by drivers only. One per worker; called from one thread at a time.

#include <algorithm>
#include <chrono>
#include <functional>
#include <thread>
#include <utility>
#include <vector>

#include "core/cpu_time.h"
#include "core/speed_schedule.h"

namespace prt {

// How long to wait after a stretch that used `cpuSeconds` of CPU and took `wallSeconds` of
// wall time, so that it lasts `slowdown` times its CPU time in all, less `lagSeconds` the
// previous stretch ended late; never negative.
inline double throttlePauseSeconds(double slowdown, double cpuSeconds, double wallSeconds,
                                   double lagSeconds = 0) {
  return std::max(0.0, slowdown * cpuSeconds - lagSeconds - wallSeconds);
}

// One throttled stretch of computing.
struct Stretch {
  double wallSeconds = 0;      // from start to the end of the wait
  double emulatedSeconds = 0;  // its length on the emulated machine: k * the CPU time it
                               // used, or the wall time when k = 1
};

class Throttle {
 public:
  // `changes`: this worker's, sorted (changesOf()); values are slowdown factors >= 1.
  explicit Throttle(double slowdown = 1.0, std::vector<SpeedChange> changes = {})
      : slowdown_(slowdown),
        changes_(std::move(changes)),
        epoch_(std::chrono::steady_clock::now()) {}
  double slowdown() const { return slowdown_; }  // the factor at the start
  // The factor in force `seconds` after construction.
  double slowdownAt(double seconds) const { return valueAt(changes_, slowdown_, seconds); }

  // Runs fn, then waits until it has lasted k times the CPU time it used (less the lag the
  // previous stretch left, if this one follows it at once). `tick`, if given, is called at
  // least every kTickSeconds of the wait (a worker's heartbeats: a machine emulated a
  // thousand times slower waits seconds after each batch, longer than a short lease).
  template <typename F>
  Stretch measure(F&& fn, const std::function<void()>& tick = {}) {
    const auto start = std::chrono::steady_clock::now();
    const double cpuStart = threadCpuSeconds();
    fn();
    return finish(start, threadCpuSeconds() - cpuStart, 1, tick);
  }

  // A stretch computed by `threads` threads at once: fn returns the CPU seconds all of them
  // used. The emulated machine has as many cores, each k times slower, so the stretch lasts
  // k times the CPU time per thread, k * cpu / threads. `tick` as for measure().
  template <typename F>
  Stretch measureParallel(F&& fn, int threads, const std::function<void()>& tick = {}) {
    const auto start = std::chrono::steady_clock::now();
    const double cpu = fn();
    return finish(start, cpu, std::max(1, threads), tick);
  }

  // measure(fn, tick), returning the wall seconds.
  template <typename F>
  double run(F&& fn, const std::function<void()>& tick = {}) {
    return measure(std::forward<F>(fn), tick).wallSeconds;
  }

  static constexpr double kTickSeconds = 0.05;

 private:
  Stretch finish(std::chrono::steady_clock::time_point start, double totalCpu, int threads,
                 const std::function<void()>& tick = {}) {
    const double cpu = totalCpu / threads;
    // Before the first stretch lastEnd_ is the clock's epoch: never back to back.
    const bool backToBack =
        std::chrono::duration<double>(start - lastEnd_).count() < kBackToBackSeconds;
    const double lag = backToBack ? lagSeconds_ : 0.0;
    const double k = slowdownAt(std::chrono::duration<double>(start - epoch_).count());
    if (k > 1.0) {
      const double pause = throttlePauseSeconds(k, cpu, secondsSince(start), lag);
      const auto until = std::chrono::steady_clock::now() +
                         std::chrono::duration_cast<std::chrono::steady_clock::duration>(
                             std::chrono::duration<double>(pause));
      for (;;) {
        const double left =
            std::chrono::duration<double>(until - std::chrono::steady_clock::now()).count();
        if (left <= 0) break;
        std::this_thread::sleep_for(
            std::chrono::duration<double>(tick ? std::min(left, kTickSeconds) : left));
        if (tick) tick();
      }
    }
    lastEnd_ = std::chrono::steady_clock::now();
    const double wall = std::chrono::duration<double>(lastEnd_ - start).count();
    if (k > 1.0) lagSeconds_ = std::max(0.0, wall - (k * cpu - lag));
    return {wall, k > 1.0 ? k * cpu : wall};
  }
  static double secondsSince(std::chrono::steady_clock::time_point start) {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  }

  static constexpr double kBackToBackSeconds = 1e-3;

  double slowdown_;
  std::vector<SpeedChange> changes_;
  std::chrono::steady_clock::time_point epoch_;
  double lagSeconds_ = 0;  // how far the last stretch ended behind its schedule
  std::chrono::steady_clock::time_point lastEnd_;
};

}  // namespace prt
