#include "cluster/task_map.h"

#include <gtest/gtest.h>

namespace prt {
namespace {

TEST(TaskMapTest, IdentityWithoutDonePixels) {
  const TaskMap map(100);
  EXPECT_TRUE(map.isIdentity());
  EXPECT_EQ(map.taskCount(), 100u);
  EXPECT_EQ(map.toPixels(TaskSet::strided(3, 10, 7)), TaskSet::strided(3, 10, 7));
}

TEST(TaskMapTest, TasksAreTheMissingPixelsInOrder) {
  TaskSet done = TaskSet::range(0, 3);      // 0 1 2
  done.append(TaskSet::range(5, 2));        // 5 6
  done.append(TaskSet::strided(10, 3, 2));  // 10 12 14
  const TaskMap map(16, done);
  EXPECT_FALSE(map.isIdentity());
  // Missing: 3 4 7 8 9 11 13 15
  EXPECT_EQ(map.taskCount(), 8u);
  EXPECT_EQ(map.toPixels(TaskSet::range(0, 8)).toVector(),
            (std::vector<uint64_t>{3, 4, 7, 8, 9, 11, 13, 15}));
  EXPECT_EQ(map.toPixels(TaskSet::strided(1, 3, 3)).toVector(),
            (std::vector<uint64_t>{4, 9, 15}));
  EXPECT_EQ(map.toTasks(map.toPixels(TaskSet::range(2, 5))), TaskSet::range(2, 5));
}

TEST(TaskMapTest, EverythingDoneLeavesNoTasks) {
  const TaskMap map(5, TaskSet::range(0, 5));
  EXPECT_FALSE(map.isIdentity());
  EXPECT_EQ(map.taskCount(), 0u);
}

}  // namespace
}  // namespace prt
