#include "balance/scatter.h"

#include <gtest/gtest.h>

namespace prt {
namespace {

TEST(ScatterTest, TaskIGoesToWorkerIModC) {
  ScatterStrategy s;
  EXPECT_EQ(s.name(), "scatter");
  EXPECT_EQ(s.start(StartInfo{10, {1, 1, 1}}),
            (Decisions{Assign{0, TaskSet::strided(0, 4, 3)}, Assign{1, TaskSet::strided(1, 3, 3)},
                       Assign{2, TaskSet::strided(2, 3, 3)}}));
  EXPECT_EQ(s.onRequest(1), (Decisions{NoMoreWork{1}}));
}

TEST(ScatterTest, PaperFigureOneRowOfAHundredPixels) {
  // Three computers, 100 pixels a row. 1-based, as the paper counts: the 1st, 4th, 103rd and
  // 106th pixels go to the first; the 2nd, 5th, 101st and 104th to the second; the 3rd, 6th,
  // 102nd and 105th to the third.
  const std::vector<TaskSet> shares = scatterShares(200, 3);
  EXPECT_EQ(
      (std::vector<uint64_t>{shares[0].at(0), shares[0].at(1), shares[0].at(34), shares[0].at(35)}),
      (std::vector<uint64_t>{0, 3, 102, 105}));
  EXPECT_EQ(
      (std::vector<uint64_t>{shares[1].at(0), shares[1].at(1), shares[1].at(33), shares[1].at(34)}),
      (std::vector<uint64_t>{1, 4, 100, 103}));
  EXPECT_EQ(
      (std::vector<uint64_t>{shares[2].at(0), shares[2].at(1), shares[2].at(33), shares[2].at(34)}),
      (std::vector<uint64_t>{2, 5, 101, 104}));
}

TEST(ScatterTest, MoreWorkersThanTasks) {
  ScatterStrategy s;
  EXPECT_EQ(s.start(StartInfo{2, {1, 1, 1, 1}}),
            (Decisions{Assign{0, TaskSet::range(0, 1)}, Assign{1, TaskSet::range(1, 1)}}));
}

TEST(ScatterTest, LostWorkersTasksAreSplitOverTheLiveOnes) {
  ScatterStrategy s;
  s.start(StartInfo{30, {1, 1, 1}});
  // Worker 1 held 1, 4, ..., 28 and rendered the first four.
  const TaskSet unfinished = TaskSet::strided(13, 6, 3);  // 13, 16, ..., 28
  EXPECT_EQ(s.onWorkerLost(1, unfinished), (Decisions{Assign{0, TaskSet::strided(13, 3, 3)},
                                                      Assign{2, TaskSet::strided(22, 3, 3)}}));
  EXPECT_EQ(s.onRequest(1), (Decisions{NoMoreWork{1}}));
  EXPECT_TRUE(s.onWorkerLost(0, TaskSet()).empty());
}

}  // namespace
}  // namespace prt
