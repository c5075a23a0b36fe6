#include "balance/task_split.h"

#include <gtest/gtest.h>

#include "core/input_error.h"

namespace prt {
namespace {

TEST(StrategyHelpersTest, SplitEvenlyKeepsOrderAndBalance) {
  const std::vector<TaskSet> pieces = splitEvenly(TaskSet::strided(0, 7, 2), 3);
  ASSERT_EQ(pieces.size(), 3u);
  EXPECT_EQ(pieces[0].toVector(), (std::vector<uint64_t>{0, 2, 4}));
  EXPECT_EQ(pieces[1].toVector(), (std::vector<uint64_t>{6, 8}));
  EXPECT_EQ(pieces[2].toVector(), (std::vector<uint64_t>{10, 12}));
  const std::vector<TaskSet> sparse = splitEvenly(TaskSet::range(5, 2), 4);
  EXPECT_EQ(sparse[0], TaskSet::range(5, 1));
  EXPECT_EQ(sparse[1], TaskSet::range(6, 1));
  EXPECT_TRUE(sparse[2].empty() && sparse[3].empty());
}

TEST(StrategyHelpersTest, LiveWorkers) {
  LiveWorkers w;
  w.reset(4);
  w.markLost(1);
  w.markLost(9);  // unknown: ignored
  EXPECT_EQ(w.liveCount(), 3);
  EXPECT_FALSE(w.isLive(1));
  EXPECT_FALSE(w.isLive(-1));
  EXPECT_EQ(w.liveList(), (std::vector<int>{0, 2, 3}));
}

TEST(StrategyHelpersTest, SpreadSkipsLostWorkersAndEmptyPieces) {
  LiveWorkers w;
  w.reset(3);
  w.markLost(0);
  EXPECT_EQ(spreadOverLiveWorkers(TaskSet::range(0, 1), w),
            (Decisions{Assign{1, TaskSet::range(0, 1)}}));
  w.markLost(1);
  w.markLost(2);
  EXPECT_TRUE(spreadOverLiveWorkers(TaskSet::range(0, 5), w).empty());
}

TEST(StrategyHelpersTest, StartInfoValidation) {
  EXPECT_NO_THROW(validateStartInfo(StartInfo{0, {0.5}}));
  EXPECT_THROW(validateStartInfo(StartInfo{5, {}}), InputError);
  EXPECT_THROW(validateStartInfo(StartInfo{5, {1, std::numeric_limits<double>::infinity()}}),
               InputError);
}

}  // namespace
}  // namespace prt
