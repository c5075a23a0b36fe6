#include "trace/shapes.h"

#include <cmath>

namespace prt {
namespace {

void add(Crossings& c, double t, const Vec3& n) {
  c.t[c.count] = t;
  c.normal[c.count] = n;
  ++c.count;
}

}  // namespace

Crossings intersect(const SphereShape& s, const Ray& ray, double tMin, double tMax) {
  Crossings c;
  // Geometric form (Hearn & Baker): robust when the sphere is far away relative to its size.
  const Vec3 oc = s.center - ray.origin;
  const double tca = dot(oc, ray.direction);
  const Vec3 perp = oc - tca * ray.direction;
  const double d2 = dot(perp, perp);
  const double r2 = s.radius * s.radius;
  if (d2 > r2) return c;
  const double thc = std::sqrt(r2 - d2);
  const double inv = 1.0 / s.radius;
  for (double t : {tca - thc, tca + thc}) {
    if (t > tMin && t < tMax) add(c, t, (ray.at(t) - s.center) * inv);
  }
  return c;
}

Crossings intersect(const BoxShape& b, const Ray& ray, double tMin, double tMax) {
  Crossings c;
  double tNear = -std::numeric_limits<double>::infinity();
  double tFar = std::numeric_limits<double>::infinity();
  int nearAxis = -1, farAxis = -1;
  double nearSign = 0, farSign = 0;
  for (int axis = 0; axis < 3; ++axis) {
    const double o = ray.origin[axis];
    const double d = ray.direction[axis];
    if (d == 0.0) {
      if (o < b.min[axis] || o > b.max[axis]) return c;  // parallel to and outside the slab
      continue;
    }
    const double inv = 1.0 / d;
    double t0 = (b.min[axis] - o) * inv;
    double t1 = (b.max[axis] - o) * inv;
    // Entering through the min face when travelling +, through the max face when travelling -.
    double s0 = -1, s1 = 1;
    if (t0 > t1) {
      std::swap(t0, t1);
      std::swap(s0, s1);
    }
    if (t0 > tNear) { tNear = t0; nearAxis = axis; nearSign = s0; }
    if (t1 < tFar) { tFar = t1; farAxis = axis; farSign = s1; }
    if (tNear > tFar) return c;
  }
  auto faceNormal = [](int axis, double sign) {
    Vec3 n;
    n[axis] = sign;
    return n;
  };
  if (nearAxis >= 0 && tNear > tMin && tNear < tMax) add(c, tNear, faceNormal(nearAxis, nearSign));
  if (farAxis >= 0 && tFar > tMin && tFar < tMax && tFar > tNear) {
    add(c, tFar, faceNormal(farAxis, farSign));
  }
  return c;
}

Crossings intersect(const PlaneShape& p, const Ray& ray, double tMin, double tMax) {
  Crossings c;
  const double denom = dot(ray.direction, p.normal);
  if (denom >= 0.0) return c;  // parallel, or arriving from behind: invisible
  const double t = dot(p.point - ray.origin, p.normal) / denom;
  if (t > tMin && t < tMax) add(c, t, p.normal);
  return c;
}

Bounds boundsOf(const Shape& shape) {
  Bounds b;
  if (const auto* s = std::get_if<SphereShape>(&shape)) {
    b.extend(s->center - Vec3(s->radius));
    b.extend(s->center + Vec3(s->radius));
  } else if (const auto* x = std::get_if<BoxShape>(&shape)) {
    b.extend(x->min);
    b.extend(x->max);
  }
  return b;
}

bool isBounded(const Shape& shape) { return !std::holds_alternative<PlaneShape>(shape); }

}  // namespace prt
