#include "trace/tangents.h"

#include <cmath>

#include "core/portable_math.h"

namespace prt {
namespace {

// `v` with its part along the unit `n` taken out, made unit; zero when nothing is left.
Vec3 inPlane(const Vec3& v, const Vec3& n) {
  const Vec3 p = v - dot(n, v) * n;
  const double size = length(p);
  return size > 1e-300 && std::isfinite(size) ? p / size : Vec3();
}

// The angle between two unit vectors (0 when either is zero).
double angleBetween(const Vec3& a, const Vec3& b) { return atan2Of(length(cross(a, b)), dot(a, b)); }

}  // namespace

std::vector<std::array<double, 4>> computeTangents(const TriangleMesh& mesh) {
  const size_t n = mesh.vertices.size();
  if (mesh.uvs.size() != n || n == 0) return {};
  // The normal at each vertex: the mesh's, or its triangles' (angle-weighted).
  std::vector<Vec3> normals(n);
  if (mesh.normals.size() == n) normals = mesh.normals;
  for (const auto& t : mesh.triangles) {
    const Vec3 &a = mesh.vertices[t[0]], &b = mesh.vertices[t[1]], &c = mesh.vertices[t[2]];
    const Vec3 face = normalize(cross(b - a, c - a));
    const Vec3 corners[3] = {a, b, c};
    for (int k = 0; k < 3; ++k) {
      if (mesh.normals.size() == n && mesh.normals[t[k]] != Vec3()) continue;
      const Vec3 p = corners[k];
      const double angle = angleBetween(normalize(corners[(k + 1) % 3] - p),
                                        normalize(corners[(k + 2) % 3] - p));
      normals[t[k]] += angle * face;
    }
  }
  for (size_t i = 0; i < n; ++i) {
    if (mesh.normals.size() == n && mesh.normals[i] != Vec3()) continue;
    const double size = length(normals[i]);
    normals[i] = size > 0 && std::isfinite(size) ? normals[i] / size : Vec3();
  }
  std::vector<Vec3> alongU(n), upV(n);
  for (const auto& t : mesh.triangles) {
    const Vec3 p[3] = {mesh.vertices[t[0]], mesh.vertices[t[1]], mesh.vertices[t[2]]};
    // s = u, r = -v: r grows up the image.
    double s[3], r[3];
    for (int k = 0; k < 3; ++k) {
      s[k] = mesh.uvs[t[k]][0];
      r[k] = -static_cast<double>(mesh.uvs[t[k]][1]);
    }
    const Vec3 e1 = p[1] - p[0], e2 = p[2] - p[0];
    const double ds1 = s[1] - s[0], dr1 = r[1] - r[0], ds2 = s[2] - s[0], dr2 = r[2] - r[0];
    const double det = ds1 * dr2 - ds2 * dr1;
    if (!(det != 0) || !std::isfinite(det)) continue;  // no UV area: no direction
    const Vec3 dPds = (dr2 * e1 - dr1 * e2) / det;
    const Vec3 dPdr = (ds1 * e2 - ds2 * e1) / det;
    if (!isFinite(dPds) || !isFinite(dPdr)) continue;
    for (int k = 0; k < 3; ++k) {
      const Vec3& normal = normals[t[k]];
      const Vec3 tangent = inPlane(dPds, normal), bitangent = inPlane(dPdr, normal);
      const double angle = angleBetween(inPlane(p[(k + 1) % 3] - p[k], normal),
                                        inPlane(p[(k + 2) % 3] - p[k], normal));
      alongU[t[k]] += angle * tangent;
      upV[t[k]] += angle * bitangent;
    }
  }
  std::vector<std::array<double, 4>> out(n, std::array<double, 4>{0, 0, 0, 1});
  for (size_t i = 0; i < n; ++i) {
    const Vec3 tangent = inPlane(alongU[i], normals[i]);
    if (tangent == Vec3()) continue;
    const double w = dot(cross(normals[i], tangent), upV[i]) < 0 ? -1.0 : 1.0;
    out[i] = {tangent.x, tangent.y, tangent.z, w};
  }
  return out;
}

}  // namespace prt
