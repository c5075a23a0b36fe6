#include "image/srgb.h"

#include <gtest/gtest.h>

#include <bit>
#include <cmath>
#include <cstdint>
#include <limits>
#include <random>

namespace prt {
namespace {

// The table gives the curve's code for every sample: at each code's least value and the
// double below it, at every float of [0, 1) of one in 64 bit patterns, and at random doubles.
TEST(ImageSrgbTest, TheEncodingTableGivesTheCurvesCodes) {
  int boundaries = 0;
  for (double x = 0x1p-30; x < 1.0; x = std::nextafter(x, 2.0)) {
    // Walk from code to code: jump to the next code's least value by bisection, as a check
    // independent of the table's own search.
    const uint8_t c = linearToSrgb8ByCurve(x);
    ASSERT_EQ(linearToSrgb8(x), c) << x;
    ASSERT_EQ(linearToSrgb8(std::nextafter(x, 0.0)), linearToSrgb8ByCurve(std::nextafter(x, 0.0)))
        << x;
    if (c == 254) break;
    uint64_t below = std::bit_cast<uint64_t>(x), above = std::bit_cast<uint64_t>(1.0);
    while (above - below > 1) {
      const uint64_t middle = below + (above - below) / 2;
      (linearToSrgb8ByCurve(std::bit_cast<double>(middle)) > c ? above : below) = middle;
    }
    x = std::bit_cast<double>(above);
    ++boundaries;
    ASSERT_EQ(linearToSrgb8(x), linearToSrgb8ByCurve(x)) << x;
    x = std::nextafter(x, 0.0);  // the loop steps onto the boundary again
  }
  EXPECT_GE(boundaries, 250);
  for (uint32_t bits = 0; bits < std::bit_cast<uint32_t>(1.0f); bits += 64) {
    const double x = std::bit_cast<float>(bits);
    ASSERT_EQ(linearToSrgb8(x), linearToSrgb8ByCurve(x)) << x;
  }
  std::mt19937_64 random(3);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  for (int i = 0; i < 1000000; ++i) {
    const double x = unit(random);
    ASSERT_EQ(linearToSrgb8(x), linearToSrgb8ByCurve(x)) << x;
    const double dark = x * 0.01;  // the steep part of the curve
    ASSERT_EQ(linearToSrgb8(dark), linearToSrgb8ByCurve(dark)) << dark;
  }
  const double nan = std::numeric_limits<double>::quiet_NaN();
  for (const double x : {0.0, -0.0, -1.0, 1.0, 2.0, nan, std::numeric_limits<double>::infinity(),
                         std::numeric_limits<double>::denorm_min()}) {
    EXPECT_EQ(linearToSrgb8(x), linearToSrgb8ByCurve(x)) << x;
  }
}

}  // namespace
}  // namespace prt
