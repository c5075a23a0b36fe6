#pragma once
// World: a Scene prepared for tracing — its objects in a BVH (planes, being unbounded, on a
// side list) — answering the two questions the shader asks: the nearest surface along a ray,
// and how much light gets through along a shadow ray. Immutable after construction; safe to
// share between threads.

#include <cstdint>
#include <vector>

#include "trace/bvh.h"
#include "trace/scene.h"

namespace prt {

struct Hit {
  double t = 0;
  Vec3 point;
  Vec3 normal;         // outward unit normal of the surface at `point`
  uint32_t object = 0;  // index into Scene::objects
};

class World {
 public:
  explicit World(Scene scene);

  const Scene& scene() const { return scene_; }
  const Material& material(uint32_t object) const { return scene_.objects[object].material; }

  // Nearest crossing within (tMin, tMax); false if none.
  bool intersect(const Ray& ray, double tMin, double tMax, Hit& hit) const;

  // Fraction of light that survives from ray.origin to distance `distance` along the ray: the
  // product of the transmissivities of every surface crossed (0 as soon as one is opaque).
  double transmittance(const Ray& ray, double tMin, double distance) const;

 private:
  Scene scene_;
  Bvh bvh_;
  std::vector<uint32_t> bounded_;    // BVH item -> object index
  std::vector<Bounds> boxes_;        // BVH item -> bounds, for the paper's per-object test
  std::vector<uint32_t> unbounded_;  // planes
};

}  // namespace prt
