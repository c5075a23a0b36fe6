#include "trace/mesh_bvh.h"

#include <utility>

#include "core/check.h"

namespace prt {

MeshBvh::MeshBvh(std::shared_ptr<const TriangleMesh> mesh) : mesh_(std::move(mesh)) {
  PRT_CHECK(mesh_ != nullptr && !mesh_->triangles.empty());
  const std::vector<Vec3>& v = mesh_->vertices;
  std::vector<Bounds> boxes;
  boxes.reserve(mesh_->triangles.size());
  for (const auto& t : mesh_->triangles) {
    PRT_CHECK(t[0] < v.size() && t[1] < v.size() && t[2] < v.size());
    Bounds box;
    box.extend(v[t[0]]);
    box.extend(v[t[1]]);
    box.extend(v[t[2]]);
    bounds_.extend(box);
    boxes.push_back(box);
  }
  bvh_ = QuadBvh(boxes, BvhBuild::binned);
  boxes = {};  // no longer needed: free them before the corners are copied
  triangleOf_ = bvh_.itemOrder();
  PRT_CHECK(triangleOf_.size() == mesh_->triangles.size());
  std::vector<uint32_t> place(triangleOf_.size());
  corners_.reserve(triangleOf_.size());
  for (uint32_t i = 0; i < triangleOf_.size(); ++i) {
    place[triangleOf_[i]] = i;
    const auto& t = mesh_->triangles[triangleOf_[i]];
    const Vec3 &a = v[t[0]], &b = v[t[1]], &c = v[t[2]];
    corners_.push_back({{a.x, a.y, a.z}, {b.x, b.y, b.z}, {c.x, c.y, c.z}});
  }
  bvh_.renameItems(place);
}

bool MeshBvh::nearest(const Ray& ray, double tMin, double& t, uint32_t& triangle) const {
  const ShearedRay sheared(ray);
  const Corners* const corners = corners_.data();
  double best = t;
  uint32_t bestTriangle = ~0u;
  bvh_.traverse<true>(ray, tMin, t, [&](uint32_t index) {
    const Corners& c = corners[index];
    const double d = triangleDistance(sheared, c.a, c.b, c.c);  // NaN fails every test
    if (d > tMin && (d < best || (d == best && triangleOf_[index] < bestTriangle))) {
      best = d;
      bestTriangle = triangleOf_[index];
    }
    return best;
  });
  if (bestTriangle == ~0u) return false;
  t = best;
  triangle = bestTriangle;
  return true;
}

int MeshBvh::crossings(const Ray& ray, double tMin, double tMax, bool atMostOne) const {
  const ShearedRay sheared(ray);
  const Corners* const corners = corners_.data();
  int count = 0;
  bvh_.traverse<false>(ray, tMin, tMax, [&](uint32_t index) {
    const Corners& c = corners[index];
    const double d = triangleDistance(sheared, c.a, c.b, c.c);
    if (d > tMin && d < tMax) {
      ++count;
      if (atMostOne) return -1.0;  // stops the traversal
    }
    return tMax;
  });
  return count;
}

Vec3 MeshBvh::normal(const Ray& ray, uint32_t triangle) const {
  const auto& t = mesh_->triangles[triangle];
  const Vec3 &a = mesh_->vertices[t[0]], &b = mesh_->vertices[t[1]], &c = mesh_->vertices[t[2]];
  const Vec3 geometric = normalize(cross(b - a, c - a));
  if (mesh_->normals.empty()) return geometric;
  const TriangleHit h = triangleHit(ShearedRay(ray), a, b, c);
  const std::vector<Vec3>& n = mesh_->normals;
  const Vec3 blend = h.u * n[t[0]] + h.v * n[t[1]] + h.w * n[t[2]];
  const double size = length(blend);
  if (!(size > 1e-12)) return geometric;  // opposite normals cancel: no direction to trust
  const Vec3 smooth = blend / size;
  // Entering or leaving must be the same for both normals.
  if ((dot(smooth, ray.direction) < 0) != (dot(geometric, ray.direction) < 0)) return geometric;
  return smooth;
}

}  // namespace prt
