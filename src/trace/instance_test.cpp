// Meshes placed by instances: a mesh stored once and placed by transforms is met where the
// same mesh with its vertices moved would be, its normals face out (mirrored instances too),
// its tree is built once, and its texture coordinates and colours are interpolated at hits.

#include <gtest/gtest.h>

#include <cmath>

#include "core/rng.h"
#include "trace/shapes.h"
#include "trace/world.h"

namespace prt {
namespace {

// A closed octahedron of "radius" 1 around the origin, wound outwards, with a texture
// coordinate and a colour per vertex.
std::shared_ptr<TriangleMesh> octahedron() {
  auto m = std::make_shared<TriangleMesh>();
  m->vertices = {{1, 0, 0}, {-1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, 1}, {0, 0, -1}};
  m->triangles = {{0, 2, 4}, {2, 1, 4}, {1, 3, 4}, {3, 0, 4},
                  {2, 0, 5}, {1, 2, 5}, {3, 1, 5}, {0, 3, 5}};
  for (const Vec3& v : m->vertices) {
    m->uvs.push_back({static_cast<float>(0.5 + 0.5 * v.x), static_cast<float>(0.5 - 0.5 * v.y)});
    m->colors.push_back({static_cast<float>(0.5 + 0.5 * v.x), 0.25f, 1.0f});
  }
  return m;
}

Transform placement(double angle, const Vec3& scale, const Vec3& at) {
  return Transform::translation(at) * Transform::rotation(0, std::sin(angle / 2), 0, std::cos(angle / 2)) *
         Transform::scaling(scale);
}

// The same mesh with its vertices carried by the transform, in world space.
std::shared_ptr<TriangleMesh> moved(const TriangleMesh& mesh, const Transform& t) {
  auto m = std::make_shared<TriangleMesh>(mesh);
  for (Vec3& v : m->vertices) v = t.point(v);
  if (t.determinant() < 0) {
    for (auto& tri : m->triangles) std::swap(tri[1], tri[2]);
  }
  return m;
}

TEST(Instance, IsMetWhereTheMovedMeshIs) {
  const auto mesh = octahedron();
  const Transform placements[] = {placement(0.3, {1, 1, 1}, {0, 0, 3}),
                                  placement(1.1, {0.5, 2, 1.5}, {-2, 1, 4}),
                                  placement(-0.7, {-1, 1, 1}, {2, -1, 5})};  // a mirror
  Scene instanced, flat;
  for (const Transform& t : placements) {
    instanced.objects.push_back({InstanceShape{mesh, t}, Material{}});
    flat.objects.push_back({MeshShape{moved(*mesh, t), {}}, Material{}});
  }
  const World a(instanced), b(flat);
  EXPECT_EQ(a.meshStats().meshes, 1u);  // stored and built once
  EXPECT_EQ(a.meshStats().instances, 3u);
  Rng rng(7);
  int hits = 0;
  for (int i = 0; i < 4000; ++i) {
    const Vec3 origin(rng.uniform() * 8 - 4, rng.uniform() * 6 - 3, -3);
    const Vec3 target(rng.uniform() * 8 - 4, rng.uniform() * 6 - 3, 4);
    const Ray ray{origin, normalize(target - origin)};
    Hit ha, hb;
    const bool ga = a.intersect(ray, 0, 1e30, ha), gb = b.intersect(ray, 0, 1e30, hb);
    ASSERT_EQ(ga, gb) << i;
    if (!ga) continue;
    ++hits;
    EXPECT_EQ(ha.object, hb.object);
    EXPECT_NEAR(ha.t, hb.t, 1e-9);
    EXPECT_NEAR(dot(ha.normal, hb.normal), 1.0, 1e-9) << "normals face the same way";
    EXPECT_LT(dot(ha.normal, ray.direction), 0) << "met from outside: an outward normal";
    EXPECT_NEAR(a.transmittance(ray, 0, 1e30), b.transmittance(ray, 0, 1e30), 0);
  }
  EXPECT_GT(hits, 300);
}

TEST(Instance, AttributesAreInterpolatedAtTheHit) {
  Scene scene;
  scene.objects.push_back({InstanceShape{octahedron(), placement(0, {2, 2, 2}, {0, 0, 5})}, Material{}});
  const World world(scene);
  // Straight at the face around (1, 1, -1) / 3 of the placed octahedron, hit at its centroid.
  const Vec3 centroid = Vec3(0, 0, 5) + Vec3(2, 2, -2) / 3.0;
  const Ray ray{centroid - Vec3(0, 0, 4), {0, 0, 1}};
  Hit hit;
  ASSERT_TRUE(world.intersect(ray, 0, 1e30, hit));
  EXPECT_NEAR(hit.point.x, centroid.x, 1e-12);
  const SurfaceAttributes at = world.attributesAt(ray, hit);
  EXPECT_NEAR(at.u, 0.5 + 0.5 / 3, 1e-9);  // the mean of the corners' u: 1, 0.5, 0.5
  EXPECT_NEAR(at.v, 0.5 - 0.5 / 3, 1e-9);
  EXPECT_NEAR(at.color.x, 0.5 + 0.5 / 3, 1e-7);
  EXPECT_NEAR(at.color.y, 0.25, 1e-7);
}

TEST(Instance, ObjectsWithoutAttributesGetTheDefaults) {
  Scene scene;
  scene.objects.push_back({SphereShape{{0, 0, 5}, 1}, Material{}});
  const World world(scene);
  const Ray ray{{0, 0, 0}, {0, 0, 1}};
  Hit hit;
  ASSERT_TRUE(world.intersect(ray, 0, 1e30, hit));
  const SurfaceAttributes at = world.attributesAt(ray, hit);
  EXPECT_EQ(at.color, Color(1, 1, 1));
  EXPECT_EQ(at.u, 0.0);
}

}  // namespace
}  // namespace prt
