#include "core/speed_index.h"

#include <gtest/gtest.h>

namespace prt {
namespace {

TEST(SpeedIndexTest, HanoiIsDeterministicAndDependsOnDiscs) {
  EXPECT_EQ(solveHanoi(10), solveHanoi(10));
  EXPECT_NE(solveHanoi(10), solveHanoi(11));
  EXPECT_EQ(solveHanoi(0), 0u);
}

TEST(SpeedIndexTest, MoreDiscsTakeLonger) {
  // 2^18 vs 2^12 moves: a 64x difference in work dwarfs timer noise.
  EXPECT_GT(measureSpeedIndexSeconds(18, 1), measureSpeedIndexSeconds(12, 1));
}

}  // namespace
}  // namespace prt
