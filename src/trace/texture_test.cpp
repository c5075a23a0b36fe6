#include "trace/texture.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

namespace prt {
namespace {

// A 2 x 2 RGB image: black, white on top; red, blue below.
Texture quad() {
  auto image = std::make_shared<TextureImage>();
  image->width = 2;
  image->height = 2;
  image->channels = 3;
  image->texels = {0, 0, 0, 255, 255, 255, 255, 0, 0, 0, 0, 255};
  Texture t;
  t.image = image;
  return t;
}

void expectColor(const Color& a, const Color& b, double tolerance = 1e-12) {
  EXPECT_NEAR(a.x, b.x, tolerance);
  EXPECT_NEAR(a.y, b.y, tolerance);
  EXPECT_NEAR(a.z, b.z, tolerance);
}

TEST(Texture, SrgbDecodesToLinear) {
  EXPECT_EQ(srgbToLinear(0), 0.0);
  EXPECT_EQ(srgbToLinear(255), 1.0);
  EXPECT_NEAR(srgbToLinear(188), 0.5029, 1e-4);  // sRGB 188 is about half the light
  for (int i = 1; i < 256; ++i) EXPECT_GT(srgbToLinear(static_cast<uint8_t>(i)), srgbToLinear(static_cast<uint8_t>(i - 1)));
}

TEST(Texture, TexelCentresReadTheirTexel) {
  Texture t = quad();
  expectColor(sampleTexture(t, 0.25, 0.25), {0, 0, 0});
  expectColor(sampleTexture(t, 0.75, 0.25), {1, 1, 1});
  expectColor(sampleTexture(t, 0.25, 0.75), {1, 0, 0});  // v runs down the image
  expectColor(sampleTexture(t, 0.75, 0.75), {0, 0, 1});
}

TEST(Texture, BilinearBlendsInLinearLight) {
  Texture t = quad();
  // Halfway between the top two texel centres: half black, half white, in linear light.
  expectColor(sampleTexture(t, 0.5, 0.25), {0.5, 0.5, 0.5});
  // The middle of the image: the mean of all four.
  expectColor(sampleTexture(t, 0.5, 0.5), {0.5, 0.25, 0.5});
  t.nearest = true;
  expectColor(sampleTexture(t, 0.49, 0.51), {1, 0, 0});
}

TEST(Texture, WrapModesRepeatClampAndMirror) {
  Texture t = quad();
  expectColor(sampleTexture(t, 1.25, 0.25), sampleTexture(t, 0.25, 0.25));  // repeat
  expectColor(sampleTexture(t, -0.25, 0.25), {1, 1, 1});
  t.wrapU = TextureWrap::clamp;
  expectColor(sampleTexture(t, 7.0, 0.25), {1, 1, 1});
  expectColor(sampleTexture(t, -7.0, 0.25), {0, 0, 0});
  t.wrapU = TextureWrap::mirror;
  expectColor(sampleTexture(t, 1.25, 0.25), sampleTexture(t, 0.75, 0.25));
  expectColor(sampleTexture(t, 2.25, 0.25), sampleTexture(t, 0.25, 0.25));
  // Repeating across the image's edge blends the last texel with the first.
  t.wrapU = TextureWrap::repeat;
  expectColor(sampleTexture(t, 0.0, 0.25), {0.5, 0.5, 0.5});
}

TEST(Texture, AbsurdCoordinatesStayInsideTheImage) {
  Texture t = quad();
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const double inf = std::numeric_limits<double>::infinity();
  for (const double u : {nan, inf, -inf, 1e300, -1e300, 0.9999999999999999}) {
    const Color c = sampleTexture(t, u, u);
    EXPECT_TRUE(isFinite(c)) << u;
    EXPECT_GE(c.x, 0) << u;
    EXPECT_LE(c.x, 1) << u;
  }
}

TEST(Texture, GreyImagesGiveGreyAndAlphaIsNotColour) {
  auto image = std::make_shared<TextureImage>();
  image->width = 1;
  image->height = 1;
  image->channels = 2;  // grey + alpha
  image->texels = {255, 0};
  Texture t;
  t.image = image;
  expectColor(sampleTexture(t, 0.5, 0.5), {1, 1, 1});
}

// Data textures (metallic-roughness, normals) are numbers, not colours: byte / 255 with no
// sRGB curve; colour textures keep the curve.
TEST(Texture, DataTexturesAreReadWithoutTheSrgbCurve) {
  auto image = std::make_shared<TextureImage>();
  image->width = 1;
  image->height = 1;
  image->channels = 3;
  image->texels = {128, 64, 255};
  Texture t;
  t.image = image;
  const Color colour = sampleTexture(t, 0.5, 0.5);
  EXPECT_EQ(colour.x, srgbToLinear(128));
  EXPECT_NEAR(colour.x, 0.2158, 1e-4);
  t.linear = true;
  const Color data = sampleTexture(t, 0.5, 0.5);
  EXPECT_EQ(data.x, 128 / 255.0);
  EXPECT_EQ(data.y, 64 / 255.0);
  EXPECT_EQ(data.z, 1.0);
  for (int i = 0; i < 256; ++i) EXPECT_EQ(linearFromByte(static_cast<uint8_t>(i)), i / 255.0);
  EXPECT_FALSE(t == Texture{image});  // linear is part of what a texture is
}

// Where a data texture's texels agree, bilinear filtering reads their value exactly, at any
// point (a constant map equals its constant, bit for bit); colour textures blend as before.
TEST(Texture, ADataTextureOfOneValueReadsExactlyThatValue) {
  auto image = std::make_shared<TextureImage>();
  image->width = 3;
  image->height = 2;
  image->channels = 3;
  image->texels.assign(18, 77);
  Texture t;
  t.image = image;
  t.linear = true;
  for (const double u : {0.0, 0.1, 0.3333, 0.71, 0.999}) {
    for (const double v : {0.0, 0.29, 0.5, 0.93}) {
      EXPECT_EQ(sampleTexture(t, u, v), Color(77 / 255.0)) << u << " " << v;
    }
  }
}

}  // namespace
}  // namespace prt
