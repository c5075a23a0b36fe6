#include "trace/normal_map.h"

#include <gtest/gtest.h>

#include <cmath>

#include "trace/texture.h"

namespace prt {
namespace {

Color texel(uint8_t r, uint8_t g, uint8_t b) {
  return {linearFromByte(r), linearFromByte(g), linearFromByte(b)};
}

// Byte 128 is exactly 0 and 255 exactly 1: the flat texel writers use is exactly flat.
TEST(NormalMap, TheFlatTexelIsExactlyFlat) {
  EXPECT_EQ(normalMapVector(texel(128, 128, 255), 1), Vec3(0, 0, 1));
  EXPECT_EQ(normalMapVector(texel(128, 128, 255), 3), Vec3(0, 0, 1));
  EXPECT_EQ(normalMapVector(texel(255, 0, 1), 1), Vec3(1, -1, -1));  // held to [-1, 1]
  EXPECT_EQ(normalMapVector(texel(255, 128, 255), 0.5), Vec3(0.5, 0, 1));
  const Vec3 n = normalize(Vec3(0.3, 0.4, 0.8));
  const Vec3 same = mappedNormal(n, {1, 0, 0}, 1, normalMapVector(texel(128, 128, 255), 1));
  EXPECT_EQ(same, n);  // the same bits
}

// The map's x tilts the normal towards the tangent (made perpendicular to the normal), its y
// towards handedness x cross(normal, tangent).
TEST(NormalMap, TiltsAlongTheTangentFrame) {
  const Vec3 n(0, 0, 1);
  const Vec3 tangent(2, 0, 0.5);  // not unit, not perpendicular: Gram-Schmidt makes it +x
  const Vec3 x = mappedNormal(n, tangent, 1, {1, 0, 1});
  EXPECT_NEAR(x.x, std::sqrt(0.5), 1e-15);
  EXPECT_NEAR(x.y, 0, 1e-15);
  EXPECT_NEAR(x.z, std::sqrt(0.5), 1e-15);
  const Vec3 y = mappedNormal(n, tangent, 1, {0, 1, 1});
  EXPECT_NEAR(y.y, std::sqrt(0.5), 1e-15);  // cross(+z, +x) = +y
  const Vec3 mirrored = mappedNormal(n, tangent, -1, {0, 1, 1});
  EXPECT_NEAR(mirrored.y, -std::sqrt(0.5), 1e-15);
  // No tangent, or one along the normal: the normal itself.
  EXPECT_EQ(mappedNormal(n, {0, 0, 0}, 1, {1, 0, 1}), n);
  EXPECT_EQ(mappedNormal(n, {0, 0, 3}, 1, {1, 0, 1}), n);
}

// A normal tilted so far that the view's mirror direction would point into the surface is
// turned back just enough: the reflection then lies on the threshold above the surface.
TEST(NormalMap, ReflectionsAreKeptAboveTheSurface) {
  const Vec3 ng(0, 0, 1);
  const Vec3 wo = normalize(Vec3(-1, 0, 0.3));  // a grazing view from -x
  const Vec3 steep = normalize(Vec3(0.25, 0, 1));  // tilted away from the viewer
  const Vec3 r0 = 2 * dot(steep, wo) * steep - wo;
  ASSERT_LT(r0.z, 0);  // the mirror direction is below the surface
  const Vec3 kept = keepReflectionAbove(ng, wo, steep);
  EXPECT_NEAR(length(kept), 1, 1e-12);
  const Vec3 r = 2 * dot(kept, wo) * kept - wo;
  EXPECT_NEAR(r.z, std::min(0.9 * wo.z, 0.01), 1e-9);
  EXPECT_GT(kept.z, steep.z);  // turned towards the geometric normal
  EXPECT_NEAR(kept.y, 0, 1e-15);  // in the plane of the two
  // A normal that reflects above the surface is left as it is.
  const Vec3 mild = normalize(Vec3(0.1, 0, 1));
  EXPECT_EQ(keepReflectionAbove(ng, wo, mild), mild);
}

}  // namespace
}  // namespace prt
