#include "trace/shapes.h"

#include <gtest/gtest.h>

#include <limits>

namespace prt {
namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

TEST(ShapesTest, SphereFromOutsideHitsTwiceNearestFirst) {
  const SphereShape s{{0, 0, 5}, 1};
  const Crossings c = intersect(s, Ray{{0, 0, 0}, {0, 0, 1}}, 0, kInf);
  ASSERT_EQ(c.count, 2);
  EXPECT_DOUBLE_EQ(c.t[0], 4);
  EXPECT_DOUBLE_EQ(c.t[1], 6);
  EXPECT_EQ(c.normal[0], Vec3(0, 0, -1));
  EXPECT_EQ(c.normal[1], Vec3(0, 0, 1));
}

TEST(ShapesTest, SphereFromInsideHitsOnceWithOutwardNormal) {
  const Crossings c = intersect(SphereShape{{0, 0, 0}, 2}, Ray{{0, 0, 0}, {1, 0, 0}}, 0, kInf);
  ASSERT_EQ(c.count, 1);
  EXPECT_DOUBLE_EQ(c.t[0], 2);
  EXPECT_EQ(c.normal[0], Vec3(1, 0, 0));
}

TEST(ShapesTest, SphereBehindAndMissed) {
  const SphereShape s{{0, 0, -5}, 1};
  EXPECT_EQ(intersect(s, Ray{{0, 0, 0}, {0, 0, 1}}, 0, kInf).count, 0);
  EXPECT_EQ(intersect(s, Ray{{0, 2, 0}, {0, 0, -1}}, 0, kInf).count, 0);
}

TEST(ShapesTest, SphereGrazingTouchesOnce) {
  const Crossings c = intersect(SphereShape{{0, 1, 5}, 1}, Ray{{0, 0, 0}, {0, 0, 1}}, 0, kInf);
  ASSERT_GE(c.count, 1);
  EXPECT_NEAR(c.t[0], 5, 1e-9);
}

TEST(ShapesTest, SphereRespectsInterval) {
  const SphereShape s{{0, 0, 5}, 1};
  const Crossings c = intersect(s, Ray{{0, 0, 0}, {0, 0, 1}}, 0, 5);
  ASSERT_EQ(c.count, 1);
  EXPECT_DOUBLE_EQ(c.t[0], 4);
}

TEST(ShapesTest, BoxFromOutsideEntersThroughFacingFace) {
  const BoxShape b{{-1, -1, 2}, {1, 1, 4}};
  const Crossings c = intersect(b, Ray{{0, 0, 0}, {0, 0, 1}}, 0, kInf);
  ASSERT_EQ(c.count, 2);
  EXPECT_DOUBLE_EQ(c.t[0], 2);
  EXPECT_EQ(c.normal[0], Vec3(0, 0, -1));
  EXPECT_DOUBLE_EQ(c.t[1], 4);
  EXPECT_EQ(c.normal[1], Vec3(0, 0, 1));
}

TEST(ShapesTest, BoxFromInsideLeavesThroughFarFace) {
  const Crossings c =
      intersect(BoxShape{{-1, -1, -1}, {1, 1, 1}}, Ray{{0, 0, 0}, {-1, 0, 0}}, 0, kInf);
  ASSERT_EQ(c.count, 1);
  EXPECT_DOUBLE_EQ(c.t[0], 1);
  EXPECT_EQ(c.normal[0], Vec3(-1, 0, 0));
}

TEST(ShapesTest, BoxParallelOutsideSlabMisses) {
  const BoxShape b{{-1, -1, 2}, {1, 1, 4}};
  EXPECT_EQ(intersect(b, Ray{{0, 2, 0}, {0, 0, 1}}, 0, kInf).count, 0);
  EXPECT_EQ(intersect(b, Ray{{0, 0, 0}, {0, 0, -1}}, 0, kInf).count, 0);  // behind
}

TEST(ShapesTest, PlaneIsOneSided) {
  const PlaneShape p{{0, 0, 0}, {0, 1, 0}};
  const Crossings front = intersect(p, Ray{{0, 2, 0}, {0, -1, 0}}, 0, kInf);
  ASSERT_EQ(front.count, 1);
  EXPECT_DOUBLE_EQ(front.t[0], 2);
  EXPECT_EQ(intersect(p, Ray{{0, -2, 0}, {0, 1, 0}}, 0, kInf).count, 0);  // from behind
  EXPECT_EQ(intersect(p, Ray{{0, 2, 0}, {1, 0, 0}}, 0, kInf).count, 0);   // parallel
  EXPECT_EQ(intersect(p, Ray{{0, 2, 0}, {0, 1, 0}}, 0, kInf).count, 0);   // away
}

TEST(ShapesTest, BoundsOfShapes) {
  const Bounds b = boundsOf(SphereShape{{1, 2, 3}, 0.5});
  EXPECT_EQ(b.lo, Vec3(0.5, 1.5, 2.5));
  EXPECT_EQ(b.hi, Vec3(1.5, 2.5, 3.5));
  EXPECT_FALSE(isBounded(PlaneShape{}));
}

}  // namespace
}  // namespace prt
