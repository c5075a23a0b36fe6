#include "balance/self_scheduling.h"

#include <gtest/gtest.h>

#include "balance/assign_testing.h"
#include "core/input_error.h"

namespace prt {
namespace {

using testing_support::assignRange;

TEST(SelfSchedulingTest, FixedChunksFromTheFront) {
  SelfSchedulingStrategy s(10);
  EXPECT_EQ(s.name(), "self");
  EXPECT_EQ(s.start(StartInfo{35, {1, 5, 2}}),
            (Decisions{assignRange(0, 0, 10), assignRange(1, 10, 10), assignRange(2, 20, 10)}));
  EXPECT_EQ(s.onRequest(1), (Decisions{assignRange(1, 30, 5)}));  // the last chunk is short
  EXPECT_EQ(s.onRequest(0), (Decisions{NoMoreWork{0}}));
}

TEST(SelfSchedulingTest, FewerTasksThanChunks) {
  SelfSchedulingStrategy s(4);
  EXPECT_EQ(s.start(StartInfo{6, {1, 1, 1}}),
            (Decisions{assignRange(0, 0, 4), assignRange(1, 4, 2)}));
  EXPECT_EQ(s.onRequest(2), (Decisions{NoMoreWork{2}}));
}

TEST(SelfSchedulingTest, LostWorkersTasksGoFirst) {
  SelfSchedulingStrategy s(3);
  s.start(StartInfo{12, {1, 1}});  // 0..2, 3..5; pool 6..11
  EXPECT_TRUE(s.onWorkerLost(1, TaskSet::range(4, 2)).empty());
  TaskSet expected = TaskSet::range(4, 2);
  expected.append(TaskSet::range(6, 1));
  EXPECT_EQ(s.onRequest(0), (Decisions{Assign{0, expected}}));
  EXPECT_EQ(s.onRequest(0), (Decisions{assignRange(0, 7, 3)}));
}

TEST(SelfSchedulingTest, RejectsZeroChunk) {
  EXPECT_THROW(SelfSchedulingStrategy(0), InputError);
}

}  // namespace
}  // namespace prt
