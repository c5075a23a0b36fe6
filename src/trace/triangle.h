#pragma once
// The watertight ray-triangle test of Woop, Benthin and Wald (JCGT 2013), in double precision.
// The ray is sheared once so that it runs along +z through the origin; each triangle's vertices
// are then projected onto the xy-plane and the ray meets the triangle when the origin lies
// inside the projection: the signs of three edge functions agree. An edge shared by two
// triangles is computed from the same two projected vertices by the same products in the
// opposite order, so its value for one triangle is exactly the negation of its value for the
// other: no ray slips between them (nor through a shared vertex). A ray exactly on an edge
// meets both (edge functions of 0 count as inside).
//
// Pure arithmetic on doubles, with no fused operations (the project builds with
// -ffp-contract=off): every build of the kernels computes the same distances bit for bit.

#include <cmath>
#include <limits>
#include <utility>

#include "core/ray.h"

namespace prt {

// A ray prepared for many triangle tests.
struct ShearedRay {
  double origin[3];
  int kx = 0, ky = 1, kz = 2;  // the axes after the permutation: kz the largest direction
  double sx = 0, sy = 0, sz = 0;

  explicit ShearedRay(const Ray& ray) : origin{ray.origin.x, ray.origin.y, ray.origin.z} {
    const Vec3& d = ray.direction;
    const double ax = std::abs(d.x), ay = std::abs(d.y), az = std::abs(d.z);
    kz = ax > ay ? (ax > az ? 0 : 2) : (ay > az ? 1 : 2);
    kx = kz == 2 ? 0 : kz + 1;
    ky = kx == 2 ? 0 : kx + 1;
    if (d[kz] < 0) std::swap(kx, ky);  // keeps the winding, hence the sign of the determinant
    sx = d[kx] / d[kz];
    sy = d[ky] / d[kz];
    sz = 1.0 / d[kz];
  }
};

// Where a ray meets a triangle: the distance t along the ray and the barycentric weights of
// vertices a, b, c (u + v + w = 1), or hit = false.
struct TriangleHit {
  bool hit = false;
  double t = 0, u = 0, v = 0, w = 0;
};

namespace detail {
// The test itself, written once: `hit(u, v, w, det, T)` makes the result from the edge
// functions, their sum and the scaled distance's numerator (t = T / det).
template <typename Hit, typename Miss>
inline auto shearedTest(const ShearedRay& r, const double* a, const double* b, const double* c,
                        Hit&& hit, Miss&& miss) {
  const double* o = r.origin;
  const double az = a[r.kz] - o[r.kz], bz = b[r.kz] - o[r.kz], cz = c[r.kz] - o[r.kz];
  const double ax = (a[r.kx] - o[r.kx]) - r.sx * az, ay = (a[r.ky] - o[r.ky]) - r.sy * az;
  const double bx = (b[r.kx] - o[r.kx]) - r.sx * bz, by = (b[r.ky] - o[r.ky]) - r.sy * bz;
  const double cx = (c[r.kx] - o[r.kx]) - r.sx * cz, cy = (c[r.ky] - o[r.ky]) - r.sy * cz;
  const double u = cx * by - cy * bx;  // edge b-c, weight of a
  const double v = ax * cy - ay * cx;  // edge c-a, weight of b
  const double w = bx * ay - by * ax;  // edge a-b, weight of c
  if ((u < 0 || v < 0 || w < 0) && (u > 0 || v > 0 || w > 0)) return miss();
  const double det = u + v + w;
  if (det == 0) return miss();  // seen edge-on
  return hit(u, v, w, det, u * (r.sz * az) + v * (r.sz * bz) + w * (r.sz * cz));
}
}  // namespace detail

// The corners as arrays of x, y, z, indexed by the ray's permuted axes directly.
inline TriangleHit triangleHit(const ShearedRay& r, const double* a, const double* b,
                               const double* c) {
  return detail::shearedTest(
      r, a, b, c,
      [](double u, double v, double w, double det, double numerator) {
        const double inv = 1.0 / det;
        return TriangleHit{true, numerator / det, u * inv, v * inv, w * inv};
      },
      [] { return TriangleHit{}; });
}

// The distance alone, bit for bit triangleHit's t, or NaN where it misses (the hot loops need
// no barycentric weights: one division fewer).
inline double triangleDistance(const ShearedRay& r, const double* a, const double* b,
                               const double* c) {
  return detail::shearedTest(
      r, a, b, c,
      [](double, double, double, double det, double numerator) { return numerator / det; },
      [] { return std::numeric_limits<double>::quiet_NaN(); });
}

inline TriangleHit triangleHit(const ShearedRay& r, const Vec3& a, const Vec3& b, const Vec3& c) {
  const double pa[3] = {a.x, a.y, a.z}, pb[3] = {b.x, b.y, b.z}, pc[3] = {c.x, c.y, c.z};
  return triangleHit(r, pa, pb, pc);
}

}  // namespace prt
