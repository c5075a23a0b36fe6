#pragma once
// Ray intersection with the paper's three primitives: sphere, axis-aligned box, one-sided
// plane. Each reports every crossing of the surface inside (tMin, tMax), nearest first, with
// the outward normal at it: the nearest answers camera and bounce rays, all of them let shadow
// rays be attenuated by each transmissive surface they cross.
//
// The arithmetic lives in the inline kernels below (sphereRoots, boxSlabs, boxSpan), shared by
// `intersect` and by World's hot paths, which need only the distances: both paths then compute
// every crossing bit for bit alike, and the normal only for the hit that is kept.

#include <cmath>
#include <limits>
#include <utility>

#include "core/ray.h"
#include "trace/bounds.h"
#include "trace/scene.h"

namespace prt {

struct Crossings {
  int count = 0;      // 0, 1 or 2
  double t[2] = {0, 0};
  Vec3 normal[2];     // outward unit normal at each crossing
};

Crossings intersect(const SphereShape& s, const Ray& ray, double tMin, double tMax);
Crossings intersect(const BoxShape& b, const Ray& ray, double tMin, double tMax);
// One-sided: only rays travelling against the normal (arriving from the front) cross it.
Crossings intersect(const PlaneShape& p, const Ray& ray, double tMin, double tMax);
// A mesh may be crossed many times: its two nearest crossings (ties to the lower triangle
// index), each triangle tried in turn, with the geometric normals (World's MeshBvh answers
// the same nearest crossing through its tree).
Crossings intersect(const MeshShape& m, const Ray& ray, double tMin, double tMax);
// The same for the placed mesh, through the instance's inverse transform (normals carried
// back to world space).
Crossings intersect(const InstanceShape& instance, const Ray& ray, double tMin, double tMax);

// Bounds of a shape (a mesh: of its triangles); planes are unbounded and return an empty (inverted) box.
Bounds boundsOf(const Shape& shape);
bool isBounded(const Shape& shape);
// The box around a mesh's triangles, in its own coordinates.
Bounds meshBounds(const TriangleMesh& mesh);
// A box holding `box` once carried by `transform` (the box around its eight corners).
Bounds placedBounds(const Bounds& box, const Transform& transform);

// --- kernels ---------------------------------------------------------------------------------

// Where the ray's line meets a sphere: both roots, t0 <= t1, or hit = false.
struct SphereRoots {
  bool hit = false;
  double t0 = 0, t1 = 0;

  // The first crossing beyond tMin, which `intersect` reports first whatever its tMax (if
  // below tMax); NaN if none.
  double firstAfter(double tMin) const {
    if (!hit) return std::numeric_limits<double>::quiet_NaN();
    if (t0 > tMin) return t0;
    return t1 > tMin ? t1 : std::numeric_limits<double>::quiet_NaN();
  }
};

inline SphereRoots sphereRoots(const Vec3& center, double radius, const Ray& ray) {
  // Geometric form (Hearn & Baker): robust when the sphere is far away relative to its size.
  const Vec3 oc = center - ray.origin;
  const double tca = dot(oc, ray.direction);
  const Vec3 perp = oc - tca * ray.direction;
  const double d2 = dot(perp, perp);
  const double r2 = radius * radius;
  if (d2 > r2) return {};
  const double thc = std::sqrt(r2 - d2);
  return {true, tca - thc, tca + thc};
}

// Where the ray's line enters and leaves a box, and through which faces (axis -1: no face).
struct BoxSlabs {
  bool hit = false;
  double tNear = -std::numeric_limits<double>::infinity();
  double tFar = std::numeric_limits<double>::infinity();
  int nearAxis = -1, farAxis = -1;
  double nearSign = 0, farSign = 0;  // the face's outward normal is sign * unit(axis)

  // Whether each crossing counts: the entry, then the exit (a distinct point after it).
  bool nearCrosses(double tMin, double tMax) const {
    return nearAxis >= 0 && tNear > tMin && tNear < tMax;
  }
  bool farCrosses(double tMin, double tMax) const {
    return farAxis >= 0 && tFar > tMin && tFar < tMax && tFar > tNear;
  }
  // As SphereRoots::firstAfter.
  double firstAfter(double tMin) const {
    if (!hit) return std::numeric_limits<double>::quiet_NaN();
    if (nearAxis >= 0 && tNear > tMin) return tNear;
    if (farAxis >= 0 && tFar > tMin && tFar > tNear) return tFar;
    return std::numeric_limits<double>::quiet_NaN();
  }
};

namespace detail {
// The slab arithmetic of boxSlabs and boxSpan, written once: per axis, the distances to the
// slab's two planes, the entry raised and the exit lowered. `entered(axis, sign)` and
// `left(axis, sign)` hear of each change (sign: of the face's outward normal). Whether the line
// meets the box: tNear only grows and tFar only shrinks, so once crossed they stay crossed.
template <typename Entered, typename Left>
inline bool crossSlabs(const Vec3& lo, const Vec3& hi, const Ray& ray, double& tNear,
                       double& tFar, Entered&& entered, Left&& left) {
  for (int axis = 0; axis < 3; ++axis) {
    const double o = ray.origin[axis];
    const double d = ray.direction[axis];
    if (d == 0.0) {
      if (o < lo[axis] || o > hi[axis]) return false;  // parallel to and outside the slab
      continue;
    }
    const double inv = 1.0 / d;
    double t0 = (lo[axis] - o) * inv;
    double t1 = (hi[axis] - o) * inv;
    // Entering through the min face when travelling +, through the max face when travelling -.
    const bool backwards = t0 > t1;
    if (backwards) std::swap(t0, t1);
    if (t0 > tNear) {
      tNear = t0;
      entered(axis, backwards ? 1.0 : -1.0);
    }
    if (t1 < tFar) {
      tFar = t1;
      left(axis, backwards ? -1.0 : 1.0);
    }
  }
  return !(tNear > tFar);
}
}  // namespace detail

inline BoxSlabs boxSlabs(const Vec3& lo, const Vec3& hi, const Ray& ray) {
  BoxSlabs s;
  auto entered = [&](int axis, double sign) {
    s.nearAxis = axis;
    s.nearSign = sign;
  };
  auto left = [&](int axis, double sign) {
    s.farAxis = axis;
    s.farSign = sign;
  };
  s.hit = detail::crossSlabs(lo, hi, ray, s.tNear, s.tFar, entered, left);
  return s;
}

// The same entry and exit without the faces, for the loops that need only the distances (the
// nearest hit's face is found again by boxSlabs). Bit for bit as boxSlabs: the same `hit`, and
// where hit the same tNear and tFar, computed by the same crossSlabs. A face boxSlabs
// leaves unset (axis -1) is exactly a tNear of -infinity or a tFar of +infinity here, their
// initial values (a face is set only by a distance beyond them: tNear may become +infinity,
// never -infinity), so the tests below are boxSlabs's.
struct BoxSpan {
  bool hit = false;
  double tNear = -std::numeric_limits<double>::infinity();
  double tFar = std::numeric_limits<double>::infinity();

  bool nearCrosses(double tMin, double tMax) const { return tNear > tMin && tNear < tMax; }
  bool farCrosses(double tMin, double tMax) const {
    return tFar > tMin && tFar < tMax && tFar > tNear;
  }
  double firstAfter(double tMin) const {
    if (!hit) return std::numeric_limits<double>::quiet_NaN();
    if (tNear > tMin) return tNear;
    if (tFar < std::numeric_limits<double>::infinity() && tFar > tMin && tFar > tNear) return tFar;
    return std::numeric_limits<double>::quiet_NaN();
  }
};

inline BoxSpan boxSpan(const Vec3& lo, const Vec3& hi, const Ray& ray) {
  BoxSpan s;
  s.hit = detail::crossSlabs(lo, hi, ray, s.tNear, s.tFar, [](int, double) {},
                             [](int, double) {});
  return s;
}

// The plane's crossing distance, or NaN when the ray arrives from behind or runs parallel.
inline double planeDistance(const Vec3& point, const Vec3& normal, const Ray& ray) {
  const double denom = dot(ray.direction, normal);
  if (denom >= 0.0) return std::numeric_limits<double>::quiet_NaN();
  return dot(point - ray.origin, normal) / denom;
}

}  // namespace prt
