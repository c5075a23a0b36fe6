#include "balance/throughput.h"

#include <gtest/gtest.h>

namespace prt {
namespace {

TEST(ThroughputTest, HeldFollowsHandOutsTransfersAndResults) {
  Throughput t;
  t.reset(2);
  t.given(0, 100);
  t.moved(0, 1, 30);
  EXPECT_EQ(t.held(0), 70u);
  EXPECT_EQ(t.held(1), 30u);
  t.returned(0, 20, 2.0);
  EXPECT_EQ(t.held(0), 50u);
  t.moved(1, 0, 500);  // more than it holds: only what it holds
  EXPECT_EQ(t.held(0), 80u);
  EXPECT_EQ(t.held(1), 0u);
  t.chunkDone(0);
  EXPECT_EQ(t.held(0), 0u);
}

TEST(ThroughputTest, RateFollowsRecentResults) {
  Throughput t;
  t.reset(1);
  EXPECT_FALSE(t.measured(0));
  EXPECT_EQ(t.rate(0), 0.0);
  t.returned(0, 10, 0.0);  // unmeasured: learns nothing
  EXPECT_FALSE(t.measured(0));
  for (int i = 0; i < 5; ++i) t.returned(0, 100, 1.0);
  EXPECT_DOUBLE_EQ(t.rate(0), 100.0);
  for (int i = 0; i < 20; ++i) t.returned(0, 100, 4.0);  // four times slower
  EXPECT_NEAR(t.rate(0), 25.0, 0.1);
  EXPECT_NEAR(t.meanTaskSeconds(0), (5 * 1.0 + 20 * 4.0) / 2500, 1e-12);
}

TEST(ThroughputTest, VarianceOfTaskTimesFromBatchMeans) {
  Throughput t;
  t.reset(1);
  t.returned(0, 1, 1.0);
  EXPECT_EQ(t.taskSecondsVariance(0), 0.0);  // one sample
  t.returned(0, 1, 3.0);
  t.returned(0, 1, 2.0);
  EXPECT_DOUBLE_EQ(t.meanTaskSeconds(0), 2.0);
  EXPECT_DOUBLE_EQ(t.taskSecondsVariance(0), 1.0);  // samples 1, 3, 2
}

TEST(ThroughputTest, WeightedAverageCountsLaterChunksMore) {
  // DLS4LB: chunk k weighs k; the chunk in progress weighs one more than the last closed.
  Throughput t;
  t.reset(1);
  t.returned(0, 10, 10.0);  // 1 s per task
  t.chunkDone(0);
  t.returned(0, 10, 40.0);  // 4 s per task, in progress: weight 2
  EXPECT_DOUBLE_EQ(t.weightedAverageTaskSeconds(0), (10.0 + 2 * 40.0) / (10 + 2 * 10));
  t.chunkDone(0);
  t.returned(0, 10, 10.0);  // weight 3
  EXPECT_DOUBLE_EQ(t.weightedAverageTaskSeconds(0),
                   (10.0 + 2 * 40.0 + 3 * 10.0) / (10 + 20 + 30));
}

}  // namespace
}  // namespace prt
