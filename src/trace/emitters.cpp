#include "trace/emitters.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

#include "core/portable_math.h"
#include "trace/sampling.h"

namespace prt {
namespace {

constexpr double kPi = std::numbers::pi;

const TriangleMesh* meshOf(const Object& o, const Transform** placement) {
  *placement = nullptr;
  if (const auto* m = std::get_if<MeshShape>(&o.shape)) return m->mesh.get();
  if (const auto* i = std::get_if<InstanceShape>(&o.shape)) {
    *placement = &i->worldFromMesh;
    return i->mesh.get();
  }
  return nullptr;
}

}  // namespace

Emitters::Emitters(const World& world) : world_(world) {
  const Scene& scene = world.scene();
  double total = 0;
  firstEntryOfObject_.assign(scene.objects.size(), -1);
  for (uint32_t o = 0; o < scene.objects.size(); ++o) {
    const Object& object = scene.objects[o];
    const double radiance = luminance(object.material.emission);
    if (!(radiance > 0)) continue;
    const Transform* placement = nullptr;
    const TriangleMesh* mesh = meshOf(object, &placement);
    if (mesh == nullptr) continue;  // emissive spheres, boxes, planes: found by paths alone
    firstEntryOfObject_[o] = static_cast<int64_t>(cdf_.size());
    for (uint32_t t = 0; t < mesh->triangles.size(); ++t) {
      const auto& v = mesh->triangles[t];
      Vec3 a = mesh->vertices[v[0]], b = mesh->vertices[v[1]], c = mesh->vertices[v[2]];
      if (placement != nullptr) a = placement->point(a), b = placement->point(b), c = placement->point(c);
      Triangle tri{a, b - a, c - a, {}, 0, o, t};
      const Vec3 n = cross(tri.e1, tri.e2);
      const double twiceArea = length(n);
      tri.area = 0.5 * twiceArea;
      tri.normal = twiceArea > 0 ? n / twiceArea : Vec3(0, 0, 1);
      total += 2 * kPi * radiance * tri.area;
      cdf_.push_back(total);
      triangles_.push_back(tri);
    }
  }
  if (!(total > 0)) cdf_.clear(), triangles_.clear(), firstEntryOfObject_.assign(scene.objects.size(), -1);
}

size_t Emitters::lightCount() const { return world_.scene().lights.size(); }

double Emitters::pick(size_t entry) const {
  const double below = entry == 0 ? 0.0 : cdf_[entry - 1];
  return (cdf_[entry] - below) / cdf_.back();
}

Color Emitters::emissionAt(const Triangle& t, double b1, double b2) const {
  const Scene& scene = world_.scene();
  const Material& m = scene.objects[t.object].material;
  if (m.emissionTexture.texture < 0) return m.emission;
  const Transform* placement = nullptr;
  const TriangleMesh* mesh = meshOf(scene.objects[t.object], &placement);
  if (mesh == nullptr || mesh->uvs.empty()) return m.emission;
  const auto& v = mesh->triangles[t.index];
  const auto &p = mesh->uvs[v[0]], &q = mesh->uvs[v[1]], &r = mesh->uvs[v[2]];
  const double b0 = 1 - b1 - b2;
  const double u = b0 * p[0] + b1 * q[0] + b2 * r[0];
  const double w = b0 * p[1] + b1 * q[1] + b2 * r[1];
  const auto& x = m.emissionTexture.uv.m;
  const Texture& texture = scene.textures[static_cast<size_t>(m.emissionTexture.texture)];
  return m.emission * sampleTexture(texture, x[0] * u + x[1] * w + x[2], x[3] * u + x[4] * w + x[5]);
}

bool Emitters::sampleLight(size_t index, const Vec3& from, double u1, double u2,
                           EmitterSample& out) const {
  const Light& light = world_.scene().lights[index];
  const Color intensity = kPi * light.color;
  out.delta = true;
  out.pdf = 1;
  if (const auto* sun = std::get_if<DirectionalLight>(&light.shape)) {
    out.direction = -sun->direction;
    out.distance = std::numeric_limits<double>::infinity();
    out.radiance = intensity;
    return true;
  }
  // A point, or a point of a sphere light's disc or of a rectangle light (lights no ray
  // meets: each point is a point light of the whole intensity, as in the paper's renderer).
  Vec3 target;
  if (const auto* sphere = std::get_if<SphereLight>(&light.shape)) {
    target = sampleDisc(sphere->center, normalize(sphere->center - from), sphere->radius, u1, u2);
  } else if (const auto* rect = std::get_if<RectLight>(&light.shape)) {
    target = rect->corner + u1 * rect->edge1 + u2 * rect->edge2;
  } else if (const auto* spot = std::get_if<SpotLight>(&light.shape)) {
    target = spot->position;
  } else {
    target = std::get<PointLight>(light.shape).position;
  }
  Vec3 d = target - from;
  const double distance = length(d);
  if (!(distance > 0)) return false;
  d /= distance;
  double scale = 1;
  if (const auto* spot = std::get_if<SpotLight>(&light.shape)) {
    constexpr double kDegrees = kPi / 180;
    const double along = -dot(spot->direction, d);
    const double cosOuter = cosRadians(spot->outerDegrees * kDegrees);
    const double cosInner = cosRadians(spot->innerDegrees * kDegrees);
    if (!(along > cosOuter)) return false;
    if (along < cosInner) {
      const double t = (along - cosOuter) / (cosInner - cosOuter);
      scale = t * t * (3 - 2 * t);  // the smooth step of the paper's renderer
    }
  }
  if (light.falloff == Falloff::inverseSquare) scale /= distance * distance;
  out.direction = d;
  out.distance = distance;
  out.radiance = scale * intensity;
  return true;
}

bool Emitters::sampleTriangle(const Vec3& from, double u0, double u1, double u2,
                              EmitterSample& out) const {
  if (cdf_.empty()) return false;
  size_t entry = static_cast<size_t>(
      std::upper_bound(cdf_.begin(), cdf_.end(), u0 * cdf_.back()) - cdf_.begin());
  entry = std::min(entry, cdf_.size() - 1);
  const double chosen = pick(entry);
  if (!(chosen > 0)) return false;
  const Triangle& t = triangles_[entry];
  double b1 = u1, b2 = u2;
  if (b1 + b2 > 1) b1 = 1 - b1, b2 = 1 - b2;  // the square folded onto the triangle
  const Vec3 p = t.p0 + b1 * t.e1 + b2 * t.e2;
  Vec3 d = p - from;
  const double d2 = dot(d, d);
  const double distance = std::sqrt(d2);
  if (!(distance > 0)) return false;
  d /= distance;
  const double cosLight = std::abs(dot(t.normal, d));
  if (!(cosLight > 0)) return false;
  out.delta = false;
  out.direction = d;
  out.distance = distance;
  out.radiance = emissionAt(t, b1, b2);
  out.pdf = chosen / t.area * d2 / cosLight;
  return true;
}

double Emitters::pdfOfHit(const Vec3& from, const Hit& hit) const {
  if (hit.object >= firstEntryOfObject_.size()) return 0;
  const int64_t first = firstEntryOfObject_[hit.object];
  if (first < 0) return 0;
  const size_t entry = static_cast<size_t>(first) + hit.triangle;
  if (entry >= cdf_.size()) return 0;
  const Triangle& t = triangles_[entry];
  const Vec3 d = hit.point - from;
  const double d2 = dot(d, d);
  const double cosLight = std::abs(dot(t.normal, d)) / std::sqrt(d2);
  if (!(cosLight > 0)) return 0;
  return pick(entry) / t.area * d2 / cosLight;
}

}  // namespace prt
