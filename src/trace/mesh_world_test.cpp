// Meshes among the other objects of a World: the nearest hit, shadow rays and rays from
// inside agree with every object tried in turn.

#include <gtest/gtest.h>

#include <cmath>

#include "core/rng.h"
#include "trace/shapes.h"
#include "trace/world.h"

namespace prt {
namespace {

// A torus of tube radius `tube` around the y axis at radius 1 (not convex: a ray from inside
// its tube may leave it and enter it again), wound outwards.
std::shared_ptr<TriangleMesh> torus(const Vec3& centre, double tube, int around, int sides) {
  auto mesh = std::make_shared<TriangleMesh>();
  for (int i = 0; i < around; ++i) {
    const double u = 2 * M_PI * i / around;
    for (int j = 0; j < sides; ++j) {
      const double v = 2 * M_PI * j / sides;
      const double r = 1 + tube * std::cos(v);
      mesh->vertices.push_back(centre + Vec3(r * std::cos(u), tube * std::sin(v), r * std::sin(u)));
    }
  }
  auto at = [&](int i, int j) { return static_cast<uint32_t>((i % around) * sides + (j % sides)); };
  for (int i = 0; i < around; ++i) {
    for (int j = 0; j < sides; ++j) {
      mesh->triangles.push_back({at(i, j), at(i, j + 1), at(i + 1, j + 1)});
      mesh->triangles.push_back({at(i, j), at(i + 1, j + 1), at(i + 1, j)});
    }
  }
  return mesh;
}

Scene meshScene() {
  Scene scene;
  Material glass;
  glass.transmissivity = 0.7;
  Material opaque;
  scene.objects.push_back({MeshShape{torus({0, 1, 0}, 0.35, 40, 16), {}}, glass});
  scene.objects.push_back({SphereShape{{2, 1, 0.5}, 0.6}, glass});
  scene.objects.push_back({MeshShape{torus({-2.4, 0.3, -1.5}, 0.25, 24, 10), {}}, opaque});
  scene.objects.push_back({BoxShape{{-3, 0, 2}, {3, 2, 2.5}}, opaque});
  scene.objects.push_back({PlaneShape{{0, 0, 0}, {0, 1, 0}}, opaque});
  scene.lights.push_back({PointLight{{0, 6, -3}}, {1, 1, 1}});
  return scene;
}

Crossings crossingsOf(const Object& o, const Ray& ray, double tMin, double tMax) {
  return std::visit([&](const auto& s) { return intersect(s, ray, tMin, tMax); }, o.shape);
}

// How many times the ray crosses the object within (tMin, tMax).
int countCrossings(const Object& o, const Ray& ray, double tMin, double tMax) {
  if (const auto* m = std::get_if<MeshShape>(&o.shape)) {
    const ShearedRay sheared(ray);
    int n = 0;
    for (const auto& t : m->mesh->triangles) {
      const TriangleHit h = triangleHit(sheared, m->mesh->vertices[t[0]], m->mesh->vertices[t[1]],
                                        m->mesh->vertices[t[2]]);
      n += h.hit && h.t > tMin && h.t < tMax;
    }
    return n;
  }
  return crossingsOf(o, ray, tMin, tMax).count;
}

Ray randomMeshRay(Rng& rng) {
  const Vec3 o(rng.uniform() * 8 - 4, rng.uniform() * 3 + 0.05, rng.uniform() * 8 - 5);
  const Vec3 target(rng.uniform() * 4 - 2, rng.uniform() * 2, rng.uniform() * 3 - 1);
  return {o, normalize(target - o)};
}

TEST(MeshWorldTest, NearestHitIsTheNearestOfEveryObject) {
  const Scene scene = meshScene();
  const World world(scene);
  EXPECT_EQ(world.meshStats().meshes, 2u);
  EXPECT_EQ(world.meshStats().triangles, 2u * 40 * 16 + 2u * 24 * 10);
  Rng rng(4);
  int meshHits = 0;
  for (int i = 0; i < 3000; ++i) {
    const Ray ray = randomMeshRay(rng);
    double best = std::numeric_limits<double>::infinity();
    int bestObject = -1;
    for (uint32_t k = 0; k < scene.objects.size(); ++k) {
      const Crossings c = crossingsOf(scene.objects[k], ray, 0, best);
      if (c.count > 0 && c.t[0] < best) {
        best = c.t[0];
        bestObject = static_cast<int>(k);
      }
    }
    Hit hit;
    const bool found = world.intersect(ray, 0, std::numeric_limits<double>::infinity(), hit);
    ASSERT_EQ(found, bestObject >= 0) << "ray " << i;
    if (!found) continue;
    EXPECT_EQ(hit.t, best) << "ray " << i;
    EXPECT_EQ(hit.object, static_cast<uint32_t>(bestObject)) << "ray " << i;
    if (std::holds_alternative<MeshShape>(scene.objects[hit.object].shape)) {
      ++meshHits;
      EXPECT_NEAR(length(hit.normal), 1, 1e-12);
    }
  }
  EXPECT_GT(meshHits, 300);
}

TEST(MeshWorldTest, ShadowRaysAreDimmedOncePerTriangleCrossed) {
  const Scene scene = meshScene();
  const World world(scene);
  Rng rng(8);
  int dimmed = 0;
  for (int i = 0; i < 3000; ++i) {
    const Ray ray = randomMeshRay(rng);
    const double distance = 1 + rng.uniform() * 8;
    double expected = 1;
    for (const Object& o : scene.objects) {
      const int n = countCrossings(o, ray, 0, distance);
      for (int k = 0; k < n; ++k) expected *= o.material.transmissivity;
    }
    const double passed = world.transmittance(ray, 0, distance);
    EXPECT_NEAR(passed, expected, 1e-12) << "ray " << i;
    // Answered from the light's shadow shafts or the tree, the same.
    const Ray toLight{ray.origin, normalize(Vec3(0, 6, -3) - ray.origin)};
    const double d = length(Vec3(0, 6, -3) - ray.origin);
    EXPECT_EQ(world.transmittanceToLight(0, toLight, d), world.transmittance(toLight, 0, d));
    dimmed += passed > 0 && passed < 1;
  }
  EXPECT_GT(dimmed, 200);
}

// Rays refracted into the torus's tube start inside it; the tube curves away and back, so the
// first surface met may be the same mesh again farther round.
TEST(MeshWorldTest, RaysFromInsideANonConvexMeshMatchTheTree) {
  const Scene scene = meshScene();
  const World world(scene);
  Rng rng(12);
  for (int i = 0; i < 2000; ++i) {
    const double u = rng.uniform() * 2 * M_PI, v = rng.uniform() * 2 * M_PI;
    const double r = 1 + 0.2 * std::cos(v);
    const Vec3 inside(r * std::cos(u), 1 + 0.2 * std::sin(v), r * std::sin(u));
    const Ray ray{inside,
                  normalize(Vec3(rng.uniform() - 0.5, rng.uniform() - 0.5, rng.uniform() - 0.5))};
    Hit a, b;
    const bool found = world.intersect(ray, 0, std::numeric_limits<double>::infinity(), a);
    ASSERT_EQ(world.intersectFromInside(0, ray, b), found);
    ASSERT_TRUE(found);
    EXPECT_EQ(a.t, b.t);
    EXPECT_EQ(a.object, b.object);
    EXPECT_EQ(a.normal, b.normal);
    EXPECT_GT(dot(a.normal, ray.direction), 0) << "leaves through the tube's inner side";
  }
}

}  // namespace
}  // namespace prt
