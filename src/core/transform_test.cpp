#include "core/transform.h"

#include <gtest/gtest.h>

#include <cmath>

namespace prt {
namespace {

void expectNear(const Vec3& a, const Vec3& b, double tolerance = 1e-12) {
  EXPECT_NEAR(a.x, b.x, tolerance);
  EXPECT_NEAR(a.y, b.y, tolerance);
  EXPECT_NEAR(a.z, b.z, tolerance);
}

TEST(Transform, ComposesFirstTheRightThenTheLeft) {
  const Transform t = Transform::translation({1, 2, 3}) * Transform::scaling({2, 2, 2});
  expectNear(t.point({1, 1, 1}), {3, 4, 5});
  expectNear(t.vector({1, 1, 1}), {2, 2, 2});
}

TEST(Transform, QuaternionTurnsAboutItsAxis) {
  // 90 degrees about +y: x goes to -z (right-handed).
  const double h = std::sqrt(0.5);
  const Transform r = Transform::rotation(0, h, 0, h);
  expectNear(r.point({1, 0, 0}), {0, 0, -1});
  expectNear(r.point({0, 0, 1}), {1, 0, 0});
  // An unnormalised quaternion is normalised first.
  expectNear(Transform::rotation(0, 2, 0, 2).point({1, 0, 0}), {0, 0, -1});
}

TEST(Transform, InverseUndoesIt) {
  const Transform t = Transform::translation({-4, 0.5, 7}) * Transform::rotation(0.1, 0.7, -0.2, 0.6) *
                      Transform::scaling({2, -3, 0.5});
  ASSERT_TRUE(t.isUsable());
  EXPECT_LT(t.determinant(), 0);  // one negative scale: a mirror
  const Transform back = t.inverse();
  expectNear(back.point(t.point({1, 2, 3})), {1, 2, 3}, 1e-12);
  expectNear((t * back).point({5, -6, 7}), {5, -6, 7}, 1e-11);
}

TEST(Transform, NormalsStayPerpendicularUnderShear) {
  Transform shear;
  shear.m[0][1] = 2;  // x += 2 y
  const Vec3 tangent = shear.vector({1, 1, 0});
  const Vec3 n = Transform::normal(shear.inverse(), {1, -1, 0});
  EXPECT_NEAR(dot(tangent, n), 0, 1e-15);
}

TEST(Transform, ColumnMajorMatricesAreReadAsGltfWritesThem) {
  const double matrix[16] = {1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 5, 6, 7, 1};
  expectNear(Transform::fromColumnMajor(matrix).point({0, 0, 0}), {5, 6, 7});
}

TEST(Transform, FlatOrNonFiniteMapsAreNotUsable) {
  EXPECT_FALSE(Transform::scaling({1, 0, 1}).isUsable());
  Transform t;
  t.m[1][3] = std::nan("");
  EXPECT_FALSE(t.isUsable());
  EXPECT_TRUE(Transform::scaling({1e-3, 1e-3, 1e-3}).isUsable());
}

}  // namespace
}  // namespace prt
