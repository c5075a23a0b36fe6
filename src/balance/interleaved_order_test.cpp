#include "balance/interleaved_order.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cstddef>
#include <vector>

namespace prt {
namespace {

TEST(InterleavedOrder, EveryTaskExactlyOnce) {
  for (uint64_t n : {0ull, 1ull, 2ull, 3ull, 40ull, 63ull, 64ull, 1000ull, 307200ull}) {
    const TaskSet order = interleavedOrder(n);
    ASSERT_EQ(order.size(), n);
    std::vector<uint64_t> tasks = order.toVector();
    std::sort(tasks.begin(), tasks.end());
    for (uint64_t i = 0; i < n; ++i) ASSERT_EQ(tasks[i], i) << n;
  }
}

TEST(InterleavedOrder, CellsArePrimeAndStrataHoldAboutThirtyTwoTasks) {
  EXPECT_EQ(interleavedCells(640 * 480), 2411u);  // 2400 rounded up to a prime
  EXPECT_EQ(interleavedStrata(640 * 480), 2411u * kCellStrata);
  EXPECT_EQ(interleavedStrata(1), 1u);
  EXPECT_EQ(interleavedStrata(5), 5u);  // two cells of 4 would be more strata than tasks
  const TaskSet order = interleavedOrder(640 * 480);
  const uint64_t strata = 2411 * kCellStrata;
  EXPECT_EQ(order.runs().size(), strata) << "one compact run per stratum";
  // The first cell: its strata side by side, then a cell far away.
  for (uint64_t k = 0; k < kCellStrata; ++k) {
    EXPECT_EQ(order.runs()[k], (TaskRun{k, 32, strata}));
  }
  const uint64_t next = order.runs()[kCellStrata].first;
  EXPECT_EQ(next % kCellStrata, 0u);
  EXPECT_GT(next, strata / 4);
}

TEST(InterleavedOrder, ShortStretchesSampleTheWholeImage) {
  // A 640x480 image: any stretch of 640 tasks (a hand-out on a large cluster) reaches from the
  // top tenth of the rows to the bottom tenth, and from the left tenth of the columns to the
  // right tenth, and its mean row and column sit near the image's centre.
  const uint64_t w = 640, h = 480;
  const std::vector<uint64_t> tasks = interleavedOrder(w * h).toVector();
  for (size_t start = 0; start + 640 <= tasks.size(); start += 4999) {
    uint64_t top = h, bottom = 0, left = w, right = 0;
    double rows = 0, columns = 0;
    for (size_t i = start; i < start + 640; ++i) {
      const uint64_t x = tasks[i] % w, y = tasks[i] / w;
      top = std::min(top, y);
      bottom = std::max(bottom, y);
      left = std::min(left, x);
      right = std::max(right, x);
      rows += static_cast<double>(y) / 640;
      columns += static_cast<double>(x) / 640;
    }
    EXPECT_LT(top, h / 10) << start;
    EXPECT_GT(bottom, h - h / 10) << start;
    EXPECT_LT(left, w / 10) << start;
    EXPECT_GT(right, w - w / 10) << start;
    EXPECT_NEAR(rows, h / 2.0, h / 10.0) << start;
    EXPECT_NEAR(columns, w / 2.0, w / 10.0) << start;
  }
}

// A resumed sequence's frames lack what the earlier run finished, each its own share: each
// frame's tasks stay together in the order (a hand-out that mixed frames would make a worker
// prepare them over and over), frames in order, every task once.
TEST(InterleavedOrder, FramesOfUnequalSizesStayApart) {
  const std::vector<uint64_t> frames = {0, 5, 3000, 7, 0, 1, 1200};
  StartInfo info{4213, {1.0}};
  info.frameTasks = 4213 / 7;
  info.frameTaskCounts = frames;
  const std::vector<uint64_t> tasks = interleavedOrder(info).toVector();
  ASSERT_EQ(tasks.size(), 4213u);
  uint64_t start = 0;
  size_t at = 0;
  for (const uint64_t count : frames) {
    std::vector<uint64_t> frame(tasks.begin() + static_cast<std::ptrdiff_t>(at),
                                tasks.begin() + static_cast<std::ptrdiff_t>(at + count));
    std::sort(frame.begin(), frame.end());
    for (uint64_t i = 0; i < count; ++i) ASSERT_EQ(frame[i], start + i) << "frame from " << start;
    start += count;
    at += count;
  }
  // Equal frames give the order of frameTasks alone.
  StartInfo equal{3000, {1.0}};
  equal.frameTasks = 1000;
  const TaskSet byCount = interleavedOrder(equal);
  equal.frameTaskCounts = {1000, 1000, 1000};
  EXPECT_EQ(interleavedOrder(equal), byCount);
}

}  // namespace
}  // namespace prt
