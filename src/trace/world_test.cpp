#include "trace/world.h"

#include <gtest/gtest.h>

#include "core/rng.h"
#include "trace/bvh.h"
#include "trace/light_sampling.h"
#include "trace/shapes.h"

namespace prt {
namespace {

// The queries as World answered them before the four-way float BVH: the binary Bvh's
// traversal order, the paper's per-object box test, then the shape. World must match it bit
// for bit.
class ReferenceWorld {
 public:
  explicit ReferenceWorld(const Scene& scene) : scene_(scene) {
    for (uint32_t i = 0; i < scene.objects.size(); ++i) {
      if (isBounded(scene.objects[i].shape)) {
        bounded_.push_back(i);
        boxes_.push_back(boundsOf(scene.objects[i].shape));
      } else {
        unbounded_.push_back(i);
      }
    }
    bvh_ = Bvh(boxes_);
  }

  bool intersect(const Ray& ray, double tMin, double tMax, Hit& hit) const {
    bool found = false;
    auto consider = [&](uint32_t object) {
      const Crossings c = crossings(object, ray, tMin, tMax);
      if (c.count > 0) {
        tMax = c.t[0];
        hit.t = c.t[0];
        hit.normal = c.normal[0];
        hit.object = object;
        found = true;
      }
    };
    for (uint32_t object : unbounded_) consider(object);
    const RayQuery q(ray);
    bvh_.traverse(q, tMin, tMax, [&](uint32_t item) {
      if (hitsBounds(boxes_[item], q, tMin, tMax)) consider(bounded_[item]);
      return tMax;
    });
    if (found) hit.point = ray.at(hit.t);
    return found;
  }

  double transmittance(const Ray& ray, double tMin, double distance) const {
    double passed = 1.0;
    auto attenuate = [&](uint32_t object) {
      const Crossings c = crossings(object, ray, tMin, distance);
      const double k = scene_.objects[object].material.transmissivity;
      for (int i = 0; i < c.count && passed > 0; ++i) passed *= k;
    };
    for (uint32_t object : unbounded_) {
      attenuate(object);
      if (passed == 0) return 0;
    }
    const RayQuery q(ray);
    bvh_.traverse(q, tMin, distance, [&](uint32_t item) {
      if (hitsBounds(boxes_[item], q, tMin, distance)) attenuate(bounded_[item]);
      return passed == 0 ? -1.0 : distance;
    });
    return passed;
  }

 private:
  Crossings crossings(uint32_t object, const Ray& ray, double tMin, double tMax) const {
    return std::visit([&](const auto& s) { return prt::intersect(s, ray, tMin, tMax); },
                      scene_.objects[object].shape);
  }

  const Scene& scene_;
  Bvh bvh_;
  std::vector<uint32_t> bounded_, unbounded_;
  std::vector<Bounds> boxes_;
};

// Glassy spheres and boxes of several transmissivities (so products of several factors
// occur), some touching or coincident (so equal distances occur), a floor and a wall.
Scene testScene(uint64_t seed, int count) {
  Scene scene;
  Rng rng(seed);
  const double kinds[] = {0.0, 0.5, 0.9, 0.85, 0.3};
  for (int i = 0; i < count; ++i) {
    Material m;
    m.transmissivity = kinds[i % 5];
    const Vec3 c(std::floor(rng.uniform() * 8) - 4, std::floor(rng.uniform() * 4),
                 std::floor(rng.uniform() * 8) - 4);
    if (i % 3 == 0) {
      scene.objects.push_back({BoxShape{c, c + Vec3(1, 1 + std::floor(rng.uniform() * 2), 1)}, m});
    } else {
      scene.objects.push_back({SphereShape{c + Vec3(0.5), 0.5}, m});  // touch their neighbours
    }
    if (i % 17 == 0) scene.objects.push_back(scene.objects.back());  // coincident duplicates
  }
  scene.objects.push_back({PlaneShape{{0, 0, 0}, {0, 1, 0}}, Material{}});
  Material glass;
  glass.transmissivity = 0.7;
  scene.objects.push_back({PlaneShape{{0, 0, 6}, {0, 0, -1}}, glass});
  return scene;
}

Ray randomRay(Rng& rng) {
  // Origins on the lattice the objects sit on, half the time: rays through shared faces.
  Vec3 o(rng.uniform() * 12 - 6, rng.uniform() * 6 + 0.01, rng.uniform() * 12 - 6);
  if (rng.uniform() < 0.3) o = Vec3(std::floor(o.x), std::floor(o.y) + 0.5, std::floor(o.z));
  Vec3 d(rng.uniform() - 0.5, rng.uniform() - 0.5, rng.uniform() - 0.5);
  const double u = rng.uniform();
  if (u < 0.1) d = Vec3(d.x, 0, 0);  // along the lattice
  if (u > 0.9) d.z = -0.0;
  if (d.x == 0 && d.y == 0 && d.z == 0) d.x = 1;
  return {o, normalize(d)};
}

// Compares every answer on `rays` rays from makeRay(rng); returns how often each object was
// the nearest hit.
template <typename MakeRay>
std::vector<int> expectSameAnswers(const Scene& scene, uint64_t seed, int rays, MakeRay makeRay) {
  const World world(scene);
  const ReferenceWorld reference(scene);
  Rng rng(seed);
  std::vector<int> nearest(scene.objects.size());
  int hits = 0, partial = 0;
  for (int i = 0; i < rays; ++i) {
    const Ray ray = makeRay(rng);
    const double tMax = rng.uniform() < 0.5 ? std::numeric_limits<double>::infinity() : 5;
    Hit a, b;
    const bool found = world.intersect(ray, 0, tMax, a);
    EXPECT_EQ(found, reference.intersect(ray, 0, tMax, b)) << "ray " << i;
    if (found && found == reference.intersect(ray, 0, tMax, b)) {
      ++hits;
      ++nearest[a.object];
      EXPECT_EQ(a.object, b.object) << "ray " << i;
      EXPECT_EQ(a.t, b.t);
      EXPECT_EQ(a.normal, b.normal);
      EXPECT_EQ(a.point, b.point);
    }
    const double distance = rng.uniform() * 15;
    const double passed = world.transmittance(ray, 0, distance);
    EXPECT_EQ(passed, reference.transmittance(ray, 0, distance)) << "ray " << i;
    if (passed > 0 && passed < 1) ++partial;
  }
  EXPECT_GT(hits, rays / 10);
  EXPECT_GT(partial, rays / 20);
  return nearest;
}

TEST(WorldTest, MatchesTheReferenceBitForBit) {
  expectSameAnswers(testScene(1, 20), 2, 20000, randomRay);   // built bottom-up
  expectSameAnswers(testScene(3, 300), 4, 20000, randomRay);  // built top-down, then bottom-up
}

TEST(WorldTest, EqualDistancesFollowTheReferenceOrder) {
  // Boxes sharing faces in pairs, in separate BVH leaves, and spheres tangent to them: every
  // tie is decided by the order, which depends on the ray's direction.
  Scene scene;
  Material glass;
  glass.transmissivity = 0.5;
  for (int i = 0; i < 4; ++i) {
    const Vec3 c(3.0 * i, 0, 0);
    scene.objects.push_back({BoxShape{c, c + Vec3(1, 1, 1)}, glass});
    scene.objects.push_back({BoxShape{c - Vec3(1, 0, 0), c + Vec3(1, 1, 2)}, glass});
    scene.objects.push_back({SphereShape{c + Vec3(0.5, 1.5, 0.5), 0.5}, glass});
  }
  // Rays from all around aimed at the shared faces and the tangent points.
  const std::vector<int> nearest = expectSameAnswers(scene, 9, 20000, [](Rng& rng) {
    const Vec3 o(rng.uniform() * 20 - 5, rng.uniform() * 10 - 5, rng.uniform() * 10 - 5);
    const Vec3 target(3.0 * std::floor(rng.uniform() * 4) + rng.uniform(),
                      rng.uniform() < 0.5 ? 1 : rng.uniform(), rng.uniform() < 0.5 ? 0 : 1);
    return Ray{o, normalize(target - o)};
  });
  int first = 0, second = 0;
  for (int i = 0; i < 4; ++i) {
    first += nearest[3 * i];
    second += nearest[3 * i + 1];
  }
  EXPECT_GT(first, 100);
  EXPECT_GT(second, 100);
}

TEST(WorldTest, RaysFromInsideAnObjectMatchTheBvh) {
  // Rays that enter an object where a random ray hits it, as the shader spawns them: just
  // inside the surface, refracted inwards or reflected back inside. The objects overlap and
  // duplicate one another, so other surfaces lie inside some of them.
  const Scene scene = testScene(7, 80);
  const World world(scene);
  Rng rng(31);
  int inside = 0;
  for (int i = 0; i < 30000; ++i) {
    const Ray probe = randomRay(rng);
    Hit entry;
    if (!world.intersect(probe, 0, std::numeric_limits<double>::infinity(), entry)) continue;
    if (std::holds_alternative<PlaneShape>(scene.objects[entry.object].shape)) continue;
    const bool entering = dot(probe.direction, entry.normal) < 0;
    const Vec3 n = entering ? entry.normal : -entry.normal;  // faces the probe
    // Into the object across the surface, a direction perturbed about the inward normal.
    const Vec3 origin = entry.point - 1e-9 * n * (entering ? 1.0 : -1.0);
    Vec3 d = (entering ? -n : n) + 0.9 * Vec3(rng.uniform() - 0.5, rng.uniform() - 0.5,
                                              rng.uniform() - 0.5);
    if (dot(d, entering ? -n : n) <= 0) d = entering ? -n : n;
    const Ray ray{origin, normalize(d)};
    Hit a, b;
    const bool found = world.intersect(ray, 0, std::numeric_limits<double>::infinity(), a);
    ASSERT_EQ(world.intersectFromInside(entry.object, ray, b), found) << "ray " << i;
    if (!found) continue;
    ++inside;
    EXPECT_EQ(a.object, b.object) << "ray " << i;
    EXPECT_EQ(a.t, b.t);
    EXPECT_EQ(a.normal, b.normal);
    EXPECT_EQ(a.point, b.point);
  }
  EXPECT_GT(inside, 5000);
}

// A shadow ray from `origin` to a point of `light` sampled as the shader samples it, and the
// distance to that point.
struct ShadowRay {
  Ray ray;
  double distance;
};
ShadowRay towardsLight(const Light& light, const Vec3& origin, Rng& rng) {
  const Vec3 toLight = aimAt(light.shape, origin, 0, 1, rng) - origin;
  const double distance = length(toLight);
  return {Ray{origin, toLight / distance}, distance};
}

Scene litTestScene() {
  Scene scene = testScene(5, 60);
  scene.lights.push_back({PointLight{{1, 9, -2}}});
  scene.lights.push_back({SphereLight{{-3, 6, 3}, 0.8}});
  scene.lights.push_back({RectLight{{4, 3, -1}, {0, 0, 2}, {0, 1.5, 0}}});
  return scene;
}

TEST(WorldTest, ShadowRaysTowardsALightMatchTheReference) {
  const Scene scene = litTestScene();
  const World world(scene);
  const ReferenceWorld reference(scene);
  Rng rng(21);
  int partial = 0, blocked = 0;
  for (int i = 0; i < 30000; ++i) {
    // From a point of space or, as the shader does, just off a surface the ray hit.
    Vec3 origin(rng.uniform() * 12 - 6, rng.uniform() * 6 + 0.01, rng.uniform() * 12 - 6);
    Hit hit;
    const Ray probe = randomRay(rng);
    if (rng.uniform() < 0.6 && world.intersect(probe, 0, 1e9, hit)) {
      const Vec3 n = dot(probe.direction, hit.normal) < 0 ? hit.normal : -hit.normal;
      origin = hit.point + 1e-9 * n;
    }
    const size_t l = i % scene.lights.size();
    const auto [ray, distance] = towardsLight(scene.lights[l], origin, rng);
    const double passed = world.transmittanceToLight(l, ray, distance);
    ASSERT_EQ(passed, reference.transmittance(ray, 0, distance)) << "ray " << i;
    ASSERT_EQ(passed, world.transmittance(ray, 0, distance)) << "ray " << i;
    partial += passed > 0 && passed < 1;
    blocked += passed == 0;
  }
  EXPECT_GT(partial, 1000);
  EXPECT_GT(blocked, 1000);
}

TEST(WorldTest, ShadowRaysFromFarAwayMatchTheReference) {
  // From the floor far from the objects, outside the shadow shafts' grid: rays that pass over
  // or beside every object's box, and rays that cross the objects' region.
  const Scene scene = litTestScene();
  const World world(scene);
  const ReferenceWorld reference(scene);
  Bounds objects;
  for (const Bounds& b : world.itemBounds()) objects.extend(b);
  Rng rng(22);
  int clear = 0, across = 0;
  for (int i = 0; i < 20000; ++i) {
    const double angle = rng.uniform() * 6.283, reach = 8 + rng.uniform() * 40;
    const Vec3 origin(reach * std::cos(angle), 1e-9, reach * std::sin(angle));
    const size_t l = i % scene.lights.size();
    const auto [ray, distance] = towardsLight(scene.lights[l], origin, rng);
    const double passed = world.transmittanceToLight(l, ray, distance);
    ASSERT_EQ(passed, reference.transmittance(ray, 0, distance)) << "ray " << i;
    const bool crosses = hitsBounds(objects, RayQuery(ray), 0, distance);
    clear += !crosses;
    across += crosses && passed < 1;
  }
  EXPECT_GT(clear, 5000);
  EXPECT_GT(across, 1000);
}

}  // namespace
}  // namespace prt
