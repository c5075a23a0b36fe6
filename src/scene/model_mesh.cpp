#include "scene/model_mesh.h"

#include <cmath>
#include <utility>

namespace prt {
namespace {

void line(std::vector<std::string>& warnings, const std::string& file, size_t count,
          const std::string& what) {
  if (count == 0) return;
  warnings.push_back("model file \"" + file + "\": skipped " + std::to_string(count) + " " + what);
}

}  // namespace

void MeshSkips::warn(std::vector<std::string>& warnings, const std::string& file) const {
  line(warnings, file, outOfRange,
       std::string("triangle") + (outOfRange == 1 ? "" : "s") + " with a vertex index out of range");
  line(warnings, file, notFinite,
       std::string("triangle") + (notFinite == 1 ? "" : "s") + " with a vertex that is not finite");
  line(warnings, file, zeroArea, std::string("triangle") + (zeroArea == 1 ? "" : "s") + " of zero area");
  line(warnings, file, notTriangles, "points and lines (not triangles)");
}

std::shared_ptr<TriangleMesh> cleanMesh(RawMesh raw, MeshSkips& skips) {
  const size_t n = raw.positions.size();
  if (raw.normals.size() != n) raw.normals.clear();
  if (raw.uvs.size() != n) raw.uvs.clear();
  if (raw.tangents.size() != n || raw.uvs.empty()) raw.tangents.clear();
  if (raw.colors.size() != n) raw.colors.clear();
  auto mesh = std::make_shared<TriangleMesh>();
  mesh->triangles.reserve(raw.triangles.size());
  for (const auto& t : raw.triangles) {
    if (t[0] >= n || t[1] >= n || t[2] >= n) {
      ++skips.outOfRange;
      continue;
    }
    const Vec3 &a = raw.positions[t[0]], &b = raw.positions[t[1]], &c = raw.positions[t[2]];
    if (!isFinite(a) || !isFinite(b) || !isFinite(c)) {
      ++skips.notFinite;
      continue;
    }
    const double area = length(cross(b - a, c - a));
    if (!(area > 0) || !std::isfinite(area)) {
      ++skips.zeroArea;
      continue;
    }
    mesh->triangles.push_back(t);
  }
  if (mesh->triangles.empty()) return nullptr;
  std::vector<uint32_t> renumbered(n, ~0u);
  for (auto& t : mesh->triangles) {
    for (uint32_t& v : t) {
      if (renumbered[v] == ~0u) {
        renumbered[v] = static_cast<uint32_t>(mesh->vertices.size());
        mesh->vertices.push_back(raw.positions[v]);
        if (!raw.normals.empty()) {
          const Vec3& normal = raw.normals[v];
          const double size = length(normal);
          mesh->normals.push_back(isFinite(normal) && size > 0 ? normal / size : Vec3());
        }
        if (!raw.uvs.empty()) {
          auto uv = raw.uvs[v];
          for (float& x : uv) x = std::isfinite(x) ? x : 0.0f;
          mesh->uvs.push_back(uv);
        }
        if (!raw.tangents.empty()) {
          const auto& given = raw.tangents[v];
          const Vec3 xyz{given[0], given[1], given[2]};
          const double size = length(xyz);
          const Vec3 unit = isFinite(xyz) && size > 0 ? xyz / size : Vec3();
          mesh->tangents.push_back({unit.x, unit.y, unit.z, given[3] < 0 ? -1.0 : 1.0});
        }
        if (!raw.colors.empty()) {
          auto color = raw.colors[v];
          for (float& x : color) x = std::isfinite(x) && x > 0 ? x : (std::isfinite(x) ? 0.0f : 1.0f);
          mesh->colors.push_back(color);
        }
      }
      v = renumbered[v];
    }
  }
  return mesh;
}

}  // namespace prt
