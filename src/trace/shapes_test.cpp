#include "trace/shapes.h"

#include <gtest/gtest.h>

#include <bit>
#include <cmath>
#include <cstdint>
#include <limits>

#include "core/rng.h"

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

// boxSpan, the hot loops' box test, must answer as boxSlabs does: the same hit, entry and exit,
// and the same crossings and first crossing for any interval. Rays from random points (many on
// a face or an edge, so distances of exactly 0 and equal entries occur) in random directions,
// many with components of exactly zero, subnormal or huge, some exactly along a face.
TEST(ShapesTest, BoxSpanAnswersAsBoxSlabs) {
  Rng rng(42);
  const Vec3 lo(-1, -0.5, 2), hi(1, 0.25, 3);
  const double special[] = {0.0, -0.0, 4.9e-324, -1e-310, 1e300, -1e-20, 1.0, -1.0};
  auto coordinate = [&](double a, double b) {
    const double u = rng.uniform();
    if (u < 0.2) return a;  // on a face's plane
    if (u < 0.4) return b;
    return a - 2 + (b - a + 4) * rng.uniform();
  };
  auto component = [&]() {
    const double u = rng.uniform();
    if (u < 0.3) return special[static_cast<int>(rng.uniform() * 8)];
    return 2 * rng.uniform() - 1;
  };
  const double intervals[][2] = {{0, kInf}, {0, 2.5}, {-kInf, kInf}, {1e-9, 1}, {2, 2}};
  int hits = 0;
  for (int i = 0; i < 200000; ++i) {
    const Ray ray{{coordinate(lo.x, hi.x), coordinate(lo.y, hi.y), coordinate(lo.z, hi.z)},
                  {component(), component(), component()}};
    const BoxSlabs slabs = boxSlabs(lo, hi, ray);
    const BoxSpan span = boxSpan(lo, hi, ray);
    ASSERT_EQ(span.hit, slabs.hit) << i;
    if (!slabs.hit) continue;
    ++hits;
    ASSERT_EQ(std::bit_cast<uint64_t>(span.tNear), std::bit_cast<uint64_t>(slabs.tNear)) << i;
    ASSERT_EQ(std::bit_cast<uint64_t>(span.tFar), std::bit_cast<uint64_t>(slabs.tFar)) << i;
    for (const auto& interval : intervals) {
      const double tMin = interval[0], tMax = interval[1];
      ASSERT_EQ(span.nearCrosses(tMin, tMax), slabs.nearCrosses(tMin, tMax)) << i;
      ASSERT_EQ(span.farCrosses(tMin, tMax), slabs.farCrosses(tMin, tMax)) << i;
      const double a = span.firstAfter(tMin), b = slabs.firstAfter(tMin);
      ASSERT_TRUE(a == b || (std::isnan(a) && std::isnan(b))) << i;
    }
  }
  EXPECT_GT(hits, 20000);  // the comparison above ran on many hits, not only on misses
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
