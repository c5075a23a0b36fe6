#pragma once
// World: a Scene prepared for tracing — its objects in a BVH (planes, being unbounded, on a
// side list), and for each light the objects that can shadow each part of space
// (ShadowShafts) — answering the two questions the shader asks: the nearest surface along a ray,
// and how much light gets through along a shadow ray. Immutable after construction; safe to
// share between threads.
//
// Results do not depend on the order the BVH happens to offer objects in. Two things would:
// which of two hits at exactly the same distance wins, and the rounding of a product of
// several transmissivities. Both follow a fixed order per ray-direction octant, the order of
// the original binary BVH (Bvh::visitOrder, planes first): images are bit-identical to those
// rendered before the faster QuadBvh replaced it for traversal.

#include <cstdint>
#include <memory>
#include <span>
#include <vector>

#include "trace/environment_light.h"
#include "trace/mesh_bvh.h"
#include "trace/quad_bvh.h"
#include "trace/scene.h"
#include "trace/shadow_shafts.h"
#include "trace/world_items.h"

namespace prt {

struct Hit {
  double t = 0;
  Vec3 point;
  Vec3 normal;          // outward unit normal of the surface at `point`
  uint32_t object = 0;  // index into Scene::objects
  uint32_t triangle = 0;  // a mesh's: which of its triangles was met
};

// What a mesh carries at a point besides its normal (trace/triangle_mesh.h): the texture
// coordinates and vertex colour interpolated there, when the mesh has them.
struct SurfaceAttributes {
  double u = 0, v = 0;
  Color color{1, 1, 1};
  // In world space, interpolated, not unit (trace/triangle_mesh.h's tangents); zero: none.
  // `handedness` is the w of the bitangent w cross(normal, tangent), with a mirroring
  // placement's turn taken into account.
  Vec3 tangent;
  double handedness = 1;
};

class World {
 public:
  explicit World(Scene scene) : World(std::move(scene), nullptr) {}
  // The same, taking from `reuse` (if not null) the trees of the meshes it shares with
  // `scene`: how the frames of an animation are prepared, where meshes move but keep their
  // shape. `reuse` may be destroyed afterwards; meshStats() counts only what was built here.
  World(Scene scene, const World* reuse);

  const Scene& scene() const { return scene_; }
  const Material& material(uint32_t object) const { return scene_.objects[object].material; }
  // What rays that meet nothing see: the world colour or the environment map.
  const EnvironmentLight& environment() const { return *environment_; }

  // Nearest crossing within (tMin, tMax); false if none.
  bool intersect(const Ray& ray, double tMin, double tMax, Hit& hit) const;
  // The same when only the planes and the items in `candidates` (indices in itemBounds()'s
  // order, in any order) can be met, as ViewLists knows for camera rays.
  bool intersectAmong(std::span<const uint32_t> candidates, const Ray& ray, double tMin,
                      double tMax, Hit& hit) const;

  // The nearest crossing from 0 of a ray that starts inside scene object `object` (a sphere or
  // a box, into which the ray was refracted or inside which it was reflected), as intersect
  // gives it: only the object and those whose boxes overlap its box can be met before the ray
  // leaves that box, and the BVH is asked only when the ray gets that far.
  bool intersectFromInside(uint32_t object, const Ray& ray, Hit& hit) const;

  // The attributes of the mesh object met by `ray` at `hit` (hit.object a mesh or an
  // instance; the defaults for any other object and for a mesh without them).
  SurfaceAttributes attributesAt(const Ray& ray, const Hit& hit) const;

  // The boxes of the bounded objects, which the BVH holds as its items.
  std::vector<Bounds> itemBounds() const;

  // What the meshes cost to prepare: their triangles, the seconds their trees took to build
  // (on the thread that built the World) and the bytes those trees and triangles hold. A mesh
  // placed by several instances is counted (and built) once; `instances` counts the objects
  // that place one.
  struct MeshStats {
    size_t meshes = 0, triangles = 0, bytes = 0, instances = 0;
    double buildSeconds = 0;
  };
  const MeshStats& meshStats() const { return meshStats_; }

  // Whether any surface lies within (tMin, distance) along the ray, whatever it is made of:
  // the path tracer's shadow ray in a scene where every surface is opaque. Stops at the first
  // surface found, so it is cheaper than intersect().
  bool occluded(const Ray& ray, double tMin, double distance) const;
  // Fraction of light that survives from ray.origin to distance `distance` along the ray: the
  // product of the transmissivities of every surface crossed (0 as soon as one is opaque).
  double transmittance(const Ray& ray, double tMin, double distance) const;
  // The same, from 0, for a shadow ray from ray.origin to a point of scene().lights[light] (any
  // point the shader samples: on the point, inside the sphere's box, on the rectangle) at
  // `distance`: answered from the light's shadow shafts where they know the few objects that
  // can be in the way, bit for bit as from the BVH.
  double transmittanceToLight(size_t light, const Ray& ray, double distance) const;
  // Where shadow rays leave from, found once for all the lights' rays from one point.
  struct ShadowOrigin {
    size_t cell;  // in the shadow shafts' grid
  };
  ShadowOrigin shadowOrigin(const Vec3& origin) const { return {shafts_.cellOf(origin)}; }
  // transmittanceToLight for a ray leaving from `from` (shadowOrigin(ray.origin)).
  double transmittanceToLight(const ShadowOrigin& from, size_t light, const Ray& ray,
                              double distance) const;

 private:
  // A bounded object as the BVH's item, flattened for the hot loops (trace/world_items.h).
  using Item = WorldItem;
  const MeshBvh& treeFor(const std::shared_ptr<const TriangleMesh>& mesh, const World* reuse);
  struct Plane {
    Vec3 point, normal;
    double transmissivity = 0;
    uint32_t object = 0;
  };

  void buildNeighbours(const std::vector<Bounds>& boxes);
  template <typename Candidates>
  [[gnu::always_inline]] inline bool intersect(const Ray& ray, double tMin, double tMax, Hit& hit,
                                              Candidates&& candidates) const;
  template <typename Candidates>
  [[gnu::always_inline]] inline double transmittance(const Ray& ray, double tMin, double distance,
                                                     Candidates&& candidates) const;

  Scene scene_;
  std::shared_ptr<const EnvironmentLight> environment_;  // shared with the frames that reuse it
  QuadBvh bvh_;
  ShadowShafts shafts_;
  std::vector<Item> items_;
  std::vector<std::shared_ptr<const MeshBvh>> meshes_;
  std::vector<std::unique_ptr<Transform>> placements_;
  MeshStats meshStats_;
  Bounds itemsBox_;  // around all of them
  std::vector<Plane> planes_;
  // Per item: its box widened by a margin, and the items whose boxes come within twice that
  // margin of it (itself included); empty when there are too many objects to pair.
  struct Neighbours {
    Bounds box;
    uint32_t begin = 0, count = 0;
  };
  std::vector<Neighbours> neighbours_;
  std::vector<uint32_t> neighbourItems_;
  std::vector<uint32_t> itemOfObject_;  // per scene object; ~0u for planes
  // ranks_[octant * items + item]: the item's place in the tie-breaking order, from 1.
  std::vector<uint32_t> ranks_;
};

}  // namespace prt
