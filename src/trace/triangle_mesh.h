#pragma once
// TriangleMesh: the triangles of one scene object, as loaded from a mesh file (or written
// inline as `triangle` blocks) with the object's transform already applied: world-space
// vertices, three vertex indices per triangle, and optionally one unit normal per vertex for
// smooth shading. Plain data, shared read-only (through MeshShape's shared_ptr) by the scene,
// its copies and the World built from it. Loaders guarantee what World relies on: finite
// vertices, indices in range, no triangle of zero area, normals finite.

#include <array>
#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "core/vec3.h"

namespace prt {

struct TriangleMesh {
  std::vector<Vec3> vertices;                      // world units
  std::vector<std::array<uint32_t, 3>> triangles;  // counter-clockwise seen from outside
  // One per vertex, unit length (or zero where the faces around a vertex cancel, when they
  // were computed); empty: flat shading.
  std::vector<Vec3> normals;
  // Per vertex, or empty: texture coordinates (u across, v down the image: trace/texture.h)
  // and linear RGB colours (which multiply the material's colour).
  std::vector<std::array<float, 2>> uvs;
  std::vector<std::array<float, 3>> colors;
  // Per vertex, or empty (only with `uvs`): glTF's TANGENT, for normal maps (trace/tangents.h):
  // x, y, z a unit vector along which u grows (zero: none known there), w = +1 or -1 the
  // handedness: the bitangent, along which v falls (up the image), is w cross(normal, xyz).
  std::vector<std::array<double, 4>> tangents;
  bool operator==(const TriangleMesh&) const = default;
};

// How a `mesh` block placed its file: kept so that the scene can be written back as it was read.
struct MeshSource {
  std::string file;     // absolute, as resolved against the scene file's directory
  Vec3 scale{1, 1, 1};  // applied first,
  Vec3 rotateDegrees;   // then rotations about x, then y, then z,
  Vec3 translate;       // then the translation
  bool smooth = false;  // vertex normals computed from the faces when the file has none
  bool operator==(const MeshSource&) const = default;
};

struct MeshShape {
  std::shared_ptr<const TriangleMesh> mesh;  // never null
  MeshSource source;  // file empty: inline `triangle` blocks, written back from `mesh`
  bool operator==(const MeshShape& o) const {
    return source == o.source && (mesh == o.mesh || *mesh == *o.mesh);
  }
};

}  // namespace prt
