#pragma once
// Where a shadow ray towards a light aims: the one place that draws the points, for the shader
// and for the tests that check what it may skip, with how many random numbers a point takes
// and the ball every point lies in. Inline: it sits in the shading loop.

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <variant>

#include "core/rng.h"
#include "core/vec3.h"
#include "trace/sampling.h"
#include "trace/scene.h"

namespace prt {

// The point shadow ray s of `samples` towards a light aims at, from a hit at `from`: the
// light's position, or a point of its disc (a sphere light, seen from `from`) or of its
// rectangle, stratified over the samples. Draws two random numbers for a light with extent,
// none for a point or spot light. Not for a directional light, which has no point to aim at
// (the shader sends its shadow rays along its direction).
inline Vec3 aimAt(const LightShape& shape, const Vec3& from, int s, int samples, Rng& rng) {
  if (const auto* p = std::get_if<PointLight>(&shape)) return p->position;
  if (const auto* spot = std::get_if<SpotLight>(&shape)) return spot->position;
  if (const auto* sun = std::get_if<DirectionalLight>(&shape)) return from - sun->direction;
  if (const auto* sph = std::get_if<SphereLight>(&shape)) {
    const Vec3 axis = normalize(sph->center - from);
    const double u1 = stratum(s, samples, rng.uniform());  // stratified over the samples
    return sampleDisc(sph->center, axis, sph->radius, u1, rng.uniform());
  }
  const auto& rect = std::get<RectLight>(shape);
  const double u1 = stratum(s, samples, rng.uniform());
  return rect.corner + u1 * rect.edge1 + rng.uniform() * rect.edge2;
}

// How many random numbers aimAt draws for one point of the light.
inline uint64_t aimDraws(const LightShape& shape) {
  return std::holds_alternative<SphereLight>(shape) || std::holds_alternative<RectLight>(shape) ? 2
                                                                                                : 0;
}

// Whether a light is sampled at a single point (one shadow ray per shading point).
inline bool isPointLike(const LightShape& shape) { return aimDraws(shape) == 0; }

// A ball holding every point aimAt may return for a light: its centre and radius, and the sum
// of the centre's coordinates' magnitudes (for rounding margins).
struct LightReach {
  Vec3 center;
  double radius = 0;
  double magnitude = 0;
};

inline LightReach reachOf(const LightShape& shape) {
  LightReach r;
  if (const auto* p = std::get_if<PointLight>(&shape)) {
    r.center = p->position;
  } else if (const auto* spot = std::get_if<SpotLight>(&shape)) {
    r.center = spot->position;
  } else if (std::holds_alternative<DirectionalLight>(shape)) {
    // Never behind a surface by position: the shader tests the direction instead.
    r.radius = std::numeric_limits<double>::infinity();
  } else if (const auto* sph = std::get_if<SphereLight>(&shape)) {
    r.center = sph->center;
    r.radius = sph->radius;
  } else {
    // The rectangle's centre; its farthest points are corners, half a diagonal away.
    const auto& rect = std::get<RectLight>(shape);
    r.center = rect.corner + 0.5 * (rect.edge1 + rect.edge2);
    r.radius = 0.5 * std::max(length(rect.edge1 + rect.edge2), length(rect.edge1 - rect.edge2));
  }
  r.magnitude = std::abs(r.center.x) + std::abs(r.center.y) + std::abs(r.center.z);
  return r;
}

}  // namespace prt
