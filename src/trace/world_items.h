#pragma once
// The items of World's tree: each bounded shape flattened for the hot loops, and the one table
// that dispatches on an item's kind. A kind is a struct of static functions:
//   - firstAfter: the first crossing beyond tMin, no farther than `nearest` (NaN if none; a
//     mesh also says which triangle), as intersect(shape) reports it first;
//   - normal: the outward unit normal at the crossing firstAfter found, at distance t;
//   - crossings: how many times a shadow ray crosses the surface within (tMin, distance);
//   - kBoxTested: whether the paper's per-object box test must pass too (a mesh's tree tests
//     boxes itself).
// World's loops call these through visitItemKind and nothing else, so a new bounded shape is
// its kind here (one struct and one entry in ItemKinds), how World builds its item (World's
// constructor) and its bounds (boundsOf, trace/shapes.cpp); the loops do not change.
// Bit-identity: each kind does the arithmetic its shape's intersect does (the kernels in
// trace/shapes.h), so images do not depend on this dispatch.

#include <cstdint>
#include <limits>
#include <tuple>
#include <utility>

#include "core/ray.h"
#include "core/transform.h"
#include "trace/bounds.h"
#include "trace/mesh_bvh.h"
#include "trace/shapes.h"

namespace prt {

struct WorldItem {
  Vec3 a, b;   // sphere: centre, (radius, 1 / radius, 0); box: min, max; an instance of a
               // mesh: its box, widened; a mesh in world space: unused
  Bounds box;  // for the paper's per-object box test
  double transmissivity = 0;
  uint32_t object = 0;  // index into Scene::objects
  uint8_t kind = 0;     // its index in ItemKinds
  const MeshBvh* mesh = nullptr;  // for a mesh; owned by World
  // For an instance of a mesh: the inverse of its placement (owned by World), which carries
  // rays into the mesh's coordinates; null for a mesh placed in world space.
  const Transform* meshFromWorld = nullptr;
};

struct SphereItem {
  static constexpr bool kBoxTested = true;
  static double firstAfter(const WorldItem& item, const Ray& ray, double tMin, double,
                           uint32_t&) {
    return sphereRoots(item.a, item.b.x, ray).firstAfter(tMin);
  }
  static Vec3 normal(const WorldItem& item, const Ray& ray, double t, uint32_t) {
    return (ray.at(t) - item.a) * item.b.y;  // times 1 / radius
  }
  static int crossings(const WorldItem& item, const Ray& ray, double tMin, double distance) {
    const SphereRoots r = sphereRoots(item.a, item.b.x, ray);
    if (!r.hit) return 0;
    return (r.t0 > tMin && r.t0 < distance) + (r.t1 > tMin && r.t1 < distance);
  }
};

struct BoxItem {
  static constexpr bool kBoxTested = true;
  static double firstAfter(const WorldItem& item, const Ray& ray, double tMin, double,
                           uint32_t&) {
    return boxSpan(item.a, item.b, ray).firstAfter(tMin);
  }
  static Vec3 normal(const WorldItem& item, const Ray& ray, double t, uint32_t) {
    const BoxSlabs s = boxSlabs(item.a, item.b, ray);
    Vec3 n = Vec3();
    if (t == s.tNear) {
      n[s.nearAxis] = s.nearSign;
    } else {
      n[s.farAxis] = s.farSign;
    }
    return n;
  }
  static int crossings(const WorldItem& item, const Ray& ray, double tMin, double distance) {
    const BoxSpan s = boxSpan(item.a, item.b, ray);
    if (!s.hit) return 0;
    return s.nearCrosses(tMin, distance) + s.farCrosses(tMin, distance);
  }
};

// A triangle mesh, in world space or placed by an instance.
struct MeshItem {
  static constexpr bool kBoxTested = false;
  // The ray in the coordinates of the item's tree (the same distances along it).
  static Ray local(const WorldItem& item, const Ray& ray) {
    if (item.meshFromWorld == nullptr) return ray;
    return {item.meshFromWorld->point(ray.origin), item.meshFromWorld->vector(ray.direction)};
  }
  // An instance the ray passes by is not worth carrying the ray over for.
  static bool passesBy(const WorldItem& item, const Ray& ray, double tMin, double tMax) {
    return item.meshFromWorld != nullptr &&
           !hitsBounds(Bounds{item.a, item.b}, RayQuery(ray), tMin, tMax);
  }
  static double firstAfter(const WorldItem& item, const Ray& ray, double tMin, double nearest,
                           uint32_t& triangle) {
    constexpr double kNone = std::numeric_limits<double>::quiet_NaN();
    if (passesBy(item, ray, tMin, nearest)) return kNone;
    double t = nearest;  // a crossing at `nearest` itself is reported: a tie to break
    return item.mesh->nearest(local(item, ray), tMin, t, triangle) ? t : kNone;
  }
  static Vec3 normal(const WorldItem& item, const Ray& ray, double, uint32_t triangle) {
    if (item.meshFromWorld == nullptr) return item.mesh->normal(ray, triangle);
    return normalize(
        Transform::normal(*item.meshFromWorld, item.mesh->normal(local(item, ray), triangle)));
  }
  static int crossings(const WorldItem& item, const Ray& ray, double tMin, double distance) {
    if (passesBy(item, ray, tMin, distance)) return 0;
    return item.mesh->crossings(local(item, ray), tMin, distance, item.transmissivity == 0);
  }
};

// The kinds, most common first (the dispatch tests them in this order).
using ItemKinds = std::tuple<SphereItem, BoxItem, MeshItem>;

// The index of Kind in ItemKinds: what WorldItem::kind holds for it.
template <typename Kind, size_t I = 0>
constexpr uint8_t itemKind() {
  static_assert(I < std::tuple_size_v<ItemKinds>, "not one of ItemKinds");
  if constexpr (std::is_same_v<Kind, std::tuple_element_t<I, ItemKinds>>) {
    return static_cast<uint8_t>(I);
  } else {
    return itemKind<Kind, I + 1>();
  }
}

// Calls f(Kind{}) for the kind with index `kind`, returning what it returns.
template <typename F>
[[gnu::always_inline]] inline auto visitItemKind(uint8_t kind, F&& f) {
  return [&]<size_t... I>(std::index_sequence<I...>) {
    using R = decltype(f(std::tuple_element_t<0, ItemKinds>{}));
    R result{};
    (void)((kind == I && ((result = f(std::tuple_element_t<I, ItemKinds>{})), true)) || ...);
    return result;
  }(std::make_index_sequence<std::tuple_size_v<ItemKinds>>{});
}

}  // namespace prt
