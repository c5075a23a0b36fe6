#pragma once
// PathTracer: the physically based integrator. Unidirectional path tracing: from the camera a
// path bounces off surfaces, each bounce's direction drawn from the surface's BSDF
// (trace/bsdf.h); at every surface that is not a perfect mirror or clear glass, one emitter is
// chosen (trace/emitters.h) and a shadow ray sent to it (next-event estimation). Where both
// could have found the same light — an emissive triangle, met by a bounce or aimed at — the two
// estimates are weighed by multiple importance sampling with the power heuristic (Veach 1997).
// Rays that leave the scene take the environment's radiance (trace/environment_light.h: the
// world colour, or an HDR map, which next-event estimation also aims at, weighed by MIS). After three bounces a
// path whose throughput has fallen below 1 survives with that probability (Russian roulette,
// its survivors weighted up to keep the mean); every path ends after the environment's
// max_bounces.
//
// Textures (glTF 2.0, appendix B): the base colour and emission textures (sRGB), and the data
// textures: the metallic-roughness texture's B and G multiply metallic and roughness, the
// transmission texture's R the transmission, and a tangent-space normal map tilts the shading
// normal (trace/normal_map.h, guarded by keepReflectionAbove). The tilted normal is the
// BSDF's alone: the surface's own normal still decides which side a ray leaves from and where
// it starts, and, as in Cycles, a bounce reflected below the surface (or transmitted above it)
// ends the path and a light on the other side of the surface than of the tilted normal
// lights nothing.
//
// Volumes (KHR_materials_volume): a path keeps the media it is in, as Cycles keeps its volume
// stack: a bounce through a refracting, not thin-walled surface from outside enters that
// object's medium, one from inside leaves it. Every segment travelled inside a medium (the
// innermost: a liquid in a glass is the liquid's, an ice cube in it clear) multiplies the
// throughput by the medium's transmittance over its length, exp(-sigma t) per channel, whatever
// surface ends it: a glass standing on a table whose floor the path meets from inside it
// still absorbs on the way there. Closed objects are assumed: a path that leaves the scene
// from inside one is not absorbed on its way out (its length is infinite).
//
// Shadow rays are stopped by any surface but the transparent part of one (coverage < 1): the
// glass of a path-traced scene lets light through by refraction alone, as a real one does.
// Random numbers: one counter-based stream per sample (core/rng.h), a child stream per bounce,
// so that a pixel's value depends only on the pixel and the sample, on any machine.
// Reads only immutable data; one PathTracer may be used by many threads at once.

#include <cstdint>
#include <span>

#include "core/rng.h"
#include "trace/bsdf.h"
#include "trace/emitters.h"
#include "trace/sampling.h"
#include "trace/world.h"

namespace prt {

// The path tracer's surface for a material written for the paper's renderer (pbr.given
// false): base colour = colour; metallic = the larger of `metallic` and `reflect` (a mirror is
// a metal of the surface's colour); roughness = from the gloss cone for a reflecting or
// refracting surface (0 for a sharp one), from the Phong exponent for one with a highlight,
// 1 otherwise; transmission = `transmit` when it refracts (ior > 1), and coverage 1 - `transmit`
// when it does not (light passes straight through); ior = the material's where it refracts,
// 1.5 otherwise. The inverse of the mapping of glTF's materials onto Hall's (material_mapping).
PbrSurface pbrFromHall(const Material& m);

class PathTracer {
 public:
  explicit PathTracer(const World& world);

  // Radiance arriving along the camera ray; with `candidates`, the first hit is looked for
  // among them (ViewLists). `rays` counts every ray traced, shadow rays included.
  Color radiance(const Ray& ray, const std::span<const uint32_t>* candidates, Rng rng,
                 uint64_t& rays) const;

  const Emitters& emitters() const { return emitters_; }

 private:
  struct Surface {
    BsdfInputs bsdf;
    double coverage = 1;
    bool attributes = false;  // texture coordinates or vertex colours are needed
    // glTF's data textures in use (the mesh has texture coordinates; and tangents for the
    // normal map).
    bool metallicRoughnessMap = false, transmissionMap = false, normalMap = false;
    // KHR_materials_volume: `medium` when the inside is one (refracting, not thin-walled);
    // its absorption coefficient per unit length (Beer and Lambert: sigma = -ln(attenuation
    // colour) / attenuation distance), `absorbs` when any is above 0.
    bool medium = false;
    Color absorption;
    bool absorbs = false;
  };
  // Whether anything opaque lies between `origin` and `distance` along `direction`; returns the
  // share of light that gets through the transparent parts of what lies between.
  double visibility(const Vec3& origin, const Vec3& direction, double distance,
                    uint64_t& rays) const;

  const World& world_;
  Emitters emitters_;
  std::vector<Surface> surfaces_;  // per object
  int maxBounces_;
  bool allOpaque_ = true;  // no surface lets light straight through: shadow rays stop at any
};

}  // namespace prt
