#pragma once
// Transform: an affine map of 3-space, p -> L p + t, as the 3x4 matrix [L | t] (row-major).
// Scene graphs (glTF nodes, assimp's node tree, the scene format's `import` blocks) place
// meshes, lights and cameras by composing these; instances of a mesh are traced through the
// inverse. Plain value type; pure, thread-safe. The arithmetic is written out in a fixed order
// (no fused operations in the kernels that build with -ffp-contract=off), so every machine
// computes the same bits.

#include <array>

#include "core/vec3.h"

namespace prt {

struct Transform {
  // m[row][column]; column 3 is the translation.
  std::array<std::array<double, 4>, 3> m{{{1, 0, 0, 0}, {0, 1, 0, 0}, {0, 0, 1, 0}}};

  static Transform identity() { return {}; }
  static Transform translation(const Vec3& t) {
    Transform r;
    r.m[0][3] = t.x, r.m[1][3] = t.y, r.m[2][3] = t.z;
    return r;
  }
  static Transform scaling(const Vec3& s) {
    Transform r;
    r.m[0][0] = s.x, r.m[1][1] = s.y, r.m[2][2] = s.z;
    return r;
  }
  // The rotation of the unit quaternion (x, y, z, w) (glTF's order); normalised first.
  static Transform rotation(double x, double y, double z, double w);
  // From a column-major 4x4 matrix (glTF, OpenGL): its last row is taken to be 0 0 0 1.
  static Transform fromColumnMajor(const double* sixteen);

  Vec3 point(const Vec3& p) const {
    return {m[0][0] * p.x + m[0][1] * p.y + m[0][2] * p.z + m[0][3],
            m[1][0] * p.x + m[1][1] * p.y + m[1][2] * p.z + m[1][3],
            m[2][0] * p.x + m[2][1] * p.y + m[2][2] * p.z + m[2][3]};
  }
  Vec3 vector(const Vec3& v) const {
    return {m[0][0] * v.x + m[0][1] * v.y + m[0][2] * v.z,
            m[1][0] * v.x + m[1][1] * v.y + m[1][2] * v.z,
            m[2][0] * v.x + m[2][1] * v.y + m[2][2] * v.z};
  }
  // A normal carried by this map: by the inverse transpose of L, given `inverse` (this map's
  // inverse), not normalised.
  static Vec3 normal(const Transform& inverse, const Vec3& n) {
    const auto& a = inverse.m;
    return {a[0][0] * n.x + a[1][0] * n.y + a[2][0] * n.z,
            a[0][1] * n.x + a[1][1] * n.y + a[2][1] * n.z,
            a[0][2] * n.x + a[1][2] * n.y + a[2][2] * n.z};
  }

  double determinant() const;
  // Whether L is invertible and every entry finite: what a scene may place things with.
  bool isUsable() const;
  // The inverse; only for a usable transform.
  Transform inverse() const;
  bool isIdentity() const { return *this == Transform{}; }

  bool operator==(const Transform&) const = default;
};

// a * b: first b, then a.
Transform operator*(const Transform& a, const Transform& b);

}  // namespace prt
