#pragma once
// The meshes of an assimp scene as its node tree places them: each (mesh, node) pair with the
// node's absolute transform, in the order assimp's PreTransformVertices step would merge them
// (by material, then by vertex format, then depth-first through the tree), so that a mesh file
// flattened here gives the triangles, in the order, that step gave: bit for bit on 676 of the
// 678 files of Debian's assimp-testmodels that both read (the two others, a COLLADA cube and an
// IFC house, differ in the last bits of some vertices or in the order of some triangles). PRT does this
// itself because that step also moves the file's cameras and lights and crashes on a camera
// or light without a node (seen on OpenGEX files); a mesh file needs neither. One difference:
// a transform is taken as the identity only when it is exactly that (assimp's step skips
// transforms within 0.01 of it, a node's translation of a few millimetres).
//
// Refused with MeshFileError: a node that names a mesh the scene does not have, a tree deeper
// than kMaxNodeDepth or with more than kMaxPlacedNodes nodes (a hostile file), and placed
// meshes whose vertices would not fit the memory budget (core/memory_budget.h).

#include <assimp/matrix4x4.h>
#include <assimp/scene.h>

#include <string>
#include <vector>

namespace prt {

struct PlacedMesh {
  const aiMesh* mesh = nullptr;
  aiMatrix4x4 transform;  // the node's absolute transform
  bool identity = true;   // transform is the identity: the vertices are taken as they are
  aiMatrix3x3 normalTransform;  // inverse transpose of transform's 3x3 part
};

inline constexpr unsigned kMaxNodeDepth = 10000;
inline constexpr size_t kMaxPlacedNodes = size_t{1} << 24;

// `path` names the file in messages.
std::vector<PlacedMesh> placedMeshes(const aiScene& scene, const std::string& path);

// A vertex, and a normal (normalised), of `placed` in world space.
aiVector3D placedVertex(const PlacedMesh& placed, unsigned v);
aiVector3D placedNormal(const PlacedMesh& placed, unsigned v);

}  // namespace prt
