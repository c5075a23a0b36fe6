#include "trace/mesh_bvh.h"

#include <gtest/gtest.h>

#include <cmath>

#include "core/rng.h"

namespace prt {
namespace {

// An n x n grid of unit squares in the plane z = 0, two triangles each, counter-clockwise
// seen from +z.
std::shared_ptr<TriangleMesh> grid(int n) {
  auto mesh = std::make_shared<TriangleMesh>();
  for (int y = 0; y <= n; ++y) {
    for (int x = 0; x <= n; ++x) mesh->vertices.push_back({double(x), double(y), 0});
  }
  auto at = [&](int x, int y) { return static_cast<uint32_t>(y * (n + 1) + x); };
  for (int y = 0; y < n; ++y) {
    for (int x = 0; x < n; ++x) {
      mesh->triangles.push_back({at(x, y), at(x + 1, y), at(x + 1, y + 1)});
      mesh->triangles.push_back({at(x, y), at(x + 1, y + 1), at(x, y + 1)});
    }
  }
  return mesh;
}

// The closed cube [-1, 1]^3, twelve triangles wound outwards.
std::shared_ptr<TriangleMesh> cube() {
  auto mesh = std::make_shared<TriangleMesh>();
  for (int i = 0; i < 8; ++i) {
    mesh->vertices.push_back({(i & 1) ? 1.0 : -1.0, (i & 2) ? 1.0 : -1.0, (i & 4) ? 1.0 : -1.0});
  }
  const uint32_t quads[6][4] = {{0, 2, 3, 1}, {4, 5, 7, 6}, {0, 1, 5, 4},
                                {2, 6, 7, 3}, {0, 4, 6, 2}, {1, 3, 7, 5}};
  for (const auto& q : quads) {
    mesh->triangles.push_back({q[0], q[1], q[2]});
    mesh->triangles.push_back({q[0], q[2], q[3]});
  }
  return mesh;
}

std::shared_ptr<TriangleMesh> randomSoup(int count, uint64_t seed) {
  Rng rng(seed);
  auto mesh = std::make_shared<TriangleMesh>();
  for (int i = 0; i < count; ++i) {
    const Vec3 c(rng.uniform() * 20 - 10, rng.uniform() * 20 - 10, rng.uniform() * 20 - 10);
    for (int k = 0; k < 3; ++k) {
      mesh->vertices.push_back(c + Vec3(rng.uniform() * 3, rng.uniform() * 3, rng.uniform() * 3));
    }
    const auto first = static_cast<uint32_t>(3 * i);
    mesh->triangles.push_back({first, first + 1, first + 2});
  }
  return mesh;
}

Ray randomBvhRay(Rng& rng) {
  const Vec3 o(rng.uniform() * 30 - 15, rng.uniform() * 30 - 15, rng.uniform() * 30 - 15);
  const Vec3 d(rng.uniform() - 0.5, rng.uniform() - 0.5, rng.uniform() - 0.5);
  return {o, normalize(d)};
}

// Rays aimed exactly at the grid's shared edges and vertices (where a test that is not
// watertight lets some through) all meet it, from either side and at slants.
TEST(MeshBvhTest, NoRaySlipsThroughSharedEdgesOrVertices) {
  const MeshBvh mesh(grid(6));
  Rng rng(11);
  for (int i = 0; i < 4000; ++i) {
    const double k = 1 + std::floor(rng.uniform() * 5);  // an inner grid line, 1 to 5
    const double s = rng.uniform() * 6;
    // On the diagonal of square (a, b), shared by its two triangles.
    const double a = std::floor(rng.uniform() * 6), b = std::floor(rng.uniform() * 6);
    const double f = rng.uniform();
    const Vec3 targets[4] = {{k, s, 0},
                             {s, k, 0},
                             {a + f, b + f, 0},
                             {k, 1 + std::floor(rng.uniform() * 5), 0}};  // a vertex
    const Vec3 target = targets[i % 4];
    const Vec3 offset(rng.uniform() * 4 - 2, rng.uniform() * 4 - 2, i % 2 ? 3.0 : -3.0);
    const Ray ray{target + offset, normalize(-offset)};
    double t = 1e30;
    uint32_t triangle = 0;
    EXPECT_TRUE(mesh.nearest(ray, 0, t, triangle)) << "ray at " << target.x << " " << target.y;
  }
}

// The nearest crossing is the least (distance, index) over every triangle, whatever the tree.
TEST(MeshBvhTest, NearestMatchesEveryTriangleTriedInTurn) {
  const auto soup = randomSoup(3000, 5);
  // A copy of triangle 7 later in the list: the tie goes to 7.
  soup->triangles.push_back(soup->triangles[7]);
  const MeshBvh mesh(soup);
  Rng rng(2);
  int hits = 0;
  for (int i = 0; i < 2000; ++i) {
    Ray ray = randomBvhRay(rng);
    if (i % 10 == 0) {  // straight at triangle 7's centre
      const auto& t = soup->triangles[7];
      const Vec3 centre =
          (soup->vertices[t[0]] + soup->vertices[t[1]] + soup->vertices[t[2]]) / 3.0;
      ray.direction = normalize(centre - ray.origin);
    }
    const ShearedRay sheared(ray);
    double expected = 1e30;
    uint32_t expectedTriangle = ~0u;
    for (uint32_t k = 0; k < soup->triangles.size(); ++k) {
      const auto& t = soup->triangles[k];
      const TriangleHit h =
          triangleHit(sheared, soup->vertices[t[0]], soup->vertices[t[1]], soup->vertices[t[2]]);
      if (h.hit && h.t > 0 && h.t < expected) {
        expected = h.t;
        expectedTriangle = k;
      }
    }
    double t = 1e30;
    uint32_t triangle = ~0u;
    const bool hit = mesh.nearest(ray, 0, t, triangle);
    EXPECT_EQ(hit, expectedTriangle != ~0u);
    if (hit) {
      ++hits;
      EXPECT_EQ(t, expected);
      EXPECT_EQ(triangle, expectedTriangle);
    }
  }
  EXPECT_GT(hits, 200);
}

// A closed mesh is crossed an odd number of times from inside, an even number from outside.
TEST(MeshBvhTest, RaysFromInsideAClosedMeshCrossItOnce) {
  const MeshBvh mesh(cube());
  Rng rng(9);
  for (int i = 0; i < 1000; ++i) {
    const Vec3 inside(rng.uniform() * 1.8 - 0.9, rng.uniform() * 1.8 - 0.9,
                      rng.uniform() * 1.8 - 0.9);
    const Ray ray{inside,
                  normalize(Vec3(rng.uniform() - 0.5, rng.uniform() - 0.5, rng.uniform() - 0.5))};
    EXPECT_EQ(mesh.crossings(ray, 0, 100), 1);
    const Ray outside{inside + 10.0 * ray.direction, -ray.direction};
    EXPECT_EQ(mesh.crossings(outside, 0, 100), 2);
    EXPECT_EQ(mesh.crossings(outside, 0, 100, true), 1);  // any crossing: the first will do
    EXPECT_EQ(mesh.crossings(outside, 0, 5), 0);          // stops short of the cube
  }
}

TEST(MeshBvhTest, NormalsFollowTheWindingOrTheVertexNormals) {
  const MeshBvh flat(grid(1));
  const Ray down{{0.3, 0.6, 2}, {0, 0, -1}};
  double t = 1e30;
  uint32_t triangle = 0;
  ASSERT_TRUE(flat.nearest(down, 0, t, triangle));
  EXPECT_EQ(t, 2.0);
  EXPECT_EQ(flat.normal(down, triangle), Vec3(0, 0, 1));

  auto tilted = grid(1);
  const Vec3 n = normalize(Vec3(0.3, 0, 1));
  tilted->normals.assign(tilted->vertices.size(), n);
  const MeshBvh smooth(tilted);
  const Vec3 blended = smooth.normal(down, triangle);
  for (int axis = 0; axis < 3; ++axis) EXPECT_NEAR(blended[axis], n[axis], 1e-15);
  // A vertex normal on the far side of the ray from the geometric one is not used.
  const Ray grazing{{-2.5, 0.6, 0.3}, normalize(Vec3(1, 0, -0.1))};
  t = 1e30;
  ASSERT_TRUE(smooth.nearest(grazing, 0, t, triangle));
  EXPECT_EQ(smooth.normal(grazing, triangle), Vec3(0, 0, 1));
}

// Boxes all alike (every centroid the same) still build a tree of bounded depth that finds
// every triangle.
TEST(MeshBvhTest, CoincidentTrianglesBuildAShallowTree) {
  auto mesh = std::make_shared<TriangleMesh>();
  mesh->vertices = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
  mesh->triangles.assign(5000, {0, 1, 2});
  const MeshBvh bvh(mesh);
  double t = 1e30;
  uint32_t triangle = ~0u;
  ASSERT_TRUE(bvh.nearest({{0.2, 0.2, 1}, {0, 0, -1}}, 0, t, triangle));
  EXPECT_EQ(triangle, 0u);
  EXPECT_EQ(bvh.crossings({{0.2, 0.2, 1}, {0, 0, -1}}, 0, 2), 5000);
}

// Meshes of a few triangles (one block, or a root node of a few blocks) answer as every
// triangle tried in turn does: the nearest crossing and the count of crossings.
TEST(MeshBvhTest, SmallMeshesMatchEveryTriangleTriedInTurn) {
  int hits = 0;
  for (int count = 1; count <= 9; ++count) {
    const auto soup = randomSoup(count, static_cast<uint64_t>(40 + count));
    const MeshBvh mesh(soup);
    EXPECT_EQ(mesh.triangleCount(), static_cast<size_t>(count));
    Rng rng(static_cast<uint64_t>(count));
    for (int i = 0; i < 300; ++i) {
      Ray ray = randomBvhRay(rng);
      const auto& aim = soup->triangles[static_cast<size_t>(i % count)];
      ray.direction = normalize(soup->vertices[aim[i % 3]] * 0.5 +
                                soup->vertices[aim[(i + 1) % 3]] * 0.5 - ray.origin);
      const ShearedRay sheared(ray);
      double expected = 1e30;
      uint32_t expectedTriangle = ~0u;
      int crossed = 0;
      for (uint32_t k = 0; k < soup->triangles.size(); ++k) {
        const auto& t = soup->triangles[k];
        const TriangleHit h = triangleHit(sheared, soup->vertices[t[0]], soup->vertices[t[1]],
                                          soup->vertices[t[2]]);
        if (!h.hit || !(h.t > 0)) continue;
        if (h.t < 1e30) ++crossed;
        if (h.t < expected) {
          expected = h.t;
          expectedTriangle = k;
        }
      }
      double t = 1e30;
      uint32_t triangle = ~0u;
      ASSERT_EQ(mesh.nearest(ray, 0, t, triangle), expectedTriangle != ~0u);
      if (expectedTriangle != ~0u) {
        ++hits;
        EXPECT_EQ(t, expected);
        EXPECT_EQ(triangle, expectedTriangle);
      }
      EXPECT_EQ(mesh.crossings(ray, 0, 1e30), crossed);
      EXPECT_EQ(mesh.crossings(ray, 0, 1e30, true), crossed > 0 ? 1 : 0);
    }
  }
  EXPECT_GT(hits, 1000);  // the rays aim at edges' midpoints, half of them just inside
}

}  // namespace
}  // namespace prt
