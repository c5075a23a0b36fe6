#pragma once
// Sampling helpers for distributed ray tracing and supersampling. Pure functions of their
// random inputs, so results depend only on the counter-based Rng that feeds them.

#include <algorithm>
#include <cmath>
#include <numbers>

#include "core/portable_math.h"
#include "core/vec3.h"

namespace prt {

// How far spawned rays start off the surface they leave, scaled to the hit's magnitude so
// large scenes do not self-intersect and small ones do not skip thin gaps.
inline double surfaceEpsilon(const Vec3& p) {
  return 1e-9 * std::max(1.0, maxComponent(Vec3(std::abs(p.x), std::abs(p.y), std::abs(p.z))));
}

// Stratum i of n, jittered by u in [0, 1): (i + u) / n. With a single stratum that is u
// itself, bit for bit, and the division (slow) is skipped.
inline double stratum(int i, int n, double u) { return n == 1 ? u : (i + u) / n; }

// The mean of n samples summing to `sum`; sum itself, bit for bit, when n is 1.
inline Vec3 meanOf(const Vec3& sum, int n) { return n == 1 ? sum : sum / n; }

// A direction uniformly distributed over the cone around unit vector `axis` whose half-angle
// has cosine `cosMax` (cosRadians of it: computed once per material); u1, u2 in [0, 1).
inline Vec3 sampleCone(const Vec3& axis, double cosMax, double u1, double u2) {
  const double cosTheta = 1.0 - u1 * (1.0 - cosMax);
  const double sinTheta = std::sqrt(std::max(0.0, 1.0 - cosTheta * cosTheta));
  double sinPhi, cosPhi;
  sinCosTurns(u2, sinPhi, cosPhi);  // phi = 2 pi u2
  Vec3 u, v;
  orthonormalBasis(axis, u, v);
  return sinTheta * cosPhi * u + sinTheta * sinPhi * v + cosTheta * axis;
}

// A point uniformly distributed over the disc of radius r centred on `center`, perpendicular
// to unit vector `normal` (Shirley's concentric map keeps strata compact).
inline Vec3 sampleDisc(const Vec3& center, const Vec3& normal, double r, double u1, double u2) {
  const double a = 2.0 * u1 - 1.0, b = 2.0 * u2 - 1.0;
  double radius = 0, cosPhi = 1, sinPhi = 0;
  if (a != 0 || b != 0) {
    if (a * a > b * b) {
      radius = a;  // phi = (pi/4) (b/a)
      sinCosQuarter((std::numbers::pi / 4) * (b / a), sinPhi, cosPhi);
    } else {
      radius = b;  // phi = pi/2 - x with x = (pi/4) (a/b): cos phi = sin x, sin phi = cos x
      sinCosQuarter((std::numbers::pi / 4) * (a / b), cosPhi, sinPhi);
    }
  }
  Vec3 u, v;
  orthonormalBasis(normal, u, v);
  return center + r * radius * (cosPhi * u + sinPhi * v);
}

// A near-square grid of cells for n samples per pixel: ceil(sqrt(n)) columns and as many rows
// as the samples need. Computed once per pixel.
struct SampleGrid {
  int columns, rows;
  explicit SampleGrid(int n)
      : columns(static_cast<int>(std::ceil(std::sqrt(static_cast<double>(n))))),
        rows((n + columns - 1) / columns) {}
};

// Sample i, with one jittered point in each of the grid's first cells: returns the offset
// inside the pixel, in [0, 1)^2.
inline void stratifiedSample(int i, const SampleGrid& grid, double jx, double jy, double& x,
                             double& y) {
  x = ((i % grid.columns) + jx) / grid.columns;
  y = ((i / grid.columns) + jy) / grid.rows;
}

}  // namespace prt
