#include "trace/mesh_bvh.h"

#include <bit>
#include <string>
#include <utility>

#include "core/check.h"
#include "core/input_error.h"

namespace prt {

MeshBvh::MeshBvh(std::shared_ptr<const TriangleMesh> mesh) : mesh_(std::move(mesh)) {
  PRT_CHECK(mesh_ != nullptr && !mesh_->triangles.empty());
  if (mesh_->triangles.size() > QuadBvh::kMaxItems) {
    throw InputError("a mesh of " + std::to_string(mesh_->triangles.size()) +
                     " triangles: more than the " + std::to_string(QuadBvh::kMaxItems) +
                     " one mesh's tree holds; split it into several meshes");
  }
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
  bvh_ = QuadBvh(boxes, triangleOf_);
  boxes = {};  // no longer needed: free them before the corners are copied
  static_assert(QuadBvh::kBlockItems == kBlockLanes);
  PRT_CHECK(triangleOf_.size() % QuadBvh::kBlockItems == 0);
  blocks_.resize(triangleOf_.size() / QuadBvh::kBlockItems);
  for (size_t k = 0; k < triangleOf_.size(); ++k) {
    if (triangleOf_[k] == ~0u) continue;
    const auto& t = mesh_->triangles[triangleOf_[k]];
    const Vec3 &a = v[t[0]], &b = v[t[1]], &c = v[t[2]];
    const double pa[3] = {a.x, a.y, a.z}, pb[3] = {b.x, b.y, b.z}, pc[3] = {c.x, c.y, c.z};
    blocks_[k / QuadBvh::kBlockItems].set(static_cast<int>(k % QuadBvh::kBlockItems), pa, pb, pc);
  }
}

bool MeshBvh::nearest(const Ray& ray, double tMin, double& t, uint32_t& triangle) const {
  const ShearedRay4 sheared(ShearedRay{ray});
  const TriangleBlock* const blocks = blocks_.data();
  const uint32_t* const triangleOf = triangleOf_.data();
  double best = t;
  uint32_t bestTriangle = ~0u;
  bvh_.traverseBlocks<true>(ray, tMin, t, [&](uint32_t block, uint32_t used) {
    double d[kBlockLanes];
    int lanes = blockHits(sheared, blocks[block], static_cast<int>(used), tMin, best, true, d);
    for (; lanes != 0; lanes &= lanes - 1) {
      const int lane = std::countr_zero(static_cast<unsigned>(lanes));
      const uint32_t index = triangleOf[block * QuadBvh::kBlockItems + lane];
      if (d[lane] < best || (d[lane] == best && index < bestTriangle)) {
        best = d[lane];
        bestTriangle = index;
      }
    }
    return best;
  });
  if (bestTriangle == ~0u) return false;
  t = best;
  triangle = bestTriangle;
  return true;
}

int MeshBvh::crossings(const Ray& ray, double tMin, double tMax, bool atMostOne) const {
  const ShearedRay4 sheared(ShearedRay{ray});
  const TriangleBlock* const blocks = blocks_.data();
  int count = 0;
  bvh_.traverseBlocks<false>(ray, tMin, tMax, [&](uint32_t block, uint32_t used) {
    double d[kBlockLanes];
    const int lanes = blockHits(sheared, blocks[block], static_cast<int>(used), tMin, tMax, false, d);
    if (atMostOne) {
      if (lanes == 0) return tMax;
      count = 1;
      return -1.0;  // stops the traversal
    }
    // No branch on a coin toss; and no std::popcount, a library call in the baseline build.
    const int pairs = lanes - ((lanes >> 1) & 0x55);
    const int quads = (pairs & 0x33) + ((pairs >> 2) & 0x33);
    count += (quads + (quads >> 4)) & 0x0f;
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
