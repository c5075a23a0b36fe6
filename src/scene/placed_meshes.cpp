#include "scene/placed_meshes.h"

#include <algorithm>
#include <utility>

#include "core/memory_budget.h"
#include "core/text.h"
#include "scene/mesh_file.h"

namespace prt {
namespace {

// What the vertex format of a mesh is, as a number whose order is the order assimp merges
// meshes of one material in: normals, tangents, each texture-coordinate set (and whether it
// is 3D), each colour set.
unsigned vertexFormat(const aiMesh& mesh) {
  unsigned format = 0;
  if (mesh.HasNormals()) format |= 0x2;
  if (mesh.HasTangentsAndBitangents()) format |= 0x4;
  for (unsigned p = 0; p < 8 && mesh.HasTextureCoords(p); ++p) {
    format |= 0x100u << p;
    if (mesh.mNumUVComponents[p] == 3) format |= 0x10000u << p;
  }
  for (unsigned p = 0; p < 8 && mesh.HasVertexColors(p); ++p) format |= 0x1000000u << p;
  return format;
}

// Exactly the identity (assimp's own IsIdentity allows 0.01 off, which would drop a node's
// translation of a few millimetres).
bool exactlyIdentity(const aiMatrix4x4& m) {
  const aiMatrix4x4 identity;
  for (unsigned r = 0; r < 4; ++r) {
    for (unsigned c = 0; c < 4; ++c) {
      if (m[r][c] != identity[r][c]) return false;
    }
  }
  return true;
}

}  // namespace

std::vector<PlacedMesh> placedMeshes(const aiScene& scene, const std::string& path) {
  struct Visit {
    const aiNode* node;
    aiMatrix4x4 parent;
    unsigned depth;
  };
  struct Found {
    unsigned material, format;
    PlacedMesh placed;
  };
  std::vector<Found> found;
  if (scene.mRootNode == nullptr || scene.mNumMeshes == 0) return {};
  std::vector<Visit> stack{{scene.mRootNode, aiMatrix4x4(), 0}};
  size_t visited = 0;
  uint64_t vertexBytes = 0;
  const uint64_t budget = memoryBudgetBytes();
  while (!stack.empty()) {
    const Visit visit = stack.back();
    stack.pop_back();
    if (++visited > kMaxPlacedNodes || visit.depth > kMaxNodeDepth) {
      throw MeshFileError("mesh file " + quote(path) + ": its node tree is larger than " +
                          std::to_string(kMaxPlacedNodes) + " nodes or deeper than " +
                          std::to_string(kMaxNodeDepth));
    }
    const aiNode& node = *visit.node;
    const aiMatrix4x4 transform =
        visit.depth == 0 ? node.mTransformation : visit.parent * node.mTransformation;
    for (unsigned i = 0; i < node.mNumMeshes; ++i) {
      const unsigned index = node.mMeshes[i];
      if (index >= scene.mNumMeshes || scene.mMeshes[index] == nullptr) {
        throw MeshFileError("mesh file " + quote(path) + ": node \"" +
                            std::string(node.mName.C_Str()) + "\" refers to mesh " +
                            std::to_string(index) + ", which the file does not have");
      }
      const aiMesh& mesh = *scene.mMeshes[index];
      // Each placement is a copy of the mesh's vertices (position and normal, in doubles).
      vertexBytes += uint64_t{mesh.mNumVertices} * 48 + uint64_t{mesh.mNumFaces} * 12;
      if (vertexBytes > budget) {
        throw MeshFileError("mesh file " + quote(path) + ": its placed meshes need more than " +
                            formatMemorySize(budget) +
                            ", the memory budget (--max-memory sets it)");
      }
      PlacedMesh placed;
      placed.mesh = &mesh;
      placed.transform = transform;
      placed.identity = exactlyIdentity(transform);
      if (!placed.identity) {
        aiMatrix4x4 inverse = transform;
        inverse.Inverse().Transpose();
        placed.normalTransform = aiMatrix3x3(inverse);
      }
      found.push_back({mesh.mMaterialIndex, vertexFormat(mesh), placed});
    }
    // Children pushed last first, so that they are visited first to last (depth-first).
    if (node.mNumChildren > 0 && node.mChildren == nullptr) continue;
    for (unsigned c = node.mNumChildren; c-- > 0;) {
      if (node.mChildren[c] != nullptr) {
        stack.push_back({node.mChildren[c], transform, visit.depth + 1});
      }
    }
  }
  std::stable_sort(found.begin(), found.end(), [](const Found& a, const Found& b) {
    return std::pair(a.material, a.format) < std::pair(b.material, b.format);
  });
  std::vector<PlacedMesh> out;
  out.reserve(found.size());
  for (const Found& f : found) out.push_back(f.placed);
  return out;
}

aiVector3D placedVertex(const PlacedMesh& placed, unsigned v) {
  const aiVector3D& p = placed.mesh->mVertices[v];
  return placed.identity ? p : placed.transform * p;
}

aiVector3D placedNormal(const PlacedMesh& placed, unsigned v) {
  const aiVector3D& n = placed.mesh->mNormals[v];
  return placed.identity ? n : (placed.normalTransform * n).Normalize();
}

}  // namespace prt
