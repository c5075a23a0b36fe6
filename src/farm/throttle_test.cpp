#include "farm/throttle.h"

#include <gtest/gtest.h>

#include <vector>

#include "core/cpu_time.h"

namespace prt {
namespace {

TEST(Throttle, PausesUntilTheStretchLastsKTimesItsCpuTime) {
  // Alone on a core: wall time equals CPU time, the wait is (k - 1) * c.
  EXPECT_DOUBLE_EQ(throttlePauseSeconds(4.0, 0.010, 0.010), 0.030);
  EXPECT_DOUBLE_EQ(throttlePauseSeconds(1.0, 0.010, 0.010), 0.0);
}

TEST(Throttle, AbsorbsQueueingIntoTheWait) {
  // Sharing a core with another thread, the stretch took twice its CPU time: a k = 2 worker
  // is already as slow as it should be and does not wait; a k = 4 worker waits the rest.
  EXPECT_DOUBLE_EQ(throttlePauseSeconds(2.0, 0.010, 0.020), 0.0);
  EXPECT_DOUBLE_EQ(throttlePauseSeconds(4.0, 0.010, 0.020), 0.020);
}

TEST(Throttle, NeverWaitsANegativeTime) {
  EXPECT_EQ(throttlePauseSeconds(2.0, 0.010, 0.050), 0.0);
  EXPECT_EQ(throttlePauseSeconds(2.0, 0.010, 0.010, 0.5), 0.0);
}

TEST(Throttle, ALateWakeUpShortensTheNextWait) {
  // The previous wait ended 2 ms late: the next stretch waits 2 ms less.
  EXPECT_DOUBLE_EQ(throttlePauseSeconds(4.0, 0.010, 0.010, 0.002), 0.028);
}

TEST(Throttle, BackToBackStretchesKeepToTheirScheduleOverall) {
  // However late each wake-up, n back-to-back stretches of c CPU seconds last about k * n * c
  // (at most one late wake-up more), and never less.
  Throttle throttle(3.0);
  volatile double sink = 0;
  const auto start = std::chrono::steady_clock::now();
  double emulated = 0;
  for (int i = 0; i < 20; ++i) {
    emulated += throttle
                    .measure([&] {
                      for (int j = 0; j < 200000; ++j) sink = sink + 1e-9 * j;
                    })
                    .emulatedSeconds;
  }
  const double wall =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  EXPECT_GE(wall, emulated * 0.999);
}

TEST(Throttle, RunReturnsTheStretchedWallTime) {
  // Burn a little CPU: the run lasts at least k times the CPU time the work used.
  Throttle throttle(3.0);
  volatile double sink = 0;
  const auto cpuNow = [] {
    timespec ts{};
    clock_gettime(CLOCK_THREAD_CPUTIME_ID, &ts);
    return static_cast<double>(ts.tv_sec) + 1e-9 * static_cast<double>(ts.tv_nsec);
  };
  double cpu = 0;
  const double wall = throttle.run([&] {
    const double c0 = cpuNow();
    for (int i = 0; i < 2000000; ++i) sink = sink + 1e-9 * i;
    cpu = cpuNow() - c0;
  });
  EXPECT_GE(wall, 3.0 * cpu * 0.999);
}

TEST(Throttle, ALongWaitTicksAtLeastEveryTickInterval) {
  // A machine emulated 500 times slower: some CPU time makes a wait of many tick intervals,
  // and the tick (a worker's heartbeat) comes all through it, never more than an interval
  // (and scheduling slack) apart.
  Throttle throttle(500.0);
  volatile double sink = 0;
  std::vector<std::chrono::steady_clock::time_point> ticks;
  const auto start = std::chrono::steady_clock::now();
  const double wall = throttle.run(
      [&] {  // a millisecond of CPU time: half a second of waiting
        const double c0 = threadCpuSeconds();
        while (threadCpuSeconds() - c0 < 1e-3) sink = sink + 1e-9;
      },
      [&] { ticks.push_back(std::chrono::steady_clock::now()); });
  ASSERT_GT(wall, 8 * Throttle::kTickSeconds) << "too little CPU time to test with";
  ASSERT_GE(ticks.size(), 4u);
  auto previous = start;
  for (const auto& t : ticks) {
    EXPECT_LT(std::chrono::duration<double>(t - previous).count(), 4 * Throttle::kTickSeconds);
    previous = t;
  }
}

TEST(Throttle, EmulatedTimeIsKTimesTheCpuTimeAndWallTimeWithoutSlowdown) {
  volatile double sink = 0;
  auto work = [&] {
    for (int i = 0; i < 1000000; ++i) sink = sink + 1e-9 * i;
  };
  Throttle slow(4.0), plain(1.0);
  const Stretch slowed = slow.measure(work);
  EXPECT_GT(slowed.emulatedSeconds, 0.0);
  EXPECT_GE(slowed.wallSeconds, slowed.emulatedSeconds * 0.999);
  const Stretch full = plain.measure(work);
  EXPECT_EQ(full.emulatedSeconds, full.wallSeconds);
}

}  // namespace
}  // namespace prt

namespace prt {
namespace {

TEST(Throttle, AMultiThreadedStretchIsPacedByTheCpuTimeOfEveryThread) {
  // Two threads used 40 ms of CPU in all: the emulated machine's two cores, each three times
  // slower, take 3 * 40 / 2 = 60 ms.
  Throttle throttle(3.0);
  const Stretch s = throttle.measureParallel([] { return 0.040; }, 2);
  EXPECT_DOUBLE_EQ(s.emulatedSeconds, 0.060);
  EXPECT_GE(s.wallSeconds, 0.060 * 0.999);
  // Unthrottled, the stretch is what it took.
  Throttle plain;
  EXPECT_LT(plain.measureParallel([] { return 0.040; }, 2).wallSeconds, 0.030);
}

TEST(Throttle, AMultiThreadedStretchTicksThroughItsWait) {
  // A worker of two threads emulated 1000 times slower: 2 ms of CPU in all make a second of
  // waiting, through which its heartbeats must go on (a master's lease is a few seconds).
  Throttle throttle(1000.0);
  int ticks = 0;
  const Stretch s = throttle.measureParallel([] { return 0.002; }, 2, [&] { ++ticks; });
  EXPECT_GE(s.wallSeconds, 0.999);
  EXPECT_GE(ticks, 10);
}

TEST(Throttle, TheSlowdownFollowsItsSchedule) {
  const Throttle throttle(2.0, changesOf(parseSpeedChanges("0:1:8,0:0.5:4", "--slowdown-at", 1, 1), 0));
  EXPECT_EQ(throttle.slowdown(), 2.0);
  EXPECT_EQ(throttle.slowdownAt(0.2), 2.0);
  EXPECT_EQ(throttle.slowdownAt(0.5), 4.0);
  EXPECT_EQ(throttle.slowdownAt(3.0), 8.0);
}

TEST(Throttle, AChangeAlreadyDueSlowsTheNextStretch) {
  // A change at time 0: the first stretch is paced at k = 5, its emulated length 5 * CPU.
  Throttle throttle(1.0, {SpeedChange{0, 0, 5}});
  volatile double sink = 0;
  double cpu = 0;
  const Stretch s = throttle.measure([&] {
    timespec a{}, b{};
    clock_gettime(CLOCK_THREAD_CPUTIME_ID, &a);
    for (int j = 0; j < 2000000; ++j) sink = sink + 1e-9 * j;
    clock_gettime(CLOCK_THREAD_CPUTIME_ID, &b);
    cpu = static_cast<double>(b.tv_sec - a.tv_sec) + 1e-9 * static_cast<double>(b.tv_nsec - a.tv_nsec);
  });
  EXPECT_GE(s.emulatedSeconds, 4.5 * cpu);  // k = 1 would give the wall time, about cpu
  EXPECT_GE(s.wallSeconds, 4.5 * cpu);
}

}  // namespace
}  // namespace prt
