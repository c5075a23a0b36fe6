#include "trace/world.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>
#include <string>
#include <utility>
#include <variant>

#if defined(__SSE2__)
#include <emmintrin.h>
#endif

#include "core/input_error.h"
#include "core/overloaded.h"
#include "trace/bvh.h"
#include "trace/shapes.h"
#include "trace/triangle.h"

namespace prt {
namespace {

// Bits 1, 2, 4 set for a negative x, y, z direction component (as Bvh::traverse tests it:
// -0 is not negative).
int octantOf(const Vec3& d) {
#if defined(__SSE2__)
  const __m128d zero = _mm_setzero_pd();
  return _mm_movemask_pd(_mm_cmplt_pd(_mm_loadu_pd(&d.x), zero)) |
         (_mm_movemask_pd(_mm_cmplt_sd(_mm_load_sd(&d.z), zero)) & 1) << 2;
#else
  return (d.x < 0 ? 1 : 0) | (d.y < 0 ? 2 : 0) | (d.z < 0 ? 4 : 0);
#endif
}

// The transmissive surfaces a shadow ray crosses, kept in rank order: the product is taken in
// that order whatever order the BVH found them in. Rarely more than a handful.
class Attenuators {
 public:
  void add(uint32_t rank, int crossings, double transmissivity) {
    if (count_ == kInline && spill_.empty()) spill_.assign(inline_, inline_ + kInline);
    Entry* data = spill_.empty() ? inline_ : (spill_.push_back({}), spill_.data());
    uint32_t i = count_++;
    for (; i > 0 && data[i - 1].rank > rank; --i) data[i] = data[i - 1];
    data[i] = {rank, crossings, transmissivity};
  }
  // Multiplies `passed` by every transmissivity, once per crossing, as the objects were
  // visited one by one before: stopping once nothing passes.
  double apply(double passed) const {
    const Entry* data = spill_.empty() ? inline_ : spill_.data();
    for (uint32_t e = 0; e < count_; ++e) {
      for (int i = 0; i < data[e].crossings && passed > 0; ++i) passed *= data[e].transmissivity;
    }
    return passed;
  }

 private:
  struct Entry {
    uint32_t rank;
    int crossings;
    double transmissivity;
  };
  static constexpr uint32_t kInline = 16;
  Entry inline_[kInline];
  std::vector<Entry> spill_;
  uint32_t count_ = 0;
};

// Every point a shadow ray towards the light may aim at (all of space for a directional
// light, whose shadow rays run to infinity).
Bounds boundsOf(const LightShape& shape) {
  Bounds b;
  if (const auto* p = std::get_if<PointLight>(&shape)) {
    b.extend(p->position);
  } else if (const auto* spot = std::get_if<SpotLight>(&shape)) {
    b.extend(spot->position);
  } else if (std::holds_alternative<DirectionalLight>(shape)) {
    const double inf = std::numeric_limits<double>::infinity();
    b = Bounds{Vec3(-inf), Vec3(inf)};
  } else if (const auto* s = std::get_if<SphereLight>(&shape)) {
    b.extend(s->center - Vec3(s->radius));
    b.extend(s->center + Vec3(s->radius));
  } else {
    const auto& r = std::get<RectLight>(shape);
    for (const Vec3& q :
         {r.corner, r.corner + r.edge1, r.corner + r.edge2, r.corner + r.edge1 + r.edge2}) {
      b.extend(q);
    }
  }
  return b;
}

}  // namespace

const MeshBvh& World::treeFor(const std::shared_ptr<const TriangleMesh>& mesh,
                              const World* reuse) {
  for (const auto& tree : meshes_) {
    if (tree->mesh() == mesh.get()) return *tree;  // placed again: built once
  }
  if (reuse != nullptr) {
    for (const auto& tree : reuse->meshes_) {
      if (tree->mesh() == mesh.get()) return *meshes_.emplace_back(tree);
    }
  }
  const auto start = std::chrono::steady_clock::now();
  meshes_.push_back(std::make_shared<const MeshBvh>(mesh));
  const MeshBvh& tree = *meshes_.back();
  meshStats_.buildSeconds +=
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  ++meshStats_.meshes;
  meshStats_.triangles += tree.triangleCount();
  meshStats_.bytes += tree.bytes();
  return tree;
}

World::World(Scene scene, const World* reuse) : scene_(std::move(scene)) {
  environment_ = reuse != nullptr && reuse->environment_->sameAs(scene_.environment)
                     ? reuse->environment_
                     : std::make_shared<const EnvironmentLight>(scene_.environment);
  for (uint32_t i = 0; i < scene_.objects.size(); ++i) {
    const Object& o = scene_.objects[i];
    const double transmissivity = o.material.transmissivity;
    std::visit(
        Overloaded{
            [&](const SphereShape& s) {
              items_.push_back({s.center, Vec3(s.radius, 1.0 / s.radius, 0), boundsOf(o.shape),
                                transmissivity, i, itemKind<SphereItem>()});
            },
            [&](const BoxShape& b) {
              items_.push_back(
                  {b.min, b.max, boundsOf(o.shape), transmissivity, i, itemKind<BoxItem>()});
            },
            [&](const MeshShape& m) {
              const MeshBvh& mesh = treeFor(m.mesh, reuse);
              items_.push_back({Vec3(), Vec3(), mesh.bounds(), transmissivity, i,
                                itemKind<MeshItem>(), &mesh});
            },
            [&](const InstanceShape& instance) {
              const MeshBvh& mesh = treeFor(instance.mesh, reuse);
              ++meshStats_.instances;
              placements_.push_back(
                  std::make_unique<Transform>(instance.worldFromMesh.inverse()));
              const Bounds box = placedBounds(mesh.bounds(), instance.worldFromMesh);
              // Tested before a ray is carried into the mesh's coordinates; widened far beyond
              // the rounding of the placement, so that it never turns away a ray the mesh's
              // tree meets.
              const Bounds reach = box.widened(1e-9 * std::max(1.0, box.largestMagnitude()));
              items_.push_back({reach.lo, reach.hi, box, transmissivity, i, itemKind<MeshItem>(),
                                &mesh, placements_.back().get()});
            },
            [&](const PlaneShape& p) { planes_.push_back({p.point, p.normal, transmissivity, i}); },
        },
        o.shape);
  }
  const std::vector<Bounds> boxes = itemBounds();
  if (boxes.size() > QuadBvh::kMaxItems) {
    throw InputError("a scene of " + std::to_string(boxes.size()) + " objects: more than the " +
                     std::to_string(QuadBvh::kMaxItems) + " its tree holds");
  }
  for (const Bounds& b : boxes) itemsBox_.extend(b);
  bvh_ = QuadBvh(boxes);
  std::vector<Bounds> lights;
  for (const Light& light : scene_.lights) lights.push_back(boundsOf(light.shape));
  shafts_ = ShadowShafts(boxes, lights);
  itemOfObject_.assign(scene_.objects.size(), ~0u);
  for (uint32_t i = 0; i < items_.size(); ++i) itemOfObject_[items_[i].object] = i;
  buildNeighbours(boxes);
  const Bvh order(boxes);
  ranks_.resize(8 * items_.size());
  for (int octant = 0; octant < 8; ++octant) {
    const std::vector<uint32_t> visit = order.visitOrder(octant);
    for (uint32_t position = 0; position < visit.size(); ++position) {
      ranks_[octant * items_.size() + visit[position]] = position + 1;
    }
  }
}

bool World::intersect(const Ray& ray, double tMin, double tMax, Hit& hit) const {
  return intersect(ray, tMin, tMax, hit, [&](double& nearest, auto&& visit) {
    bvh_.traverse<true>(ray, tMin, nearest, visit);
  });
}

bool World::intersectAmong(std::span<const uint32_t> candidates, const Ray& ray, double tMin,
                           double tMax, Hit& hit) const {
  return intersect(ray, tMin, tMax, hit, [&](double&, auto&& visit) {
    for (const uint32_t index : candidates) visit(index);
  });
}

void World::buildNeighbours(const std::vector<Bounds>& boxes) {
  constexpr size_t kMostItems = 256;  // pairing them all costs n^2 box tests
  constexpr uint32_t kLongest = 8;
  if (boxes.empty() || boxes.size() > kMostItems) return;
  double magnitude = 1;
  for (const Bounds& b : boxes) magnitude = std::max(magnitude, b.largestMagnitude());
  // Far above the shader's surface offset (1e-9 of the magnitude) and any rounding.
  const double margin = 1e-6 * magnitude;
  for (const Bounds& b : boxes) {
    const Bounds reach = b.widened(2 * margin);
    Neighbours n{b.widened(margin), static_cast<uint32_t>(neighbourItems_.size()), 0};
    for (uint32_t j = 0; j < boxes.size(); ++j) {
      if (reach.overlaps(boxes[j])) neighbourItems_.push_back(j);
    }
    n.count = static_cast<uint32_t>(neighbourItems_.size()) - n.begin;
    if (n.count > kLongest) {  // too crowded: left to the BVH
      neighbourItems_.resize(n.begin);
      n = Neighbours{};  // an empty box never contains a ray's origin
    }
    neighbours_.push_back(n);
  }
}

bool World::intersectFromInside(uint32_t object, const Ray& ray, Hit& hit) const {
  const uint32_t item = object < itemOfObject_.size() ? itemOfObject_[object] : ~0u;
  if (item < neighbours_.size()) {
    const Neighbours& n = neighbours_[item];
    // From inside the box to a hit inside it, the ray never left it: nothing else came nearer.
    if (n.box.contains(ray.origin) &&
        intersectAmong({neighbourItems_.data() + n.begin, n.count}, ray, 0.0,
                       std::numeric_limits<double>::infinity(), hit) &&
        n.box.contains(hit.point)) {
      return true;
    }
  }
  return intersect(ray, 0.0, std::numeric_limits<double>::infinity(), hit);
}

SurfaceAttributes World::attributesAt(const Ray& ray, const Hit& hit) const {
  SurfaceAttributes a;
  const uint32_t index = hit.object < itemOfObject_.size() ? itemOfObject_[hit.object] : ~0u;
  if (index >= items_.size() || items_[index].mesh == nullptr) return a;
  const Item& item = items_[index];
  const TriangleMesh& mesh = item.mesh->triangles();
  if (mesh.uvs.empty() && mesh.colors.empty()) return a;
  const auto& t = mesh.triangles[hit.triangle];
  const TriangleHit h = triangleHit(ShearedRay(MeshItem::local(item, ray)), mesh.vertices[t[0]],
                                    mesh.vertices[t[1]], mesh.vertices[t[2]]);
  // Weights of a ray that grazes an edge may be a hair outside [0, 1]; they still interpolate.
  if (!mesh.uvs.empty()) {
    const auto &p = mesh.uvs[t[0]], &q = mesh.uvs[t[1]], &r = mesh.uvs[t[2]];
    a.u = h.u * p[0] + h.v * q[0] + h.w * r[0];
    a.v = h.u * p[1] + h.v * q[1] + h.w * r[1];
  }
  if (!mesh.colors.empty()) {
    const auto &p = mesh.colors[t[0]], &q = mesh.colors[t[1]], &r = mesh.colors[t[2]];
    a.color = {h.u * p[0] + h.v * q[0] + h.w * r[0], h.u * p[1] + h.v * q[1] + h.w * r[1],
               h.u * p[2] + h.v * q[2] + h.w * r[2]};
  }
  if (!mesh.tangents.empty()) {
    const auto &p = mesh.tangents[t[0]], &q = mesh.tangents[t[1]], &r = mesh.tangents[t[2]];
    a.tangent = {h.u * p[0] + h.v * q[0] + h.w * r[0], h.u * p[1] + h.v * q[1] + h.w * r[1],
                 h.u * p[2] + h.v * q[2] + h.w * r[2]};
    a.handedness = h.u * p[3] + h.v * q[3] + h.w * r[3] < 0 ? -1 : 1;
    if (const auto* instance = std::get_if<InstanceShape>(&scene_.objects[hit.object].shape)) {
      a.tangent = instance->worldFromMesh.vector(a.tangent);
      // A mirroring placement turns cross(normal, tangent) the other way.
      if (instance->worldFromMesh.determinant() < 0) a.handedness = -a.handedness;
    }
  }
  return a;
}

std::vector<Bounds> World::itemBounds() const {
  std::vector<Bounds> boxes;
  for (const Item& item : items_) boxes.push_back(item.box);
  return boxes;
}

template <typename Candidates>
bool World::intersect(const Ray& ray, double tMin, double tMax, Hit& hit,
                      Candidates&& candidates) const {
  // The best so far: its distance `nearest`, and its rank (0 for a plane: planes came first,
  // and no bounded object's rank is below it; also 0 before any hit, when ties must lose).
  double nearest = tMax;
  uint32_t bestRank = 0;
  const Plane* bestPlane = nullptr;
  const Item* bestItem = nullptr;
  uint32_t bestTriangle = 0;
  for (const Plane& p : planes_) {
    const double t = planeDistance(p.point, p.normal, ray);
    if (t > tMin && t < nearest) {
      nearest = t;
      bestPlane = &p;
    }
  }
  const uint32_t* ranks = ranks_.data() + octantOf(ray.direction) * items_.size();
  candidates(nearest, [&](uint32_t index) {
    const Item& item = items_[index];
    return visitItemKind(item.kind, [&]<typename Kind>(Kind) {
      uint32_t triangle = 0;
      const double t = Kind::firstAfter(item, ray, tMin, nearest, triangle);
      // Farther, or as far but later in the order (NaN, no crossing, fails both tests).
      if (!(t < nearest || (t == nearest && ranks[index] < bestRank))) return nearest;
      // The paper's per-object box test, which the object had to pass before.
      if constexpr (Kind::kBoxTested) {
        if (!hitsBounds(item.box, RayQuery(ray), tMin, nearest)) return nearest;
      }
      nearest = t;
      bestRank = ranks[index];
      bestItem = &item;
      bestTriangle = triangle;
      return nearest;
    });
  });
  if (bestItem != nullptr) {
    // The normal as intersect(shape) gives it for its first crossing, which is this one.
    hit.object = bestItem->object;
    hit.triangle = bestTriangle;
    hit.normal = visitItemKind(bestItem->kind, [&]<typename Kind>(Kind) {
      return Kind::normal(*bestItem, ray, nearest, bestTriangle);
    });
  } else if (bestPlane != nullptr) {
    hit.object = bestPlane->object;
    hit.normal = bestPlane->normal;
  } else {
    return false;
  }
  hit.t = nearest;
  hit.point = ray.at(nearest);
  return true;
}

template <typename Candidates>
double World::transmittance(const Ray& ray, double tMin, double distance,
                            Candidates&& candidates) const {
  double passed = 1.0;
  for (const Plane& p : planes_) {
    const double t = planeDistance(p.point, p.normal, ray);
    if (t > tMin && t < distance) {
      passed *= p.transmissivity;
      if (passed == 0) return 0;
    }
  }
  // Plain pointers, loaded once (the visits below would load the vectors' again each time);
  // the ranks are needed only for an object that lets light through.
  const Item* const items = items_.data();
  const uint32_t* const ranks = ranks_.data();
  const size_t itemCount = items_.size();
  Attenuators attenuators;
  bool opaque = false;
  candidates([&](uint32_t index) {
    const Item& item = items[index];
    const int crossings = visitItemKind(item.kind, [&]<typename Kind>(Kind) {
      const int c = Kind::crossings(item, ray, tMin, distance);
      if constexpr (Kind::kBoxTested) {
        if (c != 0 && !hitsBounds(item.box, RayQuery(ray), tMin, distance)) return 0;
      }
      return c;
    });
    if (crossings == 0) return distance;
    if (item.transmissivity == 0) {  // nothing passes, whatever else is crossed
      opaque = true;
      return -1.0;
    }
    attenuators.add(ranks[octantOf(ray.direction) * itemCount + index], crossings,
                    item.transmissivity);
    return distance;
  });
  return opaque ? 0.0 : attenuators.apply(passed);
}

bool World::occluded(const Ray& ray, double tMin, double distance) const {
  for (const Plane& p : planes_) {
    const double t = planeDistance(p.point, p.normal, ray);
    if (t > tMin && t < distance) return true;
  }
  const Item* const items = items_.data();
  bool blocked = false;
  bvh_.traverse<false>(ray, tMin, distance, [&](uint32_t index) {
    const Item& item = items[index];
    const int crossings = visitItemKind(item.kind, [&]<typename Kind>(Kind) {
      if constexpr (std::is_same_v<Kind, MeshItem>) {
        if (MeshItem::passesBy(item, ray, tMin, distance)) return 0;
        return item.mesh->crossings(MeshItem::local(item, ray), tMin, distance, true);
      } else {
        const int c = Kind::crossings(item, ray, tMin, distance);
        if constexpr (Kind::kBoxTested) {
          if (c != 0 && !hitsBounds(item.box, RayQuery(ray), tMin, distance)) return 0;
        }
        return c;
      }
    });
    if (crossings == 0) return distance;
    blocked = true;
    return -1.0;
  });
  return blocked;
}

double World::transmittance(const Ray& ray, double tMin, double distance) const {
  return transmittance(ray, tMin, distance,
                       [&](auto&& visit) { bvh_.traverse<false>(ray, tMin, distance, visit); });
}

double World::transmittanceToLight(size_t light, const Ray& ray, double distance) const {
  return transmittanceToLight(shadowOrigin(ray.origin), light, ray, distance);
}

double World::transmittanceToLight(const ShadowOrigin& from, size_t light, const Ray& ray,
                                   double distance) const {
  const auto listed = shafts_.candidatesIn(from.cell, light);
  if (!listed) {
    // A ray that misses the box around all the bounded objects fails each object's own box
    // test too (the same arithmetic on wider bounds): only the planes can be in its way. Four
    // in five of the benchmark scene's rays from outside the grid (the far floor) are so.
    if (!hitsBounds(itemsBox_, RayQuery(ray), 0.0, distance)) {
      return transmittance(ray, 0.0, distance, [](auto&&) {});
    }
    return transmittance(ray, 0.0, distance);
  }
  return transmittance(ray, 0.0, distance, [&](auto&& visit) {
    for (const uint32_t index : *listed) {
      if (visit(index) < 0) return;
    }
  });
}

}  // namespace prt
