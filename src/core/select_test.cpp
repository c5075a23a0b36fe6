#include "core/select.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

namespace prt {
namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

// Each select must give exactly what its ternary gives, NaN and signed zeros included: the
// traversal's interval arithmetic depends on a NaN leaving the interval alone.
TEST(SelectTest, MatchesTheTernaryItIsNamedAfter) {
  const double values[] = {-1.5, -0.0, 0.0, 2.0, kNaN, HUGE_VAL, -HUGE_VAL};
  for (double a : values) {
    for (double b : values) {
      const double less = a < b ? a : b, greater = a > b ? a : b;
      EXPECT_EQ(std::signbit(lessOr(a, b)), std::signbit(less)) << a << " " << b;
      EXPECT_EQ(std::signbit(greaterOr(a, b)), std::signbit(greater)) << a << " " << b;
      if (std::isnan(less)) {
        EXPECT_TRUE(std::isnan(lessOr(a, b)));
      } else {
        EXPECT_EQ(lessOr(a, b), less);
      }
      if (std::isnan(greater)) {
        EXPECT_TRUE(std::isnan(greaterOr(a, b)));
      } else {
        EXPECT_EQ(greaterOr(a, b), greater);
      }
    }
  }
  EXPECT_EQ(lessOr(kNaN, 1.0), 1.0);  // a comparison with NaN is false: the second argument
  EXPECT_TRUE(std::isnan(greaterOr(1.0, kNaN)));
}

TEST(SelectTest, SelectBits) {
  EXPECT_EQ(selectBits(true, 7u, 9u), 7u);
  EXPECT_EQ(selectBits(false, 7u, 9u), 9u);
  EXPECT_EQ(selectBits(true, 0xffffffffu, 0u), 0xffffffffu);
  EXPECT_EQ(selectBits(false, 0xffffffffu, 0u), 0u);
}

}  // namespace
}  // namespace prt
