#include "image/image_compare.h"

#include <gtest/gtest.h>

#include <cmath>

#include "core/input_error.h"
#include "image/srgb.h"

namespace prt {
namespace {

// A colour whose 8-bit sRGB encoding is exactly (r, g, b).
Color codes(int r, int g, int b) {
  return {srgb8ToLinear(static_cast<uint8_t>(r)), srgb8ToLinear(static_cast<uint8_t>(g)),
          srgb8ToLinear(static_cast<uint8_t>(b))};
}

TEST(ImageCompareTest, IdenticalImagesHaveInfinitePsnr) {
  Image a(3, 2);
  a.set(1, 1, Color(0.3, 0.6, 0.9));
  EXPECT_TRUE(std::isinf(psnr(a, a)));
  EXPECT_GT(psnr(a, a), 0.0);
  EXPECT_EQ(differingPixelFraction(a, a, 0), 0.0);
}

TEST(ImageCompareTest, PsnrMatchesAHandComputation) {
  Image a(2, 1);
  Image b(2, 1);
  a.set(0, 0, codes(100, 50, 0));
  b.set(0, 0, codes(110, 50, 0));  // one sample off by 10 codes
  a.set(1, 0, codes(0, 0, 255));
  b.set(1, 0, codes(0, 3, 255));  // one sample off by 3 codes
  // MSE over 6 samples = (10^2 + 3^2) / 6; PSNR = 10 log10(255^2 / MSE).
  const double expected = 10.0 * std::log10(255.0 * 255.0 * 6.0 / 109.0);
  EXPECT_NEAR(psnr(a, b), expected, 1e-12);
  EXPECT_NEAR(psnr(a, b), 35.5381, 1e-4);
  EXPECT_EQ(psnr(a, b), psnr(b, a));
}

TEST(ImageCompareTest, DifferencesBeyondTheEncodingDoNotCount) {
  Image a(1, 1);
  Image b(1, 1);
  a.set(0, 0, Color(1.0, -0.5, 0.2));
  b.set(0, 0, Color(5.0, 0.0, 0.2));  // brighter than white, darker than black: same codes
  EXPECT_TRUE(std::isinf(psnr(a, b)));
}

TEST(ImageCompareTest, DifferingPixelFractionUsesTheWorstChannel) {
  Image a(4, 1);
  Image b(4, 1);
  b.set(1, 0, codes(0, 0, 1));  // max channel difference 1
  b.set(2, 0, codes(2, 0, 0));  // 2
  b.set(3, 0, codes(0, 5, 1));  // 5
  EXPECT_DOUBLE_EQ(differingPixelFraction(a, b, 0), 0.75);
  EXPECT_DOUBLE_EQ(differingPixelFraction(a, b, 1), 0.5);
  EXPECT_DOUBLE_EQ(differingPixelFraction(a, b, 2), 0.25);
  EXPECT_DOUBLE_EQ(differingPixelFraction(a, b, 5), 0.0);
}

TEST(ImageCompareTest, DifferenceImageEncodesToTheScaledCodeDifference) {
  Image a(3, 1);
  Image b(3, 1);
  a.set(0, 0, codes(10, 20, 30));
  b.set(0, 0, codes(10, 22, 25));
  b.set(1, 0, codes(200, 0, 0));
  const Image d = differenceImage(a, b, 10.0);
  EXPECT_EQ(linearToSrgb8(d.at(0, 0).x), 0);
  EXPECT_EQ(linearToSrgb8(d.at(0, 0).y), 20);
  EXPECT_EQ(linearToSrgb8(d.at(0, 0).z), 50);
  EXPECT_EQ(linearToSrgb8(d.at(1, 0).x), 255);  // 2000 clamps to white
  EXPECT_EQ(d.at(2, 0), Color(0.0));
}

TEST(ImageCompareTest, SideBySideIsAThenBThenDifference) {
  Image a(2, 2);
  Image b(2, 2);
  a.set(1, 1, Color(0.25, 0.5, 0.75));
  b.set(0, 1, Color(1.0, 1.0, 1.0));
  const Image s = sideBySide(a, b, 1.0);
  ASSERT_EQ(s.width(), 6);
  ASSERT_EQ(s.height(), 2);
  EXPECT_EQ(s.at(1, 1), a.at(1, 1));
  EXPECT_EQ(s.at(2, 1), b.at(0, 1));
  const Image d = differenceImage(a, b, 1.0);
  for (int y = 0; y < 2; ++y) {
    for (int x = 0; x < 2; ++x) {
      EXPECT_EQ(s.at(x, y), a.at(x, y));
      EXPECT_EQ(s.at(2 + x, y), b.at(x, y));
      EXPECT_EQ(s.at(4 + x, y), d.at(x, y));
    }
  }
}

TEST(ImageCompareTest, DifferentSizesAreAnInputError) {
  EXPECT_THROW(psnr(Image(2, 2), Image(2, 3)), InputError);
  EXPECT_THROW(differingPixelFraction(Image(2, 2), Image(4, 1), 0), InputError);
  EXPECT_THROW(sideBySide(Image(1, 1), Image(2, 1)), InputError);
}

}  // namespace
}  // namespace prt
