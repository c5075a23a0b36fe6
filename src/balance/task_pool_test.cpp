#include "balance/task_pool.h"

#include <gtest/gtest.h>

#include <random>

#include "balance/interleaved_order.h"

namespace prt {
namespace {

// The pool hands out exactly what a TaskSet taken from the front would, with tasks put back
// at the front in between.
TEST(TaskPoolTest, TakesAndPutsBackAsATaskSetWould) {
  const TaskSet all = interleavedOrder(5000, 0);
  TaskPool pool(all);
  TaskSet reference = all;
  std::mt19937_64 random(3);
  std::vector<TaskSet> given;
  while (!reference.empty()) {
    ASSERT_EQ(pool.size(), reference.size());
    if (!given.empty() && random() % 5 == 0) {  // a lost worker's tasks come back first
      TaskSet back = given.back();
      given.pop_back();
      pool.putFront(back);
      back.append(reference);
      reference = back;
      continue;
    }
    const uint64_t n = 1 + random() % 300;
    const TaskSet a = pool.takeFront(n);
    const TaskSet b = reference.takeFront(n);
    ASSERT_EQ(a, b);
    given.push_back(a);
  }
  EXPECT_TRUE(pool.empty());
  EXPECT_TRUE(pool.takeFront(10).empty());
}

}  // namespace
}  // namespace prt
