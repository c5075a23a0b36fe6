#include "balance/blocks.h"

#include <gtest/gtest.h>

namespace prt {
namespace {

TEST(BlocksTest, EqualContiguousBlocksLargerFirst) {
  BlocksStrategy s;
  EXPECT_EQ(s.name(), "blocks");
  EXPECT_EQ(s.start(StartInfo{10, {1, 2, 3}}),
            (Decisions{Assign{0, TaskSet::range(0, 4)}, Assign{1, TaskSet::range(4, 3)},
                       Assign{2, TaskSet::range(7, 3)}}));
  EXPECT_EQ(s.onRequest(0), (Decisions{NoMoreWork{0}}));
}

TEST(BlocksTest, MoreWorkersThanTasks) {
  BlocksStrategy s;
  EXPECT_EQ(s.start(StartInfo{2, {1, 1, 1}}),
            (Decisions{Assign{0, TaskSet::range(0, 1)}, Assign{1, TaskSet::range(1, 1)}}));
}

TEST(BlocksTest, LostWorkersBlockIsSplitOverTheLiveOnes) {
  BlocksStrategy s;
  s.start(StartInfo{12, {1, 1, 1, 1}});
  EXPECT_EQ(s.onWorkerLost(2, TaskSet::range(7, 2)),
            (Decisions{Assign{0, TaskSet::range(7, 1)}, Assign{1, TaskSet::range(8, 1)}}));
}

}  // namespace
}  // namespace prt
