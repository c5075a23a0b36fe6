#include "core/portable_math.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "core/rng.h"

namespace prt {
namespace {

// |a - b| in units of the last place of b (b nonzero and normal).
double ulps(double a, double b) {
  return std::abs(a - b) / (std::nextafter(std::abs(b), HUGE_VAL) - std::abs(b));
}

// Error measured against the absolute scale of sin and cos (their largest magnitude is 1):
// near a zero of either function a relative measure means nothing.
double errorInUnitUlps(double a, double b) {
  return std::abs(a - b) / 0x1p-53;
}

TEST(PortableMathTest, SinCosQuarterMatchesTheLibraryWithinAnUlp) {
  Rng rng(1);
  for (int i = 0; i < 200000; ++i) {
    const double x = (2 * rng.uniform() - 1) * std::numbers::pi / 4;
    double s, c;
    sinCosQuarter(x, s, c);
    ASSERT_LE(ulps(s, std::sin(x)), 1.0) << x;
    ASSERT_LE(ulps(c, std::cos(x)), 1.0) << x;
  }
  double s, c;
  sinCosQuarter(0.0, s, c);
  EXPECT_EQ(s, 0.0);
  EXPECT_EQ(c, 1.0);
}

TEST(PortableMathTest, SinCosTurnsCoversTheCircle) {
  Rng rng(2);
  for (int i = 0; i < 200000; ++i) {
    const double u = rng.uniform();
    double s, c;
    sinCosTurns(u, s, c);
    const double phi = 2 * std::numbers::pi * u;
    // The reference's own argument 2 pi u is rounded, by up to 4 units near 2 pi.
    ASSERT_LE(errorInUnitUlps(s, std::sin(phi)), 8.0) << u;
    ASSERT_LE(errorInUnitUlps(c, std::cos(phi)), 8.0) << u;
  }
  // The quarter turns land exactly on the axes.
  const double expected[4][2] = {{0, 1}, {1, 0}, {0, -1}, {-1, 0}};
  for (int k = 0; k < 4; ++k) {
    double s, c;
    sinCosTurns(0.25 * k, s, c);
    EXPECT_EQ(s, expected[k][0]) << k;
    EXPECT_EQ(c, expected[k][1]) << k;
  }
}

TEST(PortableMathTest, SinCosRadiansReducesLargeAngles) {
  Rng rng(3);
  for (int i = 0; i < 200000; ++i) {
    const double x = (2 * rng.uniform() - 1) * (i % 2 == 0 ? 7.0 : 1000.0);
    double s, c;
    sinCosRadians(x, s, c);
    ASSERT_LE(errorInUnitUlps(s, std::sin(x)), 8.0) << x;
    ASSERT_LE(errorInUnitUlps(c, std::cos(x)), 8.0) << x;
  }
  EXPECT_LE(ulps(tanRadians(std::numbers::pi / 4), 1.0), 2.0);
  EXPECT_LE(ulps(tanRadians(0.3), std::tan(0.3)), 4.0);
  EXPECT_LE(ulps(cosRadians(std::numbers::pi / 3), 0.5), 4.0);
}

TEST(PortableMathTest, LogAndExpMatchTheLibrary) {
  Rng rng(4);
  for (int i = 0; i < 200000; ++i) {
    const double x = std::ldexp(0.5 + rng.uniform(), static_cast<int>(rng.uniform() * 200) - 100);
    const double ln = std::log(x);
    // Absolute error near ln x = 0, relative elsewhere.
    ASSERT_LE(std::abs(logPositive(x) - ln), 4 * 0x1p-53 * std::max(1.0, std::abs(ln))) << x;
    const double y = (2 * rng.uniform() - 1) * 700;
    ASSERT_LE(ulps(expOf(y), std::exp(y)), 4.0) << y;
  }
  EXPECT_EQ(logPositive(1.0), 0.0);
  EXPECT_EQ(logPositive(0.0), -HUGE_VAL);
  EXPECT_TRUE(std::isnan(logPositive(-1.0)));
  EXPECT_EQ(expOf(0.0), 1.0);
  EXPECT_EQ(expOf(-800.0), 0.0);
  EXPECT_EQ(expOf(800.0), HUGE_VAL);
  EXPECT_TRUE(std::isnan(expOf(std::numeric_limits<double>::quiet_NaN())));
  EXPECT_GT(expOf(-740.0), 0.0);  // subnormal results survive
}

TEST(PortableMathTest, PowerOfTheKindsPhongUses) {
  Rng rng(5);
  for (int i = 0; i < 100000; ++i) {
    const double x = rng.uniform();
    const double whole = std::floor(1 + rng.uniform() * 1000);
    const double fractional = 1 + rng.uniform() * 1000;
    const double a = std::pow(x, whole), b = std::pow(x, fractional);
    // Squaring doubles a relative error: about n units in the last place for a whole n.
    if (a > 1e-300) {
      ASSERT_LE(std::abs(powNonNegative(x, whole) - a), 2 * whole * 0x1p-53 * a)
          << x << " " << whole;
    }
    if (b > 1e-300) {
      ASSERT_LE(std::abs(powNonNegative(x, fractional) - b), 1e-12 * b) << x << " " << fractional;
    }
  }
  EXPECT_EQ(powNonNegative(0.0, 3.0), 0.0);
  EXPECT_EQ(powNonNegative(1.0, 250.0), 1.0);
  EXPECT_EQ(powNonNegative(0.5, 3.0), 0.125);
  EXPECT_EQ(powNonNegative(0.9, 1.0), 0.9);
  EXPECT_EQ(powNonNegative(0.5, 2000.0), 0.0);  // underflows as the library's does
}

}  // namespace
TEST(PortableMathTest, ArcTangentsMatchTheLibraryWithinTwoUlps) {
  double worst = 0;
  for (int i = -20000; i <= 20000; ++i) {
    const double x = std::ldexp(static_cast<double>(i), -9) * (1 + 1e-7 * (i % 7));
    worst = std::max(worst, ulps(atanOf(x), std::atan(x)));
    for (const double scale : {1e-3, 1.0, 7.0, 1e6}) {
      const double y = std::sin(0.37 * i) * scale, x2 = std::cos(0.53 * i) * scale;
      worst = std::max(worst, ulps(atan2Of(y, x2), std::atan2(y, x2)));
    }
  }
  EXPECT_LE(worst, 2.0);
  EXPECT_EQ(atan2Of(0, -1), std::numbers::pi);
  EXPECT_EQ(atan2Of(0, 0), 0.0);
  EXPECT_EQ(atan2Of(1, 0), std::numbers::pi / 2);
  EXPECT_EQ(atan2Of(-1, 0), -std::numbers::pi / 2);
  EXPECT_TRUE(std::isnan(atanOf(std::nan(""))));
  EXPECT_EQ(atanOf(INFINITY), std::numbers::pi / 2);
}

}  // namespace prt
