#include "trace/world.h"

#include "trace/shapes.h"

namespace prt {
namespace {

Crossings crossings(const Shape& shape, const Ray& ray, double tMin, double tMax) {
  return std::visit([&](const auto& s) { return intersect(s, ray, tMin, tMax); }, shape);
}

}  // namespace

World::World(Scene scene) : scene_(std::move(scene)) {
  for (uint32_t i = 0; i < scene_.objects.size(); ++i) {
    const Shape& shape = scene_.objects[i].shape;
    if (isBounded(shape)) {
      bounded_.push_back(i);
      boxes_.push_back(boundsOf(shape));
    } else {
      unbounded_.push_back(i);
    }
  }
  bvh_ = Bvh(boxes_);
}

bool World::intersect(const Ray& ray, double tMin, double tMax, Hit& hit) const {
  bool found = false;
  auto consider = [&](uint32_t object) {
    const Crossings c = crossings(scene_.objects[object].shape, ray, tMin, tMax);
    if (c.count > 0) {
      tMax = c.t[0];
      hit.t = c.t[0];
      hit.normal = c.normal[0];
      hit.object = object;
      found = true;
    }
  };
  for (uint32_t object : unbounded_) consider(object);
  const RayQuery q(ray);
  bvh_.traverse(q, tMin, tMax, [&](uint32_t item) {
    if (hitsBounds(boxes_[item], q, tMin, tMax)) consider(bounded_[item]);
    return tMax;
  });
  if (found) hit.point = ray.at(hit.t);
  return found;
}

double World::transmittance(const Ray& ray, double tMin, double distance) const {
  double passed = 1.0;
  auto attenuate = [&](uint32_t object) {
    const Crossings c = crossings(scene_.objects[object].shape, ray, tMin, distance);
    for (int i = 0; i < c.count && passed > 0; ++i) passed *= material(object).transmissivity;
  };
  for (uint32_t object : unbounded_) {
    attenuate(object);
    if (passed == 0) return 0;
  }
  const RayQuery q(ray);
  bvh_.traverse(q, tMin, distance, [&](uint32_t item) {
    if (hitsBounds(boxes_[item], q, tMin, distance)) attenuate(bounded_[item]);
    return passed == 0 ? -1.0 : distance;
  });
  return passed;
}

}  // namespace prt
