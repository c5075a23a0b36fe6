#include "trace/box_pair.h"

#include <gtest/gtest.h>

#include "core/rng.h"

namespace prt {
namespace {

// A direction with some components exactly +0 or -0 now and then (rays parallel to slabs).
Vec3 randomDirection(Rng& rng) {
  Vec3 d;
  for (int a = 0; a < 3; ++a) {
    const double u = rng.uniform();
    d[a] = u < 0.1 ? 0.0 : (u < 0.2 ? -0.0 : rng.uniform() * 2 - 1);
  }
  if (d.x == 0 && d.y == 0 && d.z == 0) d.z = 1;
  return normalize(d);
}

// Origins anywhere, inside the box, or exactly on one of its planes.
Vec3 randomOrigin(Rng& rng, const Bounds& b) {
  Vec3 o;
  for (int a = 0; a < 3; ++a) {
    const double u = rng.uniform();
    if (u < 0.15) {
      o[a] = b.lo[a];
    } else if (u < 0.3) {
      o[a] = b.hi[a];
    } else if (u < 0.6) {
      o[a] = b.lo[a] + rng.uniform() * (b.hi[a] - b.lo[a]);
    } else {
      o[a] = rng.uniform() * 20 - 10;
    }
  }
  return o;
}

Bounds randomBox(Rng& rng) {
  Bounds b;
  const Vec3 c(rng.uniform() * 8 - 4, rng.uniform() * 8 - 4, rng.uniform() * 8 - 4);
  b.extend(c);
  b.extend(c + Vec3(rng.uniform() * 3, rng.uniform() * 3, rng.uniform() < 0.1 ? 0 : rng.uniform()));
  return b;
}

bool slabPlaneRay(const Ray& ray, const Bounds& b) {
  for (int a = 0; a < 3; ++a) {
    if (ray.direction[a] == 0 && (ray.origin[a] == b.lo[a] || ray.origin[a] == b.hi[a])) return true;
  }
  return false;
}

TEST(BoxPairTest, NeverRejectsABoxHitsBoundsAccepts) {
  Rng rng(5);
  int hits = 0, misses = 0;
  for (int i = 0; i < 200000; ++i) {
    const Bounds box[2] = {randomBox(rng), randomBox(rng)};
    BoxPair pair;
    pair.set(0, box[0]);
    pair.set(1, box[1]);
    const Ray ray{randomOrigin(rng, box[i % 2]), randomDirection(rng)};
    const RayQuery q(ray);
    const double tMin = rng.uniform() < 0.5 ? 0.0 : rng.uniform();
    const double tMax = rng.uniform() < 0.5 ? std::numeric_limits<double>::infinity()
                                            : rng.uniform() * 20;
    Double2 entry;
    const int mask = pair.hits(SlabRay(q), tMin, tMax, entry);
    for (int lane = 0; lane < 2; ++lane) {
      const bool expected = hitsBounds(box[lane], q, tMin, tMax);
      const bool got = (mask >> lane) & 1;
      if (expected) {
        ASSERT_TRUE(got) << "lane " << lane << " ray " << i;
        EXPECT_GE(entry[lane], tMin);
        EXPECT_LE(entry[lane], tMax);
      }
      // Off the slab planes' NaN cases the two tests are the same test.
      if (!slabPlaneRay(ray, box[lane])) {
        EXPECT_EQ(got, expected) << "lane " << lane;
      }
      (expected ? hits : misses)++;
    }
  }
  EXPECT_GT(hits, 20000);
  EXPECT_GT(misses, 20000);
}

TEST(BoxPairTest, GrazingRaysAlongFacesAndEdges) {
  const Bounds b{{0, 0, 0}, {1, 1, 1}};
  BoxPair pair;
  pair.set(0, b);
  const double inf = std::numeric_limits<double>::infinity();
  // Along the top face, along an edge, through a corner, from just outside.
  const Ray rays[] = {{{-1, 1, 0.5}, {1, 0, 0}},  {{-1, 1, 1}, {1, 0, 0}},
                      {{-1, -1, -1}, normalize(Vec3(1, 1, 1))}, {{-1, 1 + 1e-15, 0.5}, {1, 0, 0}},
                      {{0.5, 0.5, 0.5}, {0, -0.0, 1}}, {{1, 0.5, 0.5}, {-0.0, 0, -1}}};
  for (const Ray& ray : rays) {
    const RayQuery q(ray);
    Double2 entry;
    const int mask = pair.hits(SlabRay(q), 0, inf, entry);
    if (hitsBounds(b, q, 0, inf)) {
      EXPECT_EQ(mask & 1, 1);
    }
    EXPECT_EQ(mask & 2, 0);  // the empty lane is never hit
  }
}

TEST(BoxPairTest, EmptyLaneNeverHit) {
  Rng rng(8);
  const BoxPair pair;
  for (int i = 0; i < 1000; ++i) {
    const Ray ray{randomOrigin(rng, randomBox(rng)), randomDirection(rng)};
    Double2 entry;
    EXPECT_EQ(pair.hits(SlabRay(RayQuery(ray)), 0, std::numeric_limits<double>::infinity(), entry),
              0);
  }
}

}  // namespace
}  // namespace prt
