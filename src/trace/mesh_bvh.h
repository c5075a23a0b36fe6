#pragma once
// MeshBvh: one triangle mesh prepared for tracing, its own QuadBvh (binned build) over its
// triangles. World holds a mesh as a single item of its own structures (the scene's BVH, the
// view lists, the shadow shafts, the neighbour lists and the order that breaks ties), whose
// hit function is this class: those structures stay at the scale of a scene's objects, a few
// hundred, however many triangles the meshes have.
//
// Results do not depend on the order the tree offers triangles in: the nearest crossing is the
// least (distance, triangle index), and a shadow ray needs only how many triangles it crosses.
// Built once, then read-only: safe to query from many threads.

#include <cstdint>
#include <memory>
#include <vector>

#include "core/ray.h"
#include "trace/bounds.h"
#include "trace/quad_bvh.h"
#include "trace/triangle.h"
#include "trace/triangle_block.h"
#include "trace/triangle_mesh.h"

namespace prt {

class MeshBvh {
 public:
  explicit MeshBvh(std::shared_ptr<const TriangleMesh> mesh);

  const Bounds& bounds() const { return bounds_; }
  const TriangleMesh* mesh() const { return mesh_.get(); }
  const TriangleMesh& triangles() const { return *mesh_; }
  size_t triangleCount() const { return mesh_->triangles.size(); }
  // Memory held for tracing (tree and triangle corners), the mesh itself not counted.
  size_t bytes() const {
    return bvh_.bytes() + blocks_.capacity() * sizeof(TriangleBlock) +
           triangleOf_.capacity() * sizeof(uint32_t);
  }

  // The nearest crossing within (tMin, tMax], ties to the lowest triangle index: true, with
  // t lowered to it and `triangle` set, or false with both unchanged. A crossing at tMax is
  // reported, so that the caller can break a tie with another object.
  bool nearest(const Ray& ray, double tMin, double& t, uint32_t& triangle) const;
  // How many triangles the ray crosses within (tMin, tMax); with `atMostOne`, stops at the
  // first (0 or 1: whether any is crossed, all an opaque mesh's shadow ray needs).
  int crossings(const Ray& ray, double tMin, double tMax, bool atMostOne = false) const;
  // The unit normal to shade with where the ray met `triangle` at distance t: the geometric
  // one (from the winding: counter-clockwise seen from its side), or the vertex normals
  // interpolated when the mesh has them, turned to the geometric one's side of the ray (the
  // shader tells entering from leaving by it).
  Vec3 normal(const Ray& ray, uint32_t triangle) const;

 private:
  std::shared_ptr<const TriangleMesh> mesh_;
  // The tree's leaves: blocks of up to eight triangles tested at once, in the order the tree
  // lays them out (near ones close in memory), and the index in the mesh of the triangle in
  // each lane (~0u for an unused lane, whose corners are NaN).
  std::vector<TriangleBlock> blocks_;
  std::vector<uint32_t> triangleOf_;
  QuadBvh bvh_;
  Bounds bounds_;
};

}  // namespace prt
