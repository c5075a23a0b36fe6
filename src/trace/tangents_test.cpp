#include "trace/tangents.h"

#include <gtest/gtest.h>

#include <cmath>

namespace prt {
namespace {

// A 2 x 1 quad in the z = 0 plane facing +z, its texture coordinates given per corner in the
// order (0, 0, 0), (2, 0, 0), (2, 1, 0), (0, 1, 0).
TriangleMesh quad(std::array<std::array<float, 2>, 4> uvs, bool normals = true) {
  TriangleMesh m;
  m.vertices = {{0, 0, 0}, {2, 0, 0}, {2, 1, 0}, {0, 1, 0}};
  m.triangles = {{0, 1, 2}, {0, 2, 3}};
  if (normals) m.normals.assign(4, Vec3(0, 0, 1));
  m.uvs.assign(uvs.begin(), uvs.end());
  return m;
}

void expectTangent(const std::array<double, 4>& t, const Vec3& xyz, double w) {
  EXPECT_NEAR(t[0], xyz.x, 1e-12);
  EXPECT_NEAR(t[1], xyz.y, 1e-12);
  EXPECT_NEAR(t[2], xyz.z, 1e-12);
  EXPECT_EQ(t[3], w);
}

// glTF's v runs down the image: the image's bottom-left corner (u, v) = (0, 1) at the quad's
// origin. The tangent runs along x (u grows), the bitangent cross(+z, +x) = +y is where v
// falls (up the image): handedness +1.
TEST(Tangents, AQuadMappedAsDrawnRunsAlongU) {
  const auto t = computeTangents(quad({{{0, 1}, {1, 1}, {1, 0}, {0, 0}}}));
  ASSERT_EQ(t.size(), 4u);
  for (const auto& v : t) expectTangent(v, {1, 0, 0}, 1);
}

// The image mirrored left to right: u grows along -x, and the bitangent is -cross(+z, -x).
TEST(Tangents, AMirroredMappingTurnsTheHandedness) {
  const auto t = computeTangents(quad({{{1, 1}, {0, 1}, {0, 0}, {1, 0}}}));
  ASSERT_EQ(t.size(), 4u);
  for (const auto& v : t) expectTangent(v, {-1, 0, 0}, -1);
}

// The image turned a quarter: u grows along +y (v along +x), any scale; and without vertex
// normals the faces' own are used.
TEST(Tangents, ARotatedMappingAndFlatFaces) {
  for (const bool normals : {true, false}) {
    const auto t = computeTangents(quad({{{0, 0}, {0, 3}, {0.5f, 3}, {0.5f, 0}}}, normals));
    ASSERT_EQ(t.size(), 4u);
    // u along +y; v grows along +x, so falls along -x = w cross(+z, +y) = -w x: w = +1.
    for (const auto& v : t) expectTangent(v, {0, 1, 0}, 1);
  }
}

// Tangents are made perpendicular to each vertex's normal, and a vertex whose triangles have
// no texture area gets none; a mesh without texture coordinates gets none at all.
TEST(Tangents, PerpendicularToTheNormalsAndZeroWithoutAMapping) {
  TriangleMesh m = quad({{{0, 1}, {1, 1}, {1, 0}, {0, 0}}});
  const Vec3 tilted = normalize(Vec3(1, 0, 1));
  m.normals[1] = tilted;
  const auto t = computeTangents(m);
  EXPECT_NEAR(std::fabs(t[1][0] * tilted.x + t[1][1] * tilted.y + t[1][2] * tilted.z), 0, 1e-15);
  EXPECT_NEAR(t[1][0] * t[1][0] + t[1][1] * t[1][1] + t[1][2] * t[1][2], 1, 1e-15);
  TriangleMesh flat = quad({{{0.5f, 0.5f}, {0.5f, 0.5f}, {0.5f, 0.5f}, {0.5f, 0.5f}}});
  for (const auto& v : computeTangents(flat)) expectTangent(v, {0, 0, 0}, 1);
  flat.uvs.clear();
  EXPECT_TRUE(computeTangents(flat).empty());
}

}  // namespace
}  // namespace prt
