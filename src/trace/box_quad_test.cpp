#include "trace/box_quad.h"

#include <gtest/gtest.h>

#include <bit>
#include <cstdint>

#include "core/rng.h"

namespace prt {
namespace {

constexpr double kBoxInf = std::numeric_limits<double>::infinity();

// A direction with some components exactly +0 or -0 (rays parallel to slabs) or tiny now and
// then.
Vec3 randomDirection(Rng& rng) {
  Vec3 d;
  for (int a = 0; a < 3; ++a) {
    const double u = rng.uniform();
    d[a] = u < 0.1 ? 0.0 : (u < 0.2 ? -0.0 : (u < 0.25 ? 1e-41 : rng.uniform() * 2 - 1));
  }
  if (d.x == 0 && d.y == 0 && d.z == 0) d.z = 1;
  return normalize(d);
}

// Origins anywhere, inside the box, exactly on one of its planes, or just off one.
Vec3 randomOrigin(Rng& rng, const Bounds& b) {
  Vec3 o;
  for (int a = 0; a < 3; ++a) {
    const double u = rng.uniform();
    if (u < 0.15) {
      o[a] = b.lo[a];
    } else if (u < 0.3) {
      o[a] = b.hi[a];
    } else if (u < 0.35) {
      o[a] = std::nextafter(b.hi[a], kBoxInf);
    } else if (u < 0.6) {
      o[a] = b.lo[a] + rng.uniform() * (b.hi[a] - b.lo[a]);
    } else {
      o[a] = rng.uniform() * 20 - 10;
    }
  }
  return o;
}

// Boxes of every size, some flat, some far from the origin.
Bounds randomBox(Rng& rng, double scale) {
  Bounds b;
  const Vec3 c(rng.uniform() * 8 - 4, rng.uniform() * 8 - 4, rng.uniform() * 8 - 4);
  b.extend(scale * c);
  b.extend(scale * (c + Vec3(rng.uniform() * 3, rng.uniform() * 3,
                             rng.uniform() < 0.1 ? 0 : rng.uniform())));
  return b;
}

// hitsBounds' interval, or false when it rejects: the entry distance the float test must not
// exceed.
bool doubleEntry(const Bounds& b, const RayQuery& q, double tMin, double tMax, double& entry) {
  if (!hitsBounds(b, q, tMin, tMax)) return false;
  for (int axis = 0; axis < 3; ++axis) {
    double t0 = (b.lo[axis] - q.ray.origin[axis]) * q.invDirection[axis];
    double t1 = (b.hi[axis] - q.ray.origin[axis]) * q.invDirection[axis];
    if (t0 > t1) std::swap(t0, t1);
    tMin = t0 > tMin ? t0 : tMin;
  }
  entry = tMin;
  return true;
}

void checkRandomRays(double scale, uint64_t seed) {
  Rng rng(seed);
  int hits = 0, misses = 0, falseHits = 0;
  for (int i = 0; i < 100000; ++i) {
    Bounds box[4];
    BoxQuad quad;
    double maxCoordinate = 0;
    for (int lane = 0; lane < 4; ++lane) {
      box[lane] = randomBox(rng, scale);
      quad.set(lane, box[lane]);
      for (int a = 0; a < 3; ++a) {
        maxCoordinate = std::max({maxCoordinate, std::abs(box[lane].lo[a]),
                                  std::abs(box[lane].hi[a])});
      }
    }
    const Ray ray{randomOrigin(rng, box[i % 4]), randomDirection(rng)};
    const RayQuery q(ray);
    const double tMin = rng.uniform() < 0.5 ? 0.0 : rng.uniform() * scale;
    const double tMax = rng.uniform() < 0.5 ? kBoxInf : rng.uniform() * 20 * scale;
    Float4 entry;
    const int mask = quad.hits(QuadRay(ray, floatAbove(maxCoordinate)), floatBelow(tMin),
                               floatAbove(tMax), entry);
    for (int lane = 0; lane < 4; ++lane) {
      double expectedEntry = 0;
      const bool expected = doubleEntry(box[lane], q, tMin, tMax, expectedEntry);
      const bool got = (mask >> lane) & 1;
      if (expected) {
        ++hits;
        ASSERT_TRUE(got) << "scale " << scale << " ray " << i << " lane " << lane;
        EXPECT_LE(entry[lane], expectedEntry) << "ray " << i << " lane " << lane;
      } else if (std::abs(ray.direction.x) > 1e-3 && std::abs(ray.direction.y) > 1e-3 &&
                 std::abs(ray.direction.z) > 1e-3) {
        // (An axis the ray runs parallel to cannot be tested in float: see box_quad.h.)
        ++misses;
        falseHits += got;
      }
    }
  }
  EXPECT_GT(hits, 8000);
  EXPECT_GT(misses, 40000);
  EXPECT_LT(falseHits, misses / 100);  // conservative, yet culls nearly as well
}

TEST(BoxQuadTest, NeverRejectsABoxHitsBoundsAccepts) {
  checkRandomRays(1, 5);
  checkRandomRays(1e-3, 6);
  checkRandomRays(1e6, 7);
}

TEST(BoxQuadTest, GrazingRaysAlongFacesAndEdges) {
  const Bounds b{{0, 0, 0}, {1, 1, 1}};
  BoxQuad quad;
  quad.set(0, b);
  quad.set(2, Bounds{{1, 0, 0}, {2, 1, 1}});  // shares a face with lane 0
  const Ray rays[] = {{{-1, 1, 0.5}, {1, 0, 0}},
                      {{-1, 1, 1}, {1, 0, 0}},
                      {{-1, -1, -1}, normalize(Vec3(1, 1, 1))},
                      {{-1, 1 + 1e-15, 0.5}, {1, 0, 0}},
                      {{0.5, 0.5, 0.5}, {0, -0.0, 1}},
                      {{1, 0.5, 0.5}, {-0.0, 0, -1}},
                      {{1, 0.5, 0.5}, normalize(Vec3(1e-300, 1, 1))},
                      {{3, 1, 0.5}, normalize(Vec3(-1, -1e-17, 0))}};
  for (const Ray& ray : rays) {
    const RayQuery q(ray);
    Float4 entry;
    const int mask = quad.hits(QuadRay(ray, 2), 0, floatAbove(kBoxInf), entry);
    if (hitsBounds(b, q, 0, kBoxInf)) {
      EXPECT_EQ(mask & 1, 1);
    }
    if (hitsBounds(Bounds{{1, 0, 0}, {2, 1, 1}}, q, 0, kBoxInf)) {
      EXPECT_EQ(mask & 4, 4);
    }
    EXPECT_EQ(mask & 10, 0);  // the empty lanes are never hit
  }
}

TEST(BoxQuadTest, OutOfRangeCoordinatesOnlyLoosenTheTest) {
  // Beyond float's range the axes cannot be tested: every box is accepted, none lost.
  BoxQuad quad;
  const Bounds huge{{1e300, 0, 0}, {2e300, 1, 1}};
  quad.set(0, huge);
  const Ray ray{{1.5e300, 0.5, -5}, {0, 0, 1}};
  Float4 entry;
  EXPECT_EQ(quad.hits(QuadRay(ray, floatAbove(2e300)), 0, floatAbove(kBoxInf), entry) & 1, 1);
  EXPECT_TRUE(hitsBounds(huge, RayQuery(ray), 0, kBoxInf));
}

TEST(BoxQuadTest, FloatRoundingIsOutwards) {
  Rng rng(3);
  for (int i = 0; i < 10000; ++i) {
    const double x = (rng.uniform() - 0.5) * std::ldexp(1.0, static_cast<int>(rng.uniform() * 200) - 100);
    EXPECT_LE(static_cast<double>(floatBelow(x)), x);
    EXPECT_GE(static_cast<double>(floatAbove(x)), x);
    EXPECT_LT(std::abs(floatAbove(x) - x), std::abs(x) * 1e-6);
  }
  EXPECT_EQ(floatAbove(kBoxInf), std::numeric_limits<float>::infinity());
  EXPECT_EQ(floatBelow(0.0), 0.0f);
  EXPECT_GE(static_cast<double>(floatAbove(1e300)), 1e300);
}

}  // namespace
}  // namespace prt

namespace prt {
namespace {

// BoxOct is BoxQuad eight lanes wide: the same masks and entries, bit for bit, as two quads
// holding the same boxes, on the rays above (so it is just as conservative).
TEST(BoxOctTest, GivesWhatTwoQuadsGiveBitForBit) {
  Rng rng(11);
  for (const double scale : {1e-3, 1.0, 1e6}) {
    for (int i = 0; i < 20000; ++i) {
      Bounds box[8];
      BoxQuad quads[2];
      BoxOct oct;
      double maxCoordinate = 0;
      for (int lane = 0; lane < 8; ++lane) {
        box[lane] = randomBox(rng, scale);
        if (lane == 5 && i % 3 == 0) continue;  // an unused lane, as in a node not full
        quads[lane / 4].set(lane % 4, box[lane]);
        oct.set(lane, box[lane]);
        for (int a = 0; a < 3; ++a) {
          maxCoordinate = std::max({maxCoordinate, std::abs(box[lane].lo[a]),
                                    std::abs(box[lane].hi[a])});
        }
      }
      const Ray ray{randomOrigin(rng, box[i % 4]), randomDirection(rng)};
      const QuadRay q(ray, floatAbove(maxCoordinate));
      const float tMin = floatBelow(rng.uniform() < 0.5 ? 0.0 : rng.uniform() * scale);
      const float tMax = floatAbove(rng.uniform() < 0.5 ? kBoxInf : rng.uniform() * 20 * scale);
      Float4 low, high;
      const int expected =
          quads[0].hits(q, tMin, tMax, low) | quads[1].hits(q, tMin, tMax, high) << 4;
      Float8 entry;
      ASSERT_EQ(oct.hits(q, tMin, tMax, entry), expected) << "scale " << scale << " ray " << i;
      for (int lane = 0; lane < 8; ++lane) {
        const float want = lane < 4 ? low[lane] : high[lane - 4];
        EXPECT_EQ(std::bit_cast<uint32_t>(entry[lane]), std::bit_cast<uint32_t>(want))
            << "ray " << i << " lane " << lane;
      }
    }
  }
}

}  // namespace
}  // namespace prt
