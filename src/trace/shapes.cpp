#include "trace/shapes.h"

#include <variant>

#include "core/overloaded.h"
#include "trace/triangle.h"

namespace prt {
namespace {

void add(Crossings& c, double t, const Vec3& n) {
  c.t[c.count] = t;
  c.normal[c.count] = n;
  ++c.count;
}

Vec3 faceNormal(int axis, double sign) {
  Vec3 n;
  n[axis] = sign;
  return n;
}

}  // namespace

Crossings intersect(const SphereShape& s, const Ray& ray, double tMin, double tMax) {
  Crossings c;
  const SphereRoots r = sphereRoots(s.center, s.radius, ray);
  if (!r.hit) return c;
  const double inv = 1.0 / s.radius;
  for (double t : {r.t0, r.t1}) {
    if (t > tMin && t < tMax) add(c, t, (ray.at(t) - s.center) * inv);
  }
  return c;
}

Crossings intersect(const BoxShape& b, const Ray& ray, double tMin, double tMax) {
  Crossings c;
  const BoxSlabs s = boxSlabs(b.min, b.max, ray);
  if (!s.hit) return c;
  if (s.nearCrosses(tMin, tMax)) add(c, s.tNear, faceNormal(s.nearAxis, s.nearSign));
  if (s.farCrosses(tMin, tMax)) add(c, s.tFar, faceNormal(s.farAxis, s.farSign));
  return c;
}

Crossings intersect(const PlaneShape& p, const Ray& ray, double tMin, double tMax) {
  Crossings c;
  const double t = planeDistance(p.point, p.normal, ray);
  if (t > tMin && t < tMax) add(c, t, p.normal);  // false for NaN
  return c;
}

Crossings intersect(const MeshShape& m, const Ray& ray, double tMin, double tMax) {
  const ShearedRay sheared(ray);
  const TriangleMesh& mesh = *m.mesh;
  double t[2] = {tMax, tMax};
  uint32_t which[2] = {0, 0};
  int count = 0;
  for (uint32_t i = 0; i < mesh.triangles.size(); ++i) {
    const auto& v = mesh.triangles[i];
    const TriangleHit h =
        triangleHit(sheared, mesh.vertices[v[0]], mesh.vertices[v[1]], mesh.vertices[v[2]]);
    if (!h.hit || !(h.t > tMin && h.t < tMax)) continue;
    if (count < 2) ++count;
    if (h.t < t[0]) {
      t[1] = t[0];
      which[1] = which[0];
      t[0] = h.t;
      which[0] = i;
    } else if (h.t < t[1] && count == 2) {
      t[1] = h.t;
      which[1] = i;
    }
  }
  Crossings c;
  for (int k = 0; k < count; ++k) {
    const auto& v = mesh.triangles[which[k]];
    const Vec3& a = mesh.vertices[v[0]];
    add(c, t[k], normalize(cross(mesh.vertices[v[1]] - a, mesh.vertices[v[2]] - a)));
  }
  return c;
}

Crossings intersect(const InstanceShape& instance, const Ray& ray, double tMin, double tMax) {
  const Transform meshFromWorld = instance.worldFromMesh.inverse();
  const Ray local{meshFromWorld.point(ray.origin), meshFromWorld.vector(ray.direction)};
  Crossings c = intersect(MeshShape{instance.mesh, {}}, local, tMin, tMax);
  for (int k = 0; k < c.count; ++k) {
    c.normal[k] = normalize(Transform::normal(meshFromWorld, c.normal[k]));
  }
  return c;
}

Bounds meshBounds(const TriangleMesh& mesh) {
  Bounds b;
  for (const auto& t : mesh.triangles) {
    for (const uint32_t v : t) b.extend(mesh.vertices[v]);
  }
  return b;
}

Bounds placedBounds(const Bounds& box, const Transform& transform) {
  Bounds b;
  for (int corner = 0; corner < 8; ++corner) b.extend(transform.point(box.corner(corner)));
  return b;
}

Bounds boundsOf(const Shape& shape) {
  Bounds b;
  std::visit(Overloaded{
                 [&](const SphereShape& s) {
                   b.extend(s.center - Vec3(s.radius));
                   b.extend(s.center + Vec3(s.radius));
                 },
                 [&](const BoxShape& x) {
                   b.extend(x.min);
                   b.extend(x.max);
                 },
                 [&](const MeshShape& m) {
                   for (const auto& t : m.mesh->triangles) {
                     for (const uint32_t v : t) b.extend(m.mesh->vertices[v]);
                   }
                 },
                 [&](const InstanceShape& i) {
                   b = placedBounds(meshBounds(*i.mesh), i.worldFromMesh);
                 },
                 [](const PlaneShape&) {},  // unbounded: the empty box
             },
             shape);
  return b;
}

bool isBounded(const Shape& shape) { return !std::holds_alternative<PlaneShape>(shape); }

}  // namespace prt
