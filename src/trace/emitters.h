#pragma once
// Emitters: everything the path tracer's next-event estimation aims shadow rays at — the
// scene's lights, each of which gets a shadow ray at every shading point (as in the paper's
// renderer: scenes have few), and the triangles of emissive meshes (area lights, possibly
// millions), of which one is picked per shading point in proportion to its power 2 pi L A
// (radiance L from both sides, area A). Only the choice depends on the powers: an estimate
// divides by the probability it was chosen with, so the mean does not.
//
// Light units (docs/model-files.md): the path tracer takes a light's `color` times pi as its
// intensity (W/sr; irradiance for a sun), the convention that makes a Lambertian surface under
// a light read the same as under the paper's renderer, and the same as Cycles for lights
// imported from model files. Emission is radiance, as in Cycles.
// Immutable after construction; safe to share between threads.

#include <cstdint>
#include <vector>

#include "core/vec3.h"
#include "trace/world.h"

namespace prt {

struct EmitterSample {
  Vec3 direction;     // unit, from the shading point towards the light
  double distance = 0;  // to the point sampled; infinity for a sun
  Color radiance;     // arriving along `direction` (for a delta light: intensity / d^2 etc.)
  double pdf = 0;     // solid-angle density of the choice for an area light; the pick's
                      // probability for a delta light
  bool delta = true;  // a light that no ray can hit (MIS does not apply)
};

class Emitters {
 public:
  explicit Emitters(const World& world);

  size_t lightCount() const;
  bool hasTriangles() const { return !cdf_.empty(); }
  size_t triangleCount() const { return triangles_.size(); }

  // A point of light `light` (for a sphere or rectangle light, chosen by u1, u2) seen from
  // `from`; false: it sends nothing there (outside a spot's cone, at the point itself).
  bool sampleLight(size_t light, const Vec3& from, double u1, double u2,
                   EmitterSample& out) const;
  // One emissive triangle chosen by u0 and a point of it by u1, u2, seen from `from`; false:
  // none (no emissive triangle, or one seen edge-on).
  bool sampleTriangle(const Vec3& from, double u0, double u1, double u2,
                      EmitterSample& out) const;
  // The solid-angle density with which sampleTriangle would have chosen the point `hit` of an
  // emissive triangle, seen from `from`; 0 for anything it cannot choose.
  double pdfOfHit(const Vec3& from, const Hit& hit) const;

 private:
  struct Triangle {
    Vec3 p0, e1, e2;  // world space: p0 + b1 e1 + b2 e2
    Vec3 normal;      // unit
    double area = 0;
    uint32_t object = 0, index = 0;
  };
  double pick(size_t entry) const;
  Color emissionAt(const Triangle& t, double b1, double b2) const;

  const World& world_;
  std::vector<double> cdf_;  // running sums of the triangles' powers
  std::vector<Triangle> triangles_;
  std::vector<int64_t> firstEntryOfObject_;  // per object: its triangles' first entry, or -1
};

}  // namespace prt
