#include "trace/shapes.h"

namespace prt {
namespace {

void add(Crossings& c, double t, const Vec3& n) {
  c.t[c.count] = t;
  c.normal[c.count] = n;
  ++c.count;
}

Vec3 faceNormal(int axis, double sign) {
  Vec3 n;
  n[axis] = sign;
  return n;
}

}  // namespace

Crossings intersect(const SphereShape& s, const Ray& ray, double tMin, double tMax) {
  Crossings c;
  const SphereRoots r = sphereRoots(s.center, s.radius, ray);
  if (!r.hit) return c;
  const double inv = 1.0 / s.radius;
  for (double t : {r.t0, r.t1}) {
    if (t > tMin && t < tMax) add(c, t, (ray.at(t) - s.center) * inv);
  }
  return c;
}

Crossings intersect(const BoxShape& b, const Ray& ray, double tMin, double tMax) {
  Crossings c;
  const BoxSlabs s = boxSlabs(b.min, b.max, ray);
  if (!s.hit) return c;
  if (s.nearCrosses(tMin, tMax)) add(c, s.tNear, faceNormal(s.nearAxis, s.nearSign));
  if (s.farCrosses(tMin, tMax)) add(c, s.tFar, faceNormal(s.farAxis, s.farSign));
  return c;
}

Crossings intersect(const PlaneShape& p, const Ray& ray, double tMin, double tMax) {
  Crossings c;
  const double t = planeDistance(p.point, p.normal, ray);
  if (t > tMin && t < tMax) add(c, t, p.normal);  // false for NaN
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
