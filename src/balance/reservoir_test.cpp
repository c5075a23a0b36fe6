#include "balance/reservoir.h"

#include <gtest/gtest.h>

#include "balance/assign_testing.h"
#include "balance/interleaved_order.h"
#include "core/input_error.h"

namespace prt {
namespace {

using testing_support::assignRange;

TEST(ReservoirTest, ScriptedRequestsThreeWorkers) {
  // Speeds (1, 2, 4): division 4/7, 2/7, 1/7. n = 100, p = 80 %: limit 80, blocks
  // ceil(45.7) = 46, ceil(22.9) = 23, then 11 of ceil(11.4) = 12; the reservoir is 80..99.
  ReservoirStrategy s(80);
  EXPECT_EQ(s.start(StartInfo{100, {1, 2, 4}}),
            (Decisions{assignRange(0, 0, 46), assignRange(1, 46, 23), assignRange(2, 69, 11)}));
  EXPECT_EQ(s.onRequest(0), (Decisions{assignRange(0, 80, 12)}));  // ceil(20 * 4/7) = 12
  EXPECT_EQ(s.onRequest(2), (Decisions{assignRange(2, 92, 2)}));   // ceil(8 * 1/7) = 2
  EXPECT_EQ(s.onRequest(1), (Decisions{assignRange(1, 94, 2)}));   // ceil(6 * 2/7) = 2
  EXPECT_EQ(s.onRequest(0), (Decisions{assignRange(0, 96, 3)}));   // ceil(4 * 4/7) = 3
  EXPECT_EQ(s.onRequest(1), (Decisions{assignRange(1, 99, 1)}));   // ceil(1 * 2/7) = 1
  EXPECT_EQ(s.onRequest(2), (Decisions{NoMoreWork{2}}));
  EXPECT_EQ(s.onRequest(0), (Decisions{NoMoreWork{0}}));
}

TEST(ReservoirTest, TableOneWorkerOneTakesSixtyFiveOfAHundred) {
  // n = 500, p = 80 %: 400 tasks out at the start, 100 in the reserve.
  ReservoirStrategy s(80);
  const Decisions start = s.start(StartInfo{500, {1, 3, 12, 7}});
  EXPECT_EQ(start, (Decisions{assignRange(0, 0, 257), assignRange(1, 257, 86),
                              assignRange(2, 343, 22), assignRange(3, 365, 35)}));
  EXPECT_EQ(s.onRequest(0), (Decisions{assignRange(0, 400, 65)}));
  EXPECT_NEAR(s.division()[2], 1.0 / 18.714285714285714, 1e-12);
}

TEST(ReservoirTest, HundredPercentLeavesAnEmptyReservoir) {
  ReservoirStrategy s(100);
  const Decisions start = s.start(StartInfo{10, {1, 1}});
  EXPECT_EQ(start, (Decisions{assignRange(0, 0, 5), assignRange(1, 5, 5)}));
  EXPECT_EQ(s.onRequest(1), (Decisions{NoMoreWork{1}}));
}

TEST(ReservoirTest, TinyImageManyWorkers) {
  // One task, three workers: limit ceil(0.8) = 1, all of it to worker 0.
  ReservoirStrategy s(80);
  EXPECT_EQ(s.start(StartInfo{1, {1, 1, 1}}), (Decisions{assignRange(0, 0, 1)}));
  EXPECT_EQ(s.onRequest(1), (Decisions{NoMoreWork{1}}));
}

TEST(ReservoirTest, LostWorkersTasksGoOutFirstWithTheDivisionRecomputed) {
  ReservoirStrategy s(80);
  s.start(StartInfo{100, {1, 2, 4}});
  // Worker 1 rendered 46..49 of its block 46..68 and vanished.
  EXPECT_TRUE(s.onWorkerLost(1, TaskSet::range(50, 19)).empty());  // nobody is idle
  EXPECT_DOUBLE_EQ(s.division()[0], 0.8);                          // speeds (1, 4) left
  EXPECT_DOUBLE_EQ(s.division()[1], 0.0);
  // Pool {50..68, 80..99}, 39 tasks: ceil(0.8 * 39) = 32.
  TaskSet expected = TaskSet::range(50, 19);
  expected.append(TaskSet::range(80, 13));
  EXPECT_EQ(s.onRequest(0), (Decisions{Assign{0, expected}}));
  EXPECT_EQ(s.onRequest(1), (Decisions{NoMoreWork{1}}));  // lost: nothing ever again
}

TEST(ReservoirTest, LostWorkerServesIdleWorkersAtOnce) {
  ReservoirStrategy s(100);
  s.start(StartInfo{9, {1, 1, 1}});  // 0..2, 3..5, 6..8
  EXPECT_EQ(s.onRequest(2), (Decisions{NoMoreWork{2}}));
  // Worker 0 goes with 1..2 unrendered: worker 2 is idle and gets ceil(2 * 1/2) = 1 now.
  EXPECT_EQ(s.onWorkerLost(0, TaskSet::range(1, 2)), (Decisions{assignRange(2, 1, 1)}));
  EXPECT_EQ(s.onRequest(1), (Decisions{assignRange(1, 2, 1)}));
  EXPECT_EQ(s.onRequest(2), (Decisions{NoMoreWork{2}}));
}

TEST(ReservoirTest, RejectsInitialPercentOutOfRange) {
  EXPECT_THROW(ReservoirStrategy(0), InputError);
  EXPECT_THROW(ReservoirStrategy(-5), InputError);
  EXPECT_THROW(ReservoirStrategy(100.5), InputError);
  EXPECT_NO_THROW(ReservoirStrategy(0.5));
}

TEST(ReservoirTest, RejectsBadSpeedIndices) {
  ReservoirStrategy s(80);
  EXPECT_THROW(s.start(StartInfo{10, {}}), InputError);
  EXPECT_THROW(s.start(StartInfo{10, {1, 0}}), InputError);
  EXPECT_THROW(s.start(StartInfo{10, {1, -2}}), InputError);
}

}  // namespace
}  // namespace prt

namespace prt {
namespace {

TEST(ReservoirScatterTest, BlocksAndHandOutsFollowTheInterleavedOrder) {
  ReservoirStrategy strategy(80, /*interleaved=*/true);
  EXPECT_EQ(strategy.name(), "reservoir-scatter");
  // 2 equal workers, 40 tasks in the interleaved order (8 strata of 5: 0, 8, .., 32 then
  // 1, 9, ..); limit 32, blocks of 16 in that order; the reservoir holds the last 8 and half
  // of it goes to the first request.
  TaskSet order = interleavedOrder(40);
  ASSERT_EQ(order.runs().front(), (TaskRun{0, 5, 8}));
  const TaskSet first = order.takeFront(16), second = order.takeFront(16);
  const Decisions start = strategy.start(StartInfo{40, {1.0, 1.0}});
  ASSERT_EQ(start.size(), 2u);
  EXPECT_EQ(std::get<Assign>(start[0]).tasks, first);
  EXPECT_EQ(std::get<Assign>(start[1]).tasks, second);
  const Decisions more = strategy.onRequest(0);
  ASSERT_EQ(more.size(), 1u);
  EXPECT_EQ(std::get<Assign>(more[0]).tasks, order.takeFront(4));
}

}  // namespace
}  // namespace prt
