#include "trace/bvh.h"

#include <gtest/gtest.h>

#include "core/rng.h"
#include "trace/shapes.h"
#include "trace/world.h"

namespace prt {
namespace {

Scene randomSpheres(int count, uint64_t seed) {
  Scene scene;
  Rng rng(seed);
  for (int i = 0; i < count; ++i) {
    const Vec3 c(rng.uniform() * 20 - 10, rng.uniform() * 20 - 10, rng.uniform() * 20 - 10);
    scene.objects.push_back({SphereShape{c, 0.1 + rng.uniform()}, Material{}});
    if (i % 7 == 0) {
      scene.objects.push_back({BoxShape{c, c + Vec3(0.5, 1, 0.3)}, Material{}});
    }
  }
  return scene;
}

// Brute force over every object: the reference the BVH must agree with.
bool bruteNearest(const Scene& scene, const Ray& ray, double& t, uint32_t& object) {
  bool found = false;
  t = std::numeric_limits<double>::infinity();
  for (uint32_t i = 0; i < scene.objects.size(); ++i) {
    const Crossings c =
        std::visit([&](const auto& s) { return intersect(s, ray, 0.0, t); }, scene.objects[i].shape);
    if (c.count > 0) {
      t = c.t[0];
      object = i;
      found = true;
    }
  }
  return found;
}

TEST(BvhTest, NearestHitMatchesBruteForce) {
  const Scene scene = randomSpheres(500, 7);
  const World world(scene);
  Rng rng(99);
  int hits = 0;
  for (int i = 0; i < 2000; ++i) {
    const Vec3 origin(rng.uniform() * 30 - 15, rng.uniform() * 30 - 15, -15);
    const Vec3 dir = normalize(Vec3(rng.uniform() - 0.5, rng.uniform() - 0.5, 1));
    const Ray ray{origin, dir};
    double t = 0;
    uint32_t object = 0;
    const bool expected = bruteNearest(scene, ray, t, object);
    Hit hit;
    ASSERT_EQ(world.intersect(ray, 0, std::numeric_limits<double>::infinity(), hit), expected);
    if (expected) {
      ++hits;
      EXPECT_EQ(hit.t, t);
      EXPECT_EQ(hit.object, object);
    }
  }
  EXPECT_GT(hits, 100);  // the test must exercise hits, not only misses
}

TEST(BvhTest, EmptyAndSingle) {
  const World empty{Scene{}};
  Hit hit;
  EXPECT_FALSE(empty.intersect(Ray{{0, 0, 0}, {0, 0, 1}}, 0, 1e30, hit));
  Scene one;
  one.objects.push_back({SphereShape{{0, 0, 3}, 1}, Material{}});
  const World w(one);
  ASSERT_TRUE(w.intersect(Ray{{0, 0, 0}, {0, 0, 1}}, 0, 1e30, hit));
  EXPECT_DOUBLE_EQ(hit.t, 2);
  EXPECT_EQ(hit.point, Vec3(0, 0, 2));
}

TEST(BvhTest, TransmittanceMultipliesEverySurfaceCrossed) {
  Scene scene;
  Material glass;
  glass.transmissivity = 0.5;
  scene.objects.push_back({SphereShape{{0, 0, 3}, 1}, glass});   // crossed twice
  scene.objects.push_back({BoxShape{{-1, -1, 6}, {1, 1, 7}}, glass});  // crossed twice
  scene.objects.push_back({PlaneShape{{0, 0, 9}, {0, 0, -1}}, Material{}});  // opaque, further
  const World world(scene);
  const Ray ray{{0, 0, 0}, {0, 0, 1}};
  EXPECT_DOUBLE_EQ(world.transmittance(ray, 0, 5), 0.25);
  EXPECT_DOUBLE_EQ(world.transmittance(ray, 0, 8), 0.0625);
  EXPECT_DOUBLE_EQ(world.transmittance(ray, 0, 10), 0.0);
  // From behind, the one-sided plane lets light through.
  EXPECT_DOUBLE_EQ(world.transmittance(Ray{{0, 0, 20}, {0, 0, -1}}, 0, 10.5), 1.0);
}

// visitOrder(octant) is the order traverse() visits items in when every box is hit: here all
// boxes contain the ray's origin, for rays of each octant (including -0 components).
TEST(BvhTest, VisitOrderIsTheTraversalOrder) {
  Rng rng(21);
  std::vector<Bounds> boxes;
  for (int i = 0; i < 60; ++i) {
    const Vec3 c(rng.uniform() * 10 - 5, rng.uniform() * 10 - 5, rng.uniform() * 10 - 5);
    Bounds b;
    b.extend(Vec3(-0.1));  // the origin strictly inside
    b.extend(Vec3(0.1));
    b.extend(c);
    b.extend(c * 0.5 + Vec3(rng.uniform(), rng.uniform(), rng.uniform()));
    boxes.push_back(b);
  }
  const Bvh bvh(boxes);
  for (int i = 0; i < 200; ++i) {
    Vec3 d(rng.uniform() - 0.5, rng.uniform() - 0.5, rng.uniform() - 0.5);
    if (i % 10 == 0) d.y = -0.0;
    d = normalize(d);
    const int octant = (d.x < 0 ? 1 : 0) | (d.y < 0 ? 2 : 0) | (d.z < 0 ? 4 : 0);
    std::vector<uint32_t> visited;
    bvh.traverse(RayQuery(Ray{{0, 0, 0}, d}), 0, 1e30, [&](uint32_t item) {
      visited.push_back(item);
      return 1e30;
    });
    EXPECT_EQ(visited, bvh.visitOrder(octant)) << "ray " << i;
  }
}

}  // namespace
}  // namespace prt
