#include "trace/camera.h"

#include <gtest/gtest.h>

#include "core/rng.h"

namespace prt {
namespace {

TEST(CameraTest, ProjectInvertsGenerateRay) {
  Camera c;
  c.eye = Vec3(-1, 3.2, -9);
  c.lookAt = Vec3(1.2, 1.2, 0);
  c.fovDegrees = 42;
  const PinholeCamera camera(c, 640, 480);
  Rng rng(4);
  for (int i = 0; i < 10000; ++i) {
    const double px = rng.uniform() * 640, py = rng.uniform() * 480;
    const Ray ray = camera.generateRay(px, py);
    double x = 0, y = 0;
    ASSERT_TRUE(camera.project(ray.at(0.1 + 100 * rng.uniform()), x, y));
    EXPECT_NEAR(x, px, 1e-9);
    EXPECT_NEAR(y, py, 1e-9);
  }
}

TEST(CameraTest, PointsBehindTheEyeAreNotProjected) {
  const PinholeCamera camera(Camera{}, 32, 24);  // at (0, 0, -5) looking towards +z
  double x = 0, y = 0;
  EXPECT_FALSE(camera.project({0, 0, -6}, x, y));
  EXPECT_FALSE(camera.project({3, 0, -5}, x, y));  // in the eye's plane
  EXPECT_TRUE(camera.project({0, 0, 0}, x, y));
  EXPECT_DOUBLE_EQ(x, 16);
  EXPECT_DOUBLE_EQ(y, 12);
}

}  // namespace
}  // namespace prt
