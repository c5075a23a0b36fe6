#include "scene/mesh_file.h"

#include <assimp/postprocess.h>
#include <assimp/scene.h>

#include <assimp/Importer.hpp>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <unordered_map>

#include "core/input_error.h"
#include "core/input_file.h"
#include "core/portable_math.h"
#include "core/text.h"
#include "scene/contained_readers.h"
#include "scene/mesh_text_check.h"
#include "scene/placed_meshes.h"

namespace prt {
namespace {

std::string readFile(const std::string& path) {
  std::string text;
  try {
    text = readInputFile(path, "mesh file");
  } catch (const InputError& e) {
    std::string message = e.what();
    // The one example model not in the repository (its licence is the npm package's).
    if (std::filesystem::path(path).filename() == "bunny.ply" &&
        !std::filesystem::exists(path)) {
      message += " (the Stanford bunny is fetched by scripts/fetch-bunny.sh, which "
                 "scripts/test.sh runs; scripts/demo.sh does not)";
    }
    throw MeshFileError(message);
  }
  if (text.empty()) throw MeshFileError("mesh file " + quote(path) + " is empty");
  return text;
}

Vec3 rotated(Vec3 p, const double sines[3], const double cosines[3]) {
  // About x, then y, then z (right-handed, degrees counter-clockwise looking down the axis).
  p = {p.x, cosines[0] * p.y - sines[0] * p.z, sines[0] * p.y + cosines[0] * p.z};
  p = {cosines[1] * p.x + sines[1] * p.z, p.y, cosines[1] * p.z - sines[1] * p.x};
  p = {cosines[2] * p.x - sines[2] * p.y, sines[2] * p.x + cosines[2] * p.y, p.z};
  return p;
}

void warnIf(std::vector<std::string>& warnings, size_t count, const std::string& what,
            const std::string& where) {
  if (count > 0) {
    warnings.push_back(where + ": skipped " + std::to_string(count) + " triangle" +
                       (count == 1 ? "" : "s") + " " + what);
  }
}

// Corners with the same position and normal, bit for bit, become one vertex: OBJ and PLY
// readers hand over a vertex per corner of each face. By bits, not by value, so that a NaN
// corner stays itself (and its triangles are skipped as not finite, not as degenerate).
class VertexJoiner {
 public:
  uint32_t add(const aiVector3D& p, const aiVector3D* n) {
    Key key{};
    std::memcpy(key.data(), &p, sizeof p);
    if (n != nullptr) std::memcpy(key.data() + 3, n, sizeof *n);
    const auto [at, added] = index_.try_emplace(key, static_cast<uint32_t>(vertices.size()));
    if (added) {
      vertices.push_back({p.x, p.y, p.z});
      normals.push_back(n != nullptr ? Vec3(n->x, n->y, n->z) : Vec3());
    }
    return at->second;
  }
  std::vector<Vec3> vertices, normals;

 private:
  static_assert(sizeof(aiVector3D) == 3 * sizeof(uint32_t), "assimp built with float coordinates");
  using Key = std::array<uint32_t, 6>;
  struct Hash {
    size_t operator()(const Key& k) const {
      uint64_t h = 0x9e3779b97f4a7c15ULL;
      for (const uint32_t word : k) h = (h ^ word) * 0x100000001b3ULL;
      return static_cast<size_t>(h ^ (h >> 29));
    }
  };
  std::unordered_map<Key, uint32_t, Hash> index_;
};

}  // namespace

LoadedMesh placeMesh(std::vector<Vec3> vertices, std::vector<std::array<uint32_t, 3>> triangles,
                     std::vector<Vec3> normals, const MeshSource& source) {
  const std::string where =
      source.file.empty() ? std::string("triangles") : "mesh file " + quote(source.file);
  LoadedMesh out;
  auto mesh = std::make_shared<TriangleMesh>();
  double sines[3], cosines[3];
  constexpr double kRadiansPerDegree = 3.14159265358979323846 / 180.0;
  for (int axis = 0; axis < 3; ++axis) {
    sinCosRadians(source.rotateDegrees[axis] * kRadiansPerDegree, sines[axis], cosines[axis]);
  }
  const Vec3& s = source.scale;
  // A mirroring scale turns the winding inside out: the triangles are turned back.
  const bool mirrored = ((s.x < 0) != (s.y < 0)) != (s.z < 0);
  // Steps that change nothing are left out: they could still turn a -0 into a +0.
  const bool scaled = s != Vec3(1, 1, 1);
  const bool rotating = source.rotateDegrees != Vec3();
  const bool moved = source.translate != Vec3();
  for (Vec3& v : vertices) {
    if (scaled) v = v * s;
    if (rotating) v = rotated(v, sines, cosines);
    if (moved) v = v + source.translate;
  }
  if (normals.size() != vertices.size()) normals.clear();
  for (Vec3& n : normals) {
    const Vec3 m = scaled ? Vec3(n.x / s.x, n.y / s.y, n.z / s.z) : n;
    const Vec3 turned = rotating ? rotated(m, sines, cosines) : m;
    const double size = length(turned);
    n = isFinite(turned) && size > 0 ? turned / size : Vec3();
  }

  size_t outOfRange = 0, notFinite = 0, zeroArea = 0;
  mesh->triangles.reserve(triangles.size());
  for (auto t : triangles) {
    if (t[0] >= vertices.size() || t[1] >= vertices.size() || t[2] >= vertices.size()) {
      ++outOfRange;
      continue;
    }
    const Vec3 &a = vertices[t[0]], &b = vertices[t[1]], &c = vertices[t[2]];
    if (!isFinite(a) || !isFinite(b) || !isFinite(c)) {
      ++notFinite;
      continue;
    }
    const double area = length(cross(b - a, c - a));
    if (!(area > 0) || !std::isfinite(area)) {
      ++zeroArea;
      continue;
    }
    if (mirrored) std::swap(t[1], t[2]);
    mesh->triangles.push_back(t);
  }
  warnIf(out.warnings, outOfRange, "with a vertex index out of range", where);
  warnIf(out.warnings, notFinite, "with a vertex that is not finite", where);
  warnIf(out.warnings, zeroArea, "of zero area", where);
  if (mesh->triangles.empty()) {
    throw MeshFileError(where + " has no triangle that can be traced (of " +
                        std::to_string(triangles.size()) + ")");
  }
  if (normals.empty() && source.smooth) {
    // Each face's normal weighted by its area (the cross product's length) at its corners.
    normals.assign(vertices.size(), Vec3());
    for (const auto& t : mesh->triangles) {
      const Vec3 face = cross(vertices[t[1]] - vertices[t[0]], vertices[t[2]] - vertices[t[0]]);
      for (const uint32_t v : t) normals[v] += face;
    }
    for (Vec3& n : normals) {
      const double size = length(n);
      n = size > 0 && std::isfinite(size) ? n / size : Vec3();
    }
  }
  // Only the vertices of the triangles kept (a skipped one's may not be finite).
  std::vector<uint32_t> renumbered(vertices.size(), ~0u);
  for (auto& t : mesh->triangles) {
    for (uint32_t& v : t) {
      if (renumbered[v] == ~0u) {
        renumbered[v] = static_cast<uint32_t>(mesh->vertices.size());
        mesh->vertices.push_back(vertices[v]);
        if (!normals.empty()) mesh->normals.push_back(normals[v]);
      }
      v = renumbered[v];
    }
  }
  out.mesh = std::move(mesh);
  return out;
}

LoadedMesh loadMeshFile(const MeshSource& source) {
  return loadMeshFileContained(source);
}

LoadedMesh loadMeshFileHere(const MeshSource& source) {
  const std::string& path = source.file;
  {
    const std::string text = readFile(path);
    checkMeshText(text, path);
  }
  Assimp::Importer importer;
  // Every face made triangles; no normals invented. The node tree's transforms are applied
  // here (placed_meshes.h), not by assimp's PreTransformVertices step, which crashes on some
  // files' cameras and lights. No SortByPType step either: it refuses a file with an empty
  // mesh (an STL file's empty solid), and points and lines are skipped below anyway.
  const aiScene* scene = importer.ReadFile(path, aiProcess_Triangulate);
  if (scene == nullptr) {
    // assimp catches an allocation that failed and keeps only its name.
    if (std::string(importer.GetErrorString()) == "std::bad_alloc") throw std::bad_alloc();
    throw MeshFileError("mesh file " + quote(path) +
                        " could not be read: " + importer.GetErrorString());
  }
  const std::vector<PlacedMesh> placed = placedMeshes(*scene, path);
  bool allNormals = !placed.empty();
  for (const PlacedMesh& p : placed) allNormals &= p.mesh->HasNormals();
  VertexJoiner joiner;
  std::vector<std::array<uint32_t, 3>> triangles;
  size_t notTriangles = 0, outOfRange = 0;
  for (const PlacedMesh& p : placed) {
    const aiMesh& mesh = *p.mesh;
    for (unsigned f = 0; f < mesh.mNumFaces; ++f) {
      const aiFace& face = mesh.mFaces[f];
      if (face.mNumIndices != 3) {
        ++notTriangles;
        continue;
      }
      std::array<uint32_t, 3> t{};
      bool inRange = true;
      for (int k = 0; k < 3; ++k) {
        const unsigned v = face.mIndices[k];
        if (v >= mesh.mNumVertices) {
          inRange = false;
          break;
        }
        const aiVector3D position = placedVertex(p, v);
        const aiVector3D normal = allNormals ? placedNormal(p, v) : aiVector3D();
        t[k] = joiner.add(position, allNormals ? &normal : nullptr);
      }
      if (!inRange) {
        ++outOfRange;
        continue;
      }
      triangles.push_back(t);
    }
  }
  std::vector<Vec3> vertices = std::move(joiner.vertices), normals = std::move(joiner.normals);
  if (!allNormals) normals.clear();
  LoadedMesh loaded =
      placeMesh(std::move(vertices), std::move(triangles), std::move(normals), source);
  if (outOfRange > 0) {
    loaded.warnings.push_back("mesh file " + quote(path) + ": skipped " +
                              std::to_string(outOfRange) +
                              " triangles with a vertex index out of range");
  }
  if (notTriangles > 0) {
    loaded.warnings.push_back("mesh file " + quote(path) + ": skipped " +
                              std::to_string(notTriangles) + " points and lines (not triangles)");
  }
  return loaded;
}

}  // namespace prt
