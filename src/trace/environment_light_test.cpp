#include "trace/environment_light.h"

#include <gtest/gtest.h>

#include <cmath>
#include <memory>
#include <numbers>

#include "core/rng.h"

namespace prt {
namespace {

constexpr double kPiHere = std::numbers::pi;

// A map of `w` x `h` texels of radiance `sky`, with one texel (x, y) of `sun`.
Environment mapOf(int w, int h, Color sky, int x, int y, Color sun, double strength = 1,
                  double rotate = 0) {
  auto image = std::make_shared<Image>(w, h);
  for (int j = 0; j < h; ++j) {
    for (int i = 0; i < w; ++i) image->set(i, j, i == x && j == y ? sun : sky);
  }
  Environment e;
  e.background = Color(0.25);
  e.map.image = image;
  e.map.strength = strength;
  e.map.rotateDegrees = rotate;
  return e;
}

// The unit direction of map coordinates (u, v), as the layout in the header says.
Vec3 directionOf(double u, double v) {
  const double theta = kPiHere * v, phi = 2 * kPiHere * (u - 0.5);
  return Vec3(std::sin(theta) * std::cos(phi), std::cos(theta), std::sin(theta) * std::sin(phi));
}

TEST(EnvironmentLightTest, WithoutAMapTheWorldColourComesFromEveryDirection) {
  Environment e;
  e.background = Color(0.05, 0.1, 0.2);
  const EnvironmentLight light(e);
  EXPECT_FALSE(light.hasMap());
  EXPECT_FALSE(light.sampled());
  EXPECT_EQ(light.radiance(Vec3(0, 1, 0)), e.background);
  EXPECT_EQ(light.radiance(normalize(Vec3(1, -2, 3))), e.background);
  Vec3 d;
  Color c;
  double pdf;
  EXPECT_FALSE(light.sample(0.5, 0.5, d, c, pdf));
  EXPECT_EQ(light.pdf(Vec3(0, 1, 0)), 0.0);
}

// Blender's layout: the centre column looks along +x, a quarter to the right +z, the top row
// up; a turn moves what the map shows by that much azimuth.
TEST(EnvironmentLightTest, TheMapIsLaidOutAsBlendersIs) {
  // 8 x 4 texels; the sun at column 6 (u = 0.8125: azimuth 112.5 degrees), row 1 (v = 0.375).
  const Environment e = mapOf(8, 4, Color(1), 6, 1, Color(1000));
  const EnvironmentLight light(e);
  EXPECT_GT(light.radiance(directionOf(0.8125, 0.375)).x, 999);
  EXPECT_NEAR(light.radiance(directionOf(0.3125, 0.375)).x, 1, 1e-12);  // the other side
  EXPECT_NEAR(light.radiance(Vec3(0, -1, 0)).x, 1, 1e-12);
  // Turned by 90 degrees: the sun now at azimuth 202.5 degrees = u 1.0625 = u 0.0625.
  const EnvironmentLight turned(mapOf(8, 4, Color(1), 6, 1, Color(1000), 2, 90));
  EXPECT_GT(turned.radiance(directionOf(0.0625, 0.375)).x, 1999);
  EXPECT_NEAR(turned.radiance(directionOf(0.8125, 0.375)).x, 2, 1e-12);
}

// Sampling chooses the sun in proportion to its share of the light, and each density it
// reports is the one pdf() gives for the direction.
TEST(EnvironmentLightTest, SamplesFollowTheLightAndTheirDensityIsPdfs) {
  const EnvironmentLight light(mapOf(32, 16, Color(1), 24, 5, Color(5000)));
  ASSERT_TRUE(light.sampled());
  Rng rng(7);
  int sunny = 0, n = 20000;
  for (int i = 0; i < n; ++i) {
    Vec3 d;
    Color c;
    double pdf;
    ASSERT_TRUE(light.sample(rng.uniform(), rng.uniform(), d, c, pdf));
    EXPECT_NEAR(length(d), 1, 1e-12);
    EXPECT_NEAR(light.pdf(d) / pdf, 1, 1e-6);
    sunny += c.x > 100 ? 1 : 0;
  }
  // The sun's weight against the rest: 5000 sin(theta_5) against the sum of sin(theta) over
  // every texel (sin theta of row 5's centre is sin(5.5 pi / 16)).
  double rest = 0;
  for (int y = 0; y < 16; ++y) rest += 32 * std::sin((y + 0.5) * kPiHere / 16);
  const double sun = 4999 * std::sin(5.5 * kPiHere / 16);
  // A sample lands in the sun's texel with that share; its bilinear radiance is above 100
  // only over part of the texel, so the count is checked from below.
  EXPECT_GT(sunny, 0.2 * n * sun / (sun + rest));
  EXPECT_LT(sunny, 1.01 * n * sun / (sun + rest) + 200);
}

// The density integrates to 1 over the sphere (estimated with uniform directions), and an
// estimate of the light's power by sampling matches one by uniform directions.
TEST(EnvironmentLightTest, TheDensityIntegratesToOneAndEstimatesAreUnbiased) {
  const EnvironmentLight light(mapOf(16, 8, Color(0.5, 1, 2), 3, 2, Color(40)));
  Rng rng(11);
  const int n = 400000;
  double integral = 0, uniformPower = 0, sampledPower = 0;
  for (int i = 0; i < n; ++i) {
    const double z = 1 - 2 * rng.uniform(), a = 2 * kPiHere * rng.uniform();
    const double r = std::sqrt(std::max(0.0, 1 - z * z));
    const Vec3 d(r * std::cos(a), z, r * std::sin(a));
    integral += light.pdf(d) * 4 * kPiHere;
    uniformPower += light.radiance(d).y * 4 * kPiHere;
    Vec3 s;
    Color c;
    double pdf;
    if (light.sample(rng.uniform(), rng.uniform(), s, c, pdf)) sampledPower += c.y / pdf;
  }
  EXPECT_NEAR(integral / n, 1, 0.01);
  EXPECT_NEAR(sampledPower / uniformPower, 1, 0.01);
}

TEST(EnvironmentLightTest, ADarkMapIsNotSampledAndNothingNonFiniteComesOut) {
  const EnvironmentLight dark(mapOf(4, 2, Color(0), 0, 0, Color(0)));
  EXPECT_TRUE(dark.hasMap());
  EXPECT_FALSE(dark.sampled());
  EXPECT_EQ(dark.radiance(Vec3(0, 1, 0)), Color(0));
  // A texel of infinite or NaN radiance (which readers refuse) reads as black.
  const EnvironmentLight broken(mapOf(4, 2, Color(1), 1, 1, Color(INFINITY)));
  for (const Vec3& d : {Vec3(0, 1, 0), Vec3(0, -1, 0), normalize(Vec3(1, -1, 1))}) {
    EXPECT_TRUE(isFinite(broken.radiance(d)));
  }
  EXPECT_TRUE(broken.sampled());
}

}  // namespace
}  // namespace prt
