#pragma once
// Bounds: an axis-aligned bounding box and the slab test against a ray. This is the paper's
// cheap rejection test: every object's box is tried before the object itself.

#include <algorithm>
#include <cmath>
#include <limits>

#include "core/ray.h"
#include "core/select.h"

namespace prt {

struct Bounds {
  Vec3 lo{std::numeric_limits<double>::infinity()};
  Vec3 hi{-std::numeric_limits<double>::infinity()};

  void extend(const Vec3& p) {
    lo = min(lo, p);
    hi = max(hi, p);
  }
  void extend(const Bounds& b) {
    lo = min(lo, b.lo);
    hi = max(hi, b.hi);
  }
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
  // The corner picked by the bits of `bits` (1: x, 2: y, 4: z; set: the high side).
  Vec3 corner(int bits) const {
    return {(bits & 1) ? hi.x : lo.x, (bits & 2) ? hi.y : lo.y, (bits & 4) ? hi.z : lo.z};
  }
  // Grown by `margin` on every side.
  Bounds widened(double margin) const { return {lo - Vec3(margin), hi + Vec3(margin)}; }
  bool contains(const Vec3& p) const {
    return p.x >= lo.x && p.x <= hi.x && p.y >= lo.y && p.y <= hi.y && p.z >= lo.z && p.z <= hi.z;
  }
  // Whether the two share a point (touching counts).
  bool overlaps(const Bounds& b) const {
    return b.hi.x >= lo.x && b.lo.x <= hi.x && b.hi.y >= lo.y && b.lo.y <= hi.y && b.hi.z >= lo.z &&
           b.lo.z <= hi.z;
  }
  // The largest magnitude of any coordinate of the box.
  double largestMagnitude() const {
    const Vec3 a(std::abs(lo.x), std::abs(lo.y), std::abs(lo.z));
    const Vec3 b(std::abs(hi.x), std::abs(hi.y), std::abs(hi.z));
    return maxComponent(max(a, b));
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
