#include "balance/reservoir_math.h"

#include <gtest/gtest.h>

#include <numeric>

namespace prt {
namespace {

// The paper's Table I, with its two swapped rows put right: speeds (1, 3, 12, 7).
const std::vector<double> kTableOneSpeeds = {1, 3, 12, 7};

TEST(ReservoirMathTest, TableOneDivisionOfLabor) {
  const std::vector<double> div = divisionOfLabor(kTableOneSpeeds);
  ASSERT_EQ(div.size(), 4u);
  EXPECT_NEAR(div[0] * 100, 64.12, 0.005);
  EXPECT_NEAR(div[1] * 100, 21.37, 0.005);
  EXPECT_NEAR(div[2] * 100, 5.34, 0.005);  // the slowest (speed 12), printed as 9.16 %
  EXPECT_NEAR(div[3] * 100, 9.16, 0.005);  // speed 7, printed as 5.34 %
  EXPECT_NEAR(std::accumulate(div.begin(), div.end(), 0.0), 1.0, 1e-12);
  // ratio = slowest / speed = (12, 4, 1, 1.714), sum 18.714
  EXPECT_DOUBLE_EQ(div[0], 12.0 / (12 + 4 + 1 + 12.0 / 7));
}

TEST(ReservoirMathTest, TableOneHandOutOfAHundredTasks) {
  const std::vector<double> div = divisionOfLabor(kTableOneSpeeds);
  EXPECT_EQ(reservoirHandout(div[0], 100), 65u);  // the paper's 65 tasks for worker 1
  // The rounded-up percentages in brackets: 22 %, 6 %, 10 %.
  EXPECT_EQ(reservoirHandout(div[1], 100), 22u);
  EXPECT_EQ(reservoirHandout(div[2], 100), 6u);
  EXPECT_EQ(reservoirHandout(div[3], 100), 10u);
}

TEST(ReservoirMathTest, SlowestIsTheLargestSpeedIndex) {
  // Lower speed index = faster = larger share, whatever the order.
  const std::vector<double> div = divisionOfLabor({4, 1, 2});
  EXPECT_DOUBLE_EQ(div[0], 1.0 / 7);
  EXPECT_DOUBLE_EQ(div[1], 4.0 / 7);
  EXPECT_DOUBLE_EQ(div[2], 2.0 / 7);
  EXPECT_EQ(divisionOfLabor({5, 5, 5, 5}), (std::vector<double>{0.25, 0.25, 0.25, 0.25}));
}

TEST(ReservoirMathTest, InitialDistributionOfTwentyTasks) {
  // Table I's workers, n = 20, p = 80 %: limit 16, blocks ceil(16 * div) = 11, 4, 1, 2; the
  // running total reaches 16 after the third block, so the fourth is clamped to 0.
  const std::vector<double> div = divisionOfLabor(kTableOneSpeeds);
  EXPECT_EQ(initialLimit(80, 20), 16u);
  EXPECT_EQ(initialBlockSizes(div, 16), (std::vector<uint64_t>{11, 4, 1, 0}));
}

TEST(ReservoirMathTest, InitialLimitRoundsUpAndStaysInRange) {
  EXPECT_EQ(initialLimit(80, 100), 80u);
  EXPECT_EQ(initialLimit(80, 7), 6u);  // 5.6 -> 6
  EXPECT_EQ(initialLimit(1, 7), 1u);   // 0.07 -> 1
  EXPECT_EQ(initialLimit(100, 7), 7u);
  EXPECT_EQ(initialLimit(33.3, 1000), 333u);
  EXPECT_EQ(initialLimit(80, 0), 0u);
}

TEST(ReservoirMathTest, BlocksSumToTheLimitAndNeverOverrun) {
  for (uint64_t limit : {0u, 1u, 2u, 3u, 10u, 99u, 1000u, 2457u}) {
    for (const std::vector<double>& speeds :
         {std::vector<double>{1}, {1, 1, 1}, {1, 3, 12, 7}, {2, 2, 2, 2, 2, 2, 2}}) {
      const std::vector<uint64_t> blocks = initialBlockSizes(divisionOfLabor(speeds), limit);
      EXPECT_EQ(std::accumulate(blocks.begin(), blocks.end(), uint64_t{0}), limit);
    }
  }
}

TEST(ReservoirMathTest, ExactProductsAreNotRoundedUpByNoise) {
  // 0.07 * 100 is 7.000000000000001 in doubles; a plain ceil would give 8.
  EXPECT_EQ(ceilCount(0.07 * 100), 7u);
  EXPECT_EQ(ceilCount(7.0001), 8u);
  EXPECT_EQ(ceilCount(0.0), 0u);
  EXPECT_EQ(ceilCount(-3.0), 0u);
  // Speeds (1, 2, 3, 4) divide labour 48 %, 24 %, 16 %, 12 %; 25 tasks split exactly into
  // 12, 6, 4, 3, but 25 * 0.48 comes out as 12.000000000000002 (a plain ceil would give
  // 13, 7, 4, 1). Likewise 48 of a 100-task reservoir, not 49.
  const std::vector<double> div = divisionOfLabor({1, 2, 3, 4});
  EXPECT_EQ(initialBlockSizes(div, 25), (std::vector<uint64_t>{12, 6, 4, 3}));
  EXPECT_EQ(reservoirHandout(div[0], 100), 48u);
  // Three equal workers and 99 tasks: 33 each, none left over.
  EXPECT_EQ(initialBlockSizes(divisionOfLabor({1, 1, 1}), 99), (std::vector<uint64_t>{33, 33, 33}));
}

TEST(ReservoirMathTest, HandOutIsAtLeastOneAndAtMostWhatIsLeft) {
  EXPECT_EQ(reservoirHandout(0.01, 5), 1u);  // 0.05 -> 1
  EXPECT_EQ(reservoirHandout(1.0, 5), 5u);
  EXPECT_EQ(reservoirHandout(0.5, 0), 0u);
  EXPECT_EQ(reservoirHandout(4.0 / 7, 20), 12u);  // 11.43 -> 12
}

}  // namespace
}  // namespace prt
