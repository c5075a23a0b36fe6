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

TEST(CameraTest, OrthographicRaysAreParallelAndSpanTheHeight) {
  Camera c;
  c.eye = Vec3(0, 0, -5);
  c.lookAt = Vec3(0, 0, 0);
  c.orthoHeight = 4;  // 4 units high; 8 wide at 2:1
  const PinholeCamera camera(c, 200, 100);
  const Ray centre = camera.generateRay(100, 50);
  EXPECT_EQ(centre.direction, Vec3(0, 0, 1));
  EXPECT_EQ(centre.origin, c.eye);
  const Ray corner = camera.generateRay(0, 0);
  EXPECT_EQ(corner.direction, Vec3(0, 0, 1));
  EXPECT_NEAR(corner.origin.x, -4, 1e-12);  // left-handed, as the perspective camera
  EXPECT_NEAR(corner.origin.y, 2, 1e-12);
  Rng rng(9);
  for (int i = 0; i < 1000; ++i) {
    const double px = rng.uniform() * 200, py = rng.uniform() * 100;
    const Ray ray = camera.generateRay(px, py);
    double x = 0, y = 0;
    ASSERT_TRUE(camera.project(ray.at(0.5 + 50 * rng.uniform()), x, y));
    EXPECT_NEAR(x, px, 1e-9);
    EXPECT_NEAR(y, py, 1e-9);
  }
}

}  // namespace
}  // namespace prt
