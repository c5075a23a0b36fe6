#pragma once
// Where a shadow ray towards a light aims: the one place that draws the points, for the shader
// and for the tests that check what it may skip. Inline: it sits in the shading loop.

#include <variant>

#include "core/rng.h"
#include "core/vec3.h"
#include "trace/sampling.h"
#include "trace/scene.h"

namespace prt {

// The point shadow ray s of `samples` towards a light aims at, from a hit at `from`: the
// light's position, or a point of its disc (a sphere light, seen from `from`) or of its
// rectangle, stratified over the samples. Draws two random numbers for a light with extent,
// none for a point light.
inline Vec3 aimAt(const LightShape& shape, const Vec3& from, int s, int samples, Rng& rng) {
  if (const auto* p = std::get_if<PointLight>(&shape)) return p->position;
  if (const auto* sph = std::get_if<SphereLight>(&shape)) {
    const Vec3 axis = normalize(sph->center - from);
    const double u1 = stratum(s, samples, rng.uniform());  // stratified over the samples
    return sampleDisc(sph->center, axis, sph->radius, u1, rng.uniform());
  }
  const auto& rect = std::get<RectLight>(shape);
  const double u1 = stratum(s, samples, rng.uniform());
  return rect.corner + u1 * rect.edge1 + rng.uniform() * rect.edge2;
}

}  // namespace prt
