#pragma once
// Ray intersection with the paper's three primitives: sphere, axis-aligned box, one-sided
// plane. Each reports every crossing of the surface inside (tMin, tMax), nearest first, with
// the outward normal at it: the nearest answers camera and bounce rays, all of them let shadow
// rays be attenuated by each transmissive surface they cross.

#include "core/ray.h"
#include "trace/bounds.h"
#include "trace/scene.h"

namespace prt {

struct Crossings {
  int count = 0;      // 0, 1 or 2
  double t[2] = {0, 0};
  Vec3 normal[2];     // outward unit normal at each crossing
};

Crossings intersect(const SphereShape& s, const Ray& ray, double tMin, double tMax);
Crossings intersect(const BoxShape& b, const Ray& ray, double tMin, double tMax);
// One-sided: only rays travelling against the normal (arriving from the front) cross it.
Crossings intersect(const PlaneShape& p, const Ray& ray, double tMin, double tMax);

// Bounds of a shape; planes are unbounded and return an empty (inverted) box.
Bounds boundsOf(const Shape& shape);
bool isBounded(const Shape& shape);

}  // namespace prt
