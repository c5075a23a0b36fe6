#include "export/box_blur.h"

#include <gtest/gtest.h>

namespace prt {
namespace {

TEST(BoxBlur, RadiusZeroIsACopy) {
  Image image(3, 2);
  image.set(1, 1, Color(0.5, 0.25, 1));
  EXPECT_EQ(boxBlur(image, 0), image);
}

TEST(BoxBlur, ConstantImageStaysConstant) {
  Image image(7, 5);
  for (int y = 0; y < 5; ++y) {
    for (int x = 0; x < 7; ++x) image.set(x, y, Color(0.2, 0.4, 0.6));
  }
  const Image blurred = boxBlur(image, 2);
  for (int y = 0; y < 5; ++y) {
    for (int x = 0; x < 7; ++x) {
      EXPECT_NEAR(blurred.at(x, y).x, 0.2, 1e-6);
      EXPECT_NEAR(blurred.at(x, y).z, 0.6, 1e-6);
    }
  }
}

TEST(BoxBlur, SpreadsOverTheWindowAndClipsAtBorders) {
  Image image(9, 9);
  image.set(4, 4, Color(9, 9, 9));
  const Image blurred = boxBlur(image, 1);
  EXPECT_NEAR(blurred.at(4, 4).x, 1.0, 1e-6);  // 9 / 3x3
  EXPECT_NEAR(blurred.at(3, 5).y, 1.0, 1e-6);
  EXPECT_NEAR(blurred.at(2, 4).x, 0.0, 1e-6);

  Image corner(4, 4);
  corner.set(0, 0, Color(4, 4, 4));
  // The corner's window holds only 2x2 pixels.
  EXPECT_NEAR(boxBlur(corner, 1).at(0, 0).x, 1.0, 1e-6);
}

}  // namespace
}  // namespace prt
