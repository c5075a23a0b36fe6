#pragma once
// The meshes of model files as the readers gather them (RawMesh: whatever the file held) and
// the checks that make them traceable (cleanMesh): triangles with an index out of range, a
// vertex that is not finite, or no area are left out and counted; normals that are not
// finite become zero (flat shading there), texture coordinates 0, colours white, tangents
// zero (no normal map there; tangents are kept only with texture coordinates). Shared by the
// glTF and the assimp readers. Pure; thread-safe.

#include <array>
#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "trace/triangle_mesh.h"

namespace prt {

// The readers' bounds on what one model file may ask for. Each placement of a mesh costs its
// scene and every worker a few hundred bytes, so a small file placing meshes many times over
// could ask for any amount of memory; and the node tree is walked recursively.
inline constexpr size_t kMaxModelObjects = size_t{1} << 20;
inline constexpr int kMaxModelNodeDepth = 1024;

struct RawMesh {
  std::vector<Vec3> positions;
  std::vector<Vec3> normals;                 // empty or one per position
  std::vector<std::array<float, 2>> uvs;     // empty or one per position (v down the image)
  std::vector<std::array<float, 3>> colors;  // empty or one per position, linear RGB
  std::vector<std::array<double, 4>> tangents;  // empty or one per position (glTF's TANGENT)
  std::vector<std::array<uint32_t, 3>> triangles;
};

// What cleaning left out, summed over a file's meshes for its warnings.
struct MeshSkips {
  size_t outOfRange = 0, notFinite = 0, zeroArea = 0, notTriangles = 0;
  // "skipped N triangles with ..." lines, naming `file`.
  void warn(std::vector<std::string>& warnings, const std::string& file) const;
};

// The traceable part of `raw`, its unused vertices dropped; null when no triangle is left.
std::shared_ptr<TriangleMesh> cleanMesh(RawMesh raw, MeshSkips& skips);

}  // namespace prt
