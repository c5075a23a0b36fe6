#include "core/task_set.h"

#include <gtest/gtest.h>

#include <numeric>

namespace prt {
namespace {

TEST(TaskSetTest, RangeAndStrided) {
  EXPECT_EQ(TaskSet::range(5, 3).toVector(), (std::vector<uint64_t>{5, 6, 7}));
  EXPECT_EQ(TaskSet::strided(1, 4, 3).toVector(), (std::vector<uint64_t>{1, 4, 7, 10}));
  EXPECT_TRUE(TaskSet::range(0, 0).empty());
}

TEST(TaskSetTest, AppendMergesContiguousRuns) {
  TaskSet s = TaskSet::range(0, 10);
  s.append(TaskSet::range(10, 5));
  EXPECT_EQ(s.runs().size(), 1u);
  EXPECT_EQ(s.size(), 15u);
  s.append(TaskSet::range(20, 1));
  EXPECT_EQ(s.runs().size(), 2u);
  s.append(TaskSet::range(21, 1));  // singleton adopts stride 1
  EXPECT_EQ(s.runs().size(), 2u);
  EXPECT_EQ(s.describe(), "{0..14, 20..21}");
}

TEST(TaskSetTest, SingletonsFormAStridedRun) {
  TaskSet s;
  for (uint64_t i = 0; i < 5; ++i) s.append(TaskRun{3 + 4 * i, 1, 1});
  EXPECT_EQ(s.runs().size(), 1u);
  EXPECT_EQ(s.runs()[0].stride, 4u);
}

TEST(TaskSetTest, TakeFrontSplitsRuns) {
  TaskSet s = TaskSet::range(0, 10);
  s.append(TaskSet::strided(20, 5, 2));
  TaskSet front = s.takeFront(12);
  EXPECT_EQ(front.toVector(), (std::vector<uint64_t>{0, 1, 2, 3, 4, 5, 6, 7, 8, 9, 20, 22}));
  EXPECT_EQ(s.toVector(), (std::vector<uint64_t>{24, 26, 28}));
  EXPECT_EQ(s.takeFront(100).size(), 3u);
  EXPECT_TRUE(s.empty());
}

TEST(TaskSetTest, TakeBackSplitsRunsAndKeepsOrder) {
  TaskSet s = TaskSet::range(0, 4);
  s.append(TaskSet::strided(10, 3, 5));
  TaskSet back = s.takeBack(4);
  EXPECT_EQ(back.toVector(), (std::vector<uint64_t>{3, 10, 15, 20}));
  EXPECT_EQ(s.toVector(), (std::vector<uint64_t>{0, 1, 2}));
}

TEST(TaskSetTest, AtMatchesToVector) {
  TaskSet s = TaskSet::strided(7, 9, 3);
  s.append(TaskSet::range(100, 4));
  const auto v = s.toVector();
  for (uint64_t i = 0; i < s.size(); ++i) EXPECT_EQ(s.at(i), v[i]);
}

TEST(TaskSetTest, SplittingAndRejoiningPreservesEveryTask) {
  TaskSet all = TaskSet::strided(0, 1000, 1);
  TaskSet rebuilt;
  uint64_t n = 1;
  while (!all.empty()) {
    rebuilt.append(all.takeFront(n));
    n = n * 2 + 1;
  }
  EXPECT_EQ(rebuilt, TaskSet::range(0, 1000));
}

}  // namespace
}  // namespace prt
