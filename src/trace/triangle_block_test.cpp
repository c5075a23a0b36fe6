#include "trace/triangle_block.h"

#include <gtest/gtest.h>

#include <bit>
#include <cmath>
#include <limits>

#include "core/rng.h"

namespace prt {
namespace {

constexpr double kBlockInf = std::numeric_limits<double>::infinity();

Vec3 randomPoint(Rng& rng, double scale) {
  return scale * Vec3(rng.uniform() - 0.5, rng.uniform() - 0.5, rng.uniform() - 0.5);
}

// Each lane's distance has the bits of the scalar test's (NaN where that one misses), for
// random triangles at several scales, triangles sharing edges and vertices with rays aimed
// exactly at those, triangles seen edge-on and degenerate ones, in blocks of one to eight
// used lanes.
TEST(TriangleBlockTest, EveryLaneIsTheScalarTestBitForBit) {
  Rng rng(17);
  int hits = 0, misses = 0;
  for (int i = 0; i < 20000; ++i) {
    const double scale = std::ldexp(1.0, static_cast<int>(rng.uniform() * 40) - 20);
    Vec3 corners[kBlockLanes][3];
    for (auto& t : corners) {
      for (Vec3& p : t) p = randomPoint(rng, scale);
    }
    corners[1][0] = corners[0][1];  // triangle 1 shares the edge b-a of triangle 0
    corners[1][1] = corners[0][0];
    if (i % 7 == 0) corners[2][2] = corners[2][0] + 0.5 * (corners[2][1] - corners[2][0]);
    if (i % 11 == 0) corners[3][1] = corners[3][0];  // degenerate
    Ray ray{randomPoint(rng, 4 * scale), {}};
    const Vec3 target = i % 3 == 0   ? corners[0][0]                          // a shared vertex
                        : i % 3 == 1 ? 0.5 * (corners[0][0] + corners[0][1])  // a shared edge
                                     : randomPoint(rng, scale);
    ray.direction = normalize(target - ray.origin);
    if (i % 13 == 0) ray.direction = Vec3(0, 0, ray.direction.z < 0 ? -1.0 : 1.0);
    if (i % 17 == 0) {  // in the plane of triangle 3: seen edge-on
      const Vec3& a = corners[3][0];
      ray.origin = a + 2.0 * (corners[3][2] - a);
      ray.direction = normalize(a - ray.origin);
    }
    const ShearedRay sheared(ray);
    TriangleBlock block;
    double pts[kBlockLanes][3][3];
    const int used = 1 + i % kBlockLanes;  // the lanes beyond are unused
    for (int lane = 0; lane < used; ++lane) {
      for (int k = 0; k < 3; ++k) {
        for (int axis = 0; axis < 3; ++axis) pts[lane][k][axis] = corners[lane][k][axis];
      }
      block.set(lane, pts[lane][0], pts[lane][1], pts[lane][2]);
    }
    double d[kBlockLanes];
    const double lo = i % 2 ? 0.0 : -kBlockInf, hi = i % 4 < 2 ? kBlockInf : 2 * scale;
    const bool toHi = i % 16 < 8;
    // Told every lane, or only the used ones (lanes past those may then be left unset).
    const int told = i % 3 == 0 ? kBlockLanes : used;
    const int lanes = blockHits(ShearedRay4(sheared), block, told, lo, hi, toHi, d);
    EXPECT_EQ(lanes >> used, 0) << "ray " << i << ": an unused lane reported";
    for (int lane = 0; lane < used; ++lane) {
      const bool within = d[lane] > lo && (toHi ? d[lane] <= hi : d[lane] < hi);
      EXPECT_EQ((lanes >> lane) & 1, within ? 1 : 0) << "ray " << i << ", lane " << lane;
      const double expected = triangleDistance(sheared, pts[lane][0], pts[lane][1], pts[lane][2]);
      if (std::isnan(expected)) {
        ++misses;
        EXPECT_TRUE(std::isnan(d[lane])) << "ray " << i << ", lane " << lane;
      } else {
        ++hits;
        EXPECT_EQ(std::bit_cast<uint64_t>(d[lane]), std::bit_cast<uint64_t>(expected))
            << "ray " << i << ", lane " << lane;
      }
    }
  }
  EXPECT_GT(hits, 5000);
  EXPECT_GT(misses, 5000);
}

TEST(TriangleBlockTest, LanesInRangeAreReportedByTheirBits) {
  // Eight triangles facing the ray at distances 1 to 8 along +z.
  TriangleBlock block;
  for (int lane = 0; lane < kBlockLanes; ++lane) {
    const double z = lane + 1.0;
    const double a[3] = {-1, -1, z}, b[3] = {1, -1, z}, c[3] = {0, 1, z};
    block.set(lane, a, b, c);
  }
  const ShearedRay4 ray(ShearedRay(Ray{{0, 0, 0}, {0, 0, 1}}));
  double d[kBlockLanes];
  EXPECT_EQ(blockHits(ray, block, kBlockLanes, 0, 3, false, d), 0b0011);
  EXPECT_EQ(d[0], 1.0);
  EXPECT_EQ(d[7], 8.0);
  EXPECT_EQ(blockHits(ray, block, kBlockLanes, 0, 3, true, d), 0b0111);
  EXPECT_EQ(blockHits(ray, block, kBlockLanes, 1, 4, true, d), 0b1110);
  EXPECT_EQ(blockHits(ray, block, kBlockLanes, 4, 9, false, d), 0b11110000);
  EXPECT_EQ(blockHits(ray, block, kBlockLanes, 8, 9, false, d), 0);
  // Only the first lanes told used: the others are not looked at.
  EXPECT_EQ(blockHits(ray, block, 2, 0, 9, false, d) & 0b11, 0b11);
  EXPECT_EQ(blockHits(ray, block, 1, 0, 9, false, d) & 1, 1);
}

}  // namespace
}  // namespace prt
