#include "metrics/remaining_cost.h"

#include <gtest/gtest.h>

#include <limits>

namespace prt {
namespace {

// A 32x32 image whose top half costs 1 ms a pixel and bottom half 9 ms, rendered top to
// bottom at one busy worker: the pixel count says a quarter is a quarter, the cost says not.
TEST(RemainingCost, TopToBottomRenderIsEstimatedFromTheCellsCost) {
  RemainingCost cost(32, 32);
  EXPECT_FALSE(cost.etaSeconds(0));
  double now = 0;
  // Every other row of the whole image first, one row per batch (a stratified first pass),
  // then the rest: the estimate after the first pass knows both halves.
  for (int y = 0; y < 32; y += 2) {
    const double seconds = 32 * (y < 16 ? 0.001 : 0.009);
    now += seconds;
    const TaskSet row = TaskSet::range(static_cast<uint64_t>(y) * 32, 32);
    cost.measured(row, seconds, now);
    cost.finished(row);
  }
  const double truth = 8 * 32 * 0.001 + 8 * 32 * 0.009;  // the odd rows
  ASSERT_TRUE(cost.remainingWork());
  EXPECT_NEAR(*cost.remainingWork(), truth, 1e-9);
  ASSERT_TRUE(cost.etaSeconds(now));
  EXPECT_NEAR(*cost.etaSeconds(now), truth, 0.05 * truth);  // one worker: rate 1 s per s
  EXPECT_NEAR(*cost.doneFraction(), 0.5, 1e-9);
}

TEST(RemainingCost, UnmeasuredCellsTakeTheSameCellOfOtherFramesThenTheMean) {
  RemainingCost cost(16, 16, 2);  // 16 cells of 1x1 per side: a cell is a pixel
  // Frame 0 measured: pixel 0 cost 1 s, every other pixel 0.
  cost.measured(TaskSet::range(0, 1), 1.0, 1);
  cost.measured(TaskSet::range(1, 255), 0.0, 2);
  cost.finished(TaskSet::range(0, 256));
  // Frame 1 left: pixel 0 of it is expected to cost what pixel 0 of frame 0 did.
  EXPECT_NEAR(*cost.remainingWork(), 1.0, 1e-12);
  EXPECT_NEAR(*cost.doneFraction(), 0.5, 1e-12);
}

TEST(RemainingCost, RateFollowsTheRecentWindow) {
  RemainingCost cost(100, 100);
  // Two workers' worth for 40 s, then one (a worker lost): the rate drops to one.
  double now = 0;
  uint64_t next = 0;
  for (int step = 0; step < 80; ++step) {
    now += 1;
    const int busy = step < 40 ? 2 : 1;
    const TaskSet batch = TaskSet::range(next, 10ull * busy);
    next += 10ull * busy;
    cost.measured(batch, busy * 1.0, now);
    cost.finished(batch);
  }
  // 1,200 of 10,000 pixels done at 0.1 s each: 880 s of work left, one worker's rate.
  ASSERT_TRUE(cost.etaSeconds(now));
  EXPECT_NEAR(*cost.etaSeconds(now), 880.0, 1.0);
}

TEST(RemainingCost, NoEtaBeforeASecondOfMeasurements) {
  RemainingCost cost(10, 10);
  cost.measured(TaskSet::range(0, 10), 0.01, 5.0);
  cost.finished(TaskSet::range(0, 10));
  cost.measured(TaskSet::range(10, 10), 0.01, 5.01);
  cost.finished(TaskSet::range(10, 10));
  EXPECT_FALSE(cost.etaSeconds(5.02));  // a rate from 10 ms would say anything
  EXPECT_TRUE(cost.etaSeconds(6.1));
}

TEST(RemainingCost, FinishedIsZeroAndBadMeasurementsAreIgnored) {
  RemainingCost cost(4, 4);
  cost.measured(TaskSet::range(0, 16), -1, 1);
  cost.measured(TaskSet::range(0, 16), std::numeric_limits<double>::quiet_NaN(), 1);
  EXPECT_FALSE(cost.remainingWork());
  cost.finished(TaskSet::range(0, 16));
  EXPECT_EQ(*cost.etaSeconds(2), 0.0);
  cost.measured(TaskSet::range(1000, 5), 1, 3);  // outside the image: ignored
}

// Scan lines from the top, the bottom half 9 times dearer: without a prior the bottom is
// expected at the top's cost; with the relative costs of a probe, at its own.
TEST(RemainingCost, APriorScalesCellsNobodyMeasuredYet) {
  for (const bool withPrior : {false, true}) {
    RemainingCost cost(16, 16);  // cells of one pixel
    if (withPrior) {
      std::vector<double> prior(256, 1.0);
      for (size_t c = 128; c < 256; ++c) prior[c] = 9.0;
      cost.setPrior(prior);
    }
    cost.measured(TaskSet::range(0, 64), 64 * 0.001, 1);  // the first 4 rows
    cost.finished(TaskSet::range(0, 64));
    const double truth = 64 * 0.001 + 128 * 0.009;
    EXPECT_NEAR(*cost.remainingWork(), withPrior ? truth : 192 * 0.001, 1e-9) << withPrior;
  }
}

// Batches are taken a cell at a time: long runs across rows and cells, strided runs and
// single pixels leave the same counts and estimates (to rounding) as pixel by pixel.
TEST(RemainingCost, RunsCountAsTheirPixelsDo) {
  const int w = 37, h = 23;  // cells that do not divide the image evenly
  const uint64_t frames = 2, tasks = uint64_t{w} * h * frames;
  RemainingCost byRuns(w, h, frames), byPixels(w, h, frames);
  auto pixelByPixel = [](const TaskSet& t) {
    TaskSet single;
    t.forEach([&](uint64_t p) { single.append(TaskRun{p, 1, 1}); });
    return single;
  };
  TaskSet strided;
  strided.append(TaskRun{1200, 40, 3});
  const TaskSet batches[] = {TaskSet::range(0, 500), TaskSet::range(500, 700), strided,
                             TaskSet::range(1320, tasks - 1320 + 7)};  // 7 beyond the end
  double now = 0;
  for (const TaskSet& b : batches) {
    now += 1;
    byRuns.measured(b, 0.01 * static_cast<double>(b.size()), now);
    byPixels.measured(pixelByPixel(b), 0.01 * static_cast<double>(b.size()), now);
    byRuns.finished(b);
    byPixels.finished(pixelByPixel(b));
    EXPECT_EQ(byRuns.finishedCount(), byPixels.finishedCount());
    ASSERT_EQ(byRuns.remainingWork().has_value(), byPixels.remainingWork().has_value());
    EXPECT_NEAR(*byRuns.remainingWork(), *byPixels.remainingWork(), 1e-9);
  }
  byRuns.unfinished(TaskSet::range(100, 900));
  byPixels.unfinished(pixelByPixel(TaskSet::range(100, 900)));
  EXPECT_EQ(byRuns.finishedCount(), byPixels.finishedCount());
  EXPECT_NEAR(*byRuns.remainingWork(), *byPixels.remainingWork(), 1e-9);
}

}  // namespace
}  // namespace prt
