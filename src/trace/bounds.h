#pragma once
// Bounds: an axis-aligned bounding box and the slab test against a ray. This is the paper's
// cheap rejection test: every object's box is tried before the object itself.

#include <algorithm>
#include <limits>

#include "core/ray.h"
#include "core/select.h"

namespace prt {

struct Bounds {
  Vec3 lo{std::numeric_limits<double>::infinity()};
  Vec3 hi{-std::numeric_limits<double>::infinity()};

  void extend(const Vec3& p) { lo = min(lo, p); hi = max(hi, p); }
  void extend(const Bounds& b) { lo = min(lo, b.lo); hi = max(hi, b.hi); }
  Vec3 centroid() const { return 0.5 * (lo + hi); }
  Vec3 diagonal() const { return hi - lo; }
  double surfaceArea() const {
    const Vec3 d = diagonal();
    return 2.0 * (d.x * d.y + d.y * d.z + d.z * d.x);
  }
  int longestAxis() const {
    const Vec3 d = diagonal();
    return d.x > d.y ? (d.x > d.z ? 0 : 2) : (d.y > d.z ? 1 : 2);
  }
};

// A ray prepared for many slab tests: the inverse direction is computed once.
struct RayQuery {
  Ray ray;
  Vec3 invDirection;
  explicit RayQuery(const Ray& r)
      : ray(r), invDirection(1.0 / r.direction.x, 1.0 / r.direction.y, 1.0 / r.direction.z) {}
};

// True when the ray meets the box within (tMin, tMax).
inline bool hitsBounds(const Bounds& b, const RayQuery& q, double tMin, double tMax) {
  // Branch-free (each select is one minsd or maxsd): whether a ray meets a box is a coin toss
  // a branch predictor loses. The interval only narrows, so one check at the end suffices.
  for (int axis = 0; axis < 3; ++axis) {
    const double t0 = (b.lo[axis] - q.ray.origin[axis]) * q.invDirection[axis];
    const double t1 = (b.hi[axis] - q.ray.origin[axis]) * q.invDirection[axis];
    const double near = lessOr(t1, t0);  // the pair ordered (if t0 > t1, swapped)
    const double far = greaterOr(t0, t1);
    // NaN (0 * inf for a ray in a slab plane) compares false and leaves the interval alone.
    tMin = greaterOr(near, tMin);
    tMax = lessOr(far, tMax);
  }
  return tMin <= tMax;
}

}  // namespace prt
