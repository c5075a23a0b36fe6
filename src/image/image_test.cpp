#include "image/image.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "image/srgb.h"

namespace prt {
namespace {

TEST(ImageTest, StartsBlack) {
  const Image image(4, 3);
  EXPECT_EQ(image.width(), 4);
  EXPECT_EQ(image.height(), 3);
  EXPECT_EQ(image.pixelCount(), 12u);
  EXPECT_EQ(image.data().size(), 36u);
  for (float s : image.data()) EXPECT_EQ(s, 0.0f);
}

TEST(ImageTest, SetByCoordinatesAndByIndexAgree) {
  Image image(4, 3);
  image.set(1, 2, Color(0.25, 0.5, 2.0));
  EXPECT_EQ(image.at(1, 2), Color(0.25, 0.5, 2.0));
  EXPECT_EQ(image.pixelIndex(1, 2), 9u);
  EXPECT_EQ(image.at(size_t{9}), Color(0.25, 0.5, 2.0));
  image.set(size_t{11}, Color(1, 2, 3));
  EXPECT_EQ(image.at(3, 2), Color(1, 2, 3));
  // Row-major, row 0 at the top, RGB interleaved.
  EXPECT_EQ(image.data()[3 * 11 + 2], 3.0f);
}

TEST(ImageTest, StoresFloatPrecision) {
  Image image(1, 1);
  image.set(0, 0, Color(0.1, 1e-50, 1e300));
  EXPECT_EQ(image.at(0, 0).x, static_cast<double>(0.1f));
  EXPECT_EQ(image.at(0, 0).y, 0.0);
  EXPECT_TRUE(std::isinf(image.at(0, 0).z));
}

TEST(ImageTest, EqualityIsBitExact) {
  Image a(2, 2);
  Image b(2, 2);
  EXPECT_EQ(a, b);
  EXPECT_NE(a, Image(4, 1));  // same pixel count, different shape
  b.set(1, 1, Color(-0.0, 0, 0));
  EXPECT_NE(a, b);  // -0 and +0 compare equal as floats, but not as bits
  const double nan = std::numeric_limits<double>::quiet_NaN();
  a.set(0, 0, Color(nan, 0, 0));
  Image c = a;
  EXPECT_EQ(a, c);  // NaN != NaN as floats, but the bits match
}

TEST(ImageDeathTest, EmptySizeIsABug) {
  GTEST_FLAG_SET(death_test_style, "threadsafe");
  EXPECT_DEATH(Image(0, 5), "check failed");
  EXPECT_DEATH(Image(5, -1), "check failed");
}

TEST(ImageSrgbTest, KnownValues) {
  EXPECT_EQ(linearToSrgb8(0.0), 0);
  EXPECT_EQ(linearToSrgb8(1.0), 255);
  EXPECT_EQ(linearToSrgb8(0.5), 188);            // 1.055 * 0.5^(1/2.4) - 0.055 = 0.7354 -> 187.5
  EXPECT_EQ(linearToSrgb8(0.18), 118);           // "middle grey"
  EXPECT_DOUBLE_EQ(srgbEncode(0.001), 0.01292);  // linear segment
  EXPECT_NEAR(srgbEncode(0.0031308), 0.04045, 1e-6);  // the two segments meet
  EXPECT_DOUBLE_EQ(srgb8ToLinear(0), 0.0);
  EXPECT_DOUBLE_EQ(srgb8ToLinear(255), 1.0);
}

TEST(ImageSrgbTest, ClampsOutOfRangeAndNaN) {
  EXPECT_EQ(linearToSrgb8(-3.0), 0);
  EXPECT_EQ(linearToSrgb8(7.0), 255);
  EXPECT_EQ(linearToSrgb8(std::numeric_limits<double>::infinity()), 255);
  EXPECT_EQ(linearToSrgb8(std::numeric_limits<double>::quiet_NaN()), 0);
}

TEST(ImageSrgbTest, EveryCodeSurvivesDecodeAndFloatStorage) {
  for (int c = 0; c < 256; ++c) {
    const auto code = static_cast<uint8_t>(c);
    EXPECT_EQ(linearToSrgb8(srgb8ToLinear(code)), code);
    EXPECT_EQ(linearToSrgb8(static_cast<float>(srgb8ToLinear(code))), code);
    EXPECT_NEAR(srgbEncode(srgbDecode(c / 255.0)), c / 255.0, 1e-12);
    if (c > 0) {
      EXPECT_GT(srgb8ToLinear(code), srgb8ToLinear(static_cast<uint8_t>(c - 1)));
    }
  }
}

}  // namespace
}  // namespace prt
