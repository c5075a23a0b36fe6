#include "trace/path_tracer.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>

#include "core/portable_math.h"
#include "trace/normal_map.h"

namespace prt {
namespace {

// Roughness whose GGX lobe is about as wide as a cone of this half-angle (the inverse of the
// material mapping's gloss of 60 roughness^2 degrees).
double roughnessOfCone(double degrees) { return std::min(1.0, std::sqrt(degrees / 60)); }
// Roughness whose GGX lobe is about as wide as a Phong lobe of exponent n (the inverse of the
// material mapping's n = (2 / roughness^4 - 2) / 4).
double roughnessOfPhong(double n) { return std::min(1.0, std::sqrt(std::sqrt(2 / (4 * n + 2)))); }

const TriangleMesh* meshOf(const Object& o) {
  if (const auto* m = std::get_if<MeshShape>(&o.shape)) return m->mesh.get();
  if (const auto* i = std::get_if<InstanceShape>(&o.shape)) return i->mesh.get();
  return nullptr;
}

Color lookUp(const Scene& scene, const TextureRef& ref, const SurfaceAttributes& a) {
  const auto& t = ref.uv.m;
  return sampleTexture(scene.textures[static_cast<size_t>(ref.texture)],
                       t[0] * a.u + t[1] * a.v + t[2], t[3] * a.u + t[4] * a.v + t[5]);
}

// Maximum surfaces a ray passes through where they are transparent before it counts as lost.
constexpr int kMostPassThroughs = 64;
// Media a path can be inside at once (a liquid in a glass in a glass...).
constexpr int kMostMedia = 8;
// Bounces after which Russian roulette may end a path.
constexpr int kRouletteAfter = 3;

// Beer and Lambert's coefficient per unit length: what falls to `color` over `distance`
// (glTF's KHR_materials_volume: sigma = -ln(c) / d); a channel of colour 0 absorbs all.
Color absorptionOf(const Color& color, double distance) {
  auto sigma = [&](double c) {
    return c > 0 ? -logPositive(std::min(c, 1.0)) / distance : std::numeric_limits<double>::infinity();
  };
  return {sigma(color.x), sigma(color.y), sigma(color.z)};
}

// What of the light is left after `t` through a medium of coefficients `sigma`.
Color transmittance(const Color& sigma, double t) {
  return {expOf(-sigma.x * t), expOf(-sigma.y * t), expOf(-sigma.z * t)};
}

}  // namespace

PbrSurface pbrFromHall(const Material& m) {
  if (m.pbr.given) return m.pbr;
  PbrSurface p;
  p.given = true;
  const bool refracts = m.transmissivity > 0 && m.ior > 1;
  if (m.reflectivity > 0 || refracts) {
    p.roughness = roughnessOfCone(std::max(m.glossDegrees, refracts ? m.translucencyDegrees : 0.0));
  } else if (m.specular > 0) {
    p.roughness = roughnessOfPhong(m.phongExponent);
  } else {
    p.roughness = 1;
  }
  p.transmission = refracts ? m.transmissivity : 0;
  p.coverage = refracts ? 1 : 1 - m.transmissivity;
  p.ior = refracts ? m.ior : 1.5;
  return p;
}

PathTracer::PathTracer(const World& world)
    : world_(world), emitters_(world), maxBounces_(world.scene().environment.maxBounces) {
  const Scene& scene = world.scene();
  for (const Object& o : scene.objects) {
    const Material& m = o.material;
    const PbrSurface p = pbrFromHall(m);
    Surface s;
    s.bsdf.base = m.color;
    s.bsdf.metallic = m.pbr.given ? m.metallic : std::max(m.metallic, m.reflectivity);
    s.bsdf.roughness = p.roughness;
    s.bsdf.transmission = p.transmission;
    s.bsdf.ior = p.ior;
    s.bsdf.specularLevel = p.specularLevel;
    s.coverage = p.coverage;
    s.bsdf.thinWalled = p.thinWalled;
    s.bsdf.specularWeight = p.specularWeight;
    s.bsdf.specularColor = p.specularColor;
    s.bsdf.clearcoat = p.clearcoat;
    s.bsdf.clearcoatRoughness = p.clearcoatRoughness;
    s.medium = m.pbr.given && !p.thinWalled && p.transmission > 0;
    if (s.medium && std::isfinite(p.attenuationDistance)) {
      s.absorption = absorptionOf(p.attenuationColor, p.attenuationDistance);
      s.absorbs = maxComponent(s.absorption) > 0;
    }
    const TriangleMesh* mesh = meshOf(o);
    const bool textured = m.colorTexture.texture >= 0 || m.emissionTexture.texture >= 0;
    const bool uvs = mesh != nullptr && !mesh->uvs.empty();
    s.metallicRoughnessMap = uvs && m.pbr.given && m.pbr.metallicRoughnessTexture.texture >= 0;
    s.transmissionMap = uvs && m.pbr.given && m.pbr.transmissionTexture.texture >= 0;
    s.normalMap = uvs && m.pbr.given && m.pbr.normalTexture.texture >= 0 && !mesh->tangents.empty();
    s.attributes = mesh != nullptr && (!mesh->colors.empty() || (textured && uvs) ||
                                       s.metallicRoughnessMap || s.transmissionMap || s.normalMap);
    surfaces_.push_back(s);
    allOpaque_ = allOpaque_ && s.coverage >= 1;
  }
}

double PathTracer::visibility(const Vec3& origin, const Vec3& direction, double distance,
                              uint64_t& rays) const {
  if (allOpaque_) {
    ++rays;
    return world_.occluded(Ray{origin, direction}, 0.0, distance) ? 0.0 : 1.0;
  }
  double through = 1;
  Vec3 from = origin;
  double left = distance;
  for (int pass = 0; pass < kMostPassThroughs; ++pass) {
    ++rays;
    Hit hit;
    if (!world_.intersect(Ray{from, direction}, 0.0, left, hit)) return through;
    const double coverage = surfaces_[hit.object].coverage;
    if (coverage >= 1) return 0;
    through *= 1 - coverage;
    if (!(through > 0)) return 0;
    const double eps = surfaceEpsilon(hit.point);
    from = hit.point + eps * direction;
    left -= hit.t + eps;
    if (!(left > 0)) return through;
  }
  return 0;
}

Color PathTracer::radiance(const Ray& cameraRay, const std::span<const uint32_t>* candidates,
                           Rng rng, uint64_t& rays) const {
  const Scene& scene = world_.scene();
  constexpr double kInfinity = std::numeric_limits<double>::infinity();
  const size_t lightCount = emitters_.lightCount();
  const EnvironmentLight& environment = world_.environment();
  Color sum;
  Color throughput(1);
  Ray ray = cameraRay;
  bool lastDelta = true;  // the camera is a delta: what it sees directly counts in full
  double lastPdf = 0;
  Vec3 lastPoint;
  int bounce = 0, passes = 0;
  // The objects whose insides the path is in, innermost last (those past kMostMedia deep are
  // not counted).
  std::array<uint32_t, kMostMedia> media{};
  int mediaCount = 0;
  for (uint64_t vertex = 0;; ++vertex) {
    ++rays;
    Hit hit;
    const bool found = vertex == 0 && candidates != nullptr
                           ? world_.intersectAmong(*candidates, ray, 0.0, kInfinity, hit)
                           : world_.intersect(ray, 0.0, kInfinity, hit);
    if (!found) {
      double weight = 1;
      if (!lastDelta && environment.sampled()) {
        const double lightPdf = environment.pdf(ray.direction);
        if (lightPdf > 0) weight = lastPdf * lastPdf / (lastPdf * lastPdf + lightPdf * lightPdf);
      }
      sum += weight * (throughput * environment.radiance(ray.direction));
      break;
    }
    Rng draws = rng.child(vertex);
    const Material& m = world_.material(hit.object);
    const Surface& surface = surfaces_[hit.object];
    if (mediaCount > 0 && hit.t > 0) {
      const Surface& medium = surfaces_[media[mediaCount - 1]];
      if (medium.absorbs) {
        throughput = throughput * transmittance(medium.absorption, hit.t);
        if (!(maxComponent(throughput) > 0)) break;
      }
    }
    const double eps = surfaceEpsilon(hit.point);
    if (surface.coverage < 1 && draws.uniform() >= surface.coverage) {
      // The transparent part: on along the same ray, no bounce taken.
      if (++passes > kMostPassThroughs) break;
      ray.origin = hit.point + eps * ray.direction;
      continue;
    }
    Color base = m.color, emission = m.emission;
    BsdfInputs inputs = surface.bsdf;
    Vec3 mapped = hit.normal;  // the outward shading normal, a normal map's where there is one
    if (surface.attributes) {
      const SurfaceAttributes a = world_.attributesAt(ray, hit);
      base = base * a.color;
      if (m.colorTexture.texture >= 0) base = base * lookUp(scene, m.colorTexture, a);
      if (m.emissionTexture.texture >= 0) emission = emission * lookUp(scene, m.emissionTexture, a);
      if (surface.metallicRoughnessMap) {
        const Color c = lookUp(scene, m.pbr.metallicRoughnessTexture, a);
        inputs.metallic = inputs.metallic * c.z;
        inputs.roughness = inputs.roughness * c.y;
      }
      if (surface.transmissionMap) {
        inputs.transmission = inputs.transmission * lookUp(scene, m.pbr.transmissionTexture, a).x;
      }
      if (surface.normalMap) {
        mapped = mappedNormal(hit.normal, a.tangent, a.handedness,
                              normalMapVector(lookUp(scene, m.pbr.normalTexture, a), m.pbr.normalScale));
      }
    }
    if (emission != Color()) {
      double weight = 1;
      if (!lastDelta) {
        const double lightPdf = emitters_.pdfOfHit(lastPoint, hit);
        if (lightPdf > 0) weight = lastPdf * lastPdf / (lastPdf * lastPdf + lightPdf * lightPdf);
      }
      sum += weight * (throughput * emission);
    }
    if (bounce >= maxBounces_) break;

    const bool outside = dot(ray.direction, hit.normal) < 0;
    const Vec3 n = outside ? hit.normal : -hit.normal;  // faces where the ray came from
    // The BSDF's normal: n, or the normal map's on the same side, kept from facing away.
    const bool bumped = mapped != hit.normal;
    const Vec3 shading = bumped ? keepReflectionAbove(n, -ray.direction, outside ? mapped : -mapped) : n;
    inputs.base = base;
    // A clearcoat lies on the surface as it is, not on the base's normal map (glTF: the
    // coat has a normal texture of its own).
    if (bumped && inputs.clearcoat > 0) inputs.clearcoatNormal = n;
    const Bsdf bsdf(inputs, shading, -ray.direction, outside);
    const Vec3 above = hit.point + eps * n, below = hit.point - eps * n;

    // Next-event estimation: a shadow ray to every light and to one emissive triangle.
    if (bsdf.hasSmoothLobe()) {
      auto aim = [&](const EmitterSample& light) {
        // A light beyond the surface on one side and beyond the tilted normal's plane on the
        // other: none of its light comes through (as in Cycles).
        if (bumped && (dot(light.direction, n) > 0) != (dot(light.direction, shading) > 0)) return;
        const Color f = bsdf.evaluate(light.direction);
        if (!(maxComponent(f) > 0)) return;
        const Vec3 from = dot(light.direction, n) > 0 ? above : below;
        const double reach =
            std::isinf(light.distance) ? kInfinity : light.distance * (1 - 1e-9) - eps;
        const double visible = visibility(from, light.direction, reach, rays);
        if (!(visible > 0)) return;
        double weight = 1;
        if (!light.delta) {
          const double bsdfPdf = bsdf.pdf(light.direction);
          weight = light.pdf * light.pdf / (light.pdf * light.pdf + bsdfPdf * bsdfPdf);
        }
        sum += (visible * weight / light.pdf) * (throughput * f * light.radiance);
      };
      EmitterSample light;
      for (size_t l = 0; l < lightCount; ++l) {
        Rng own = draws.child(l);
        const double u1 = own.uniform(), u2 = own.uniform();
        if (emitters_.sampleLight(l, hit.point, u1, u2, light)) aim(light);
      }
      const double t0 = draws.uniform(), t1 = draws.uniform(), t2 = draws.uniform();
      if (emitters_.sampleTriangle(hit.point, t0, t1, t2, light)) aim(light);
      if (environment.sampled()) {
        // A stream of its own, after the lights' (a scene without a map draws as before).
        Rng own = draws.child(lightCount);
        const double e1 = own.uniform(), e2 = own.uniform();
        if (environment.sample(e1, e2, light.direction, light.radiance, light.pdf)) {
          light.distance = kInfinity;
          light.delta = false;
          aim(light);
        }
      }
    } else {
      draws.skip(3);
    }

    // The next bounce.
    const double b0 = draws.uniform(), b1 = draws.uniform(), b2 = draws.uniform();
    BsdfSample next;
    if (!bsdf.sample(b0, b1, b2, next)) break;
    if (bumped && (next.transmitted ? dot(next.wi, n) >= 0 : dot(next.wi, n) <= 0)) {
      break;  // reflected into the surface (or transmitted out of it) by the tilted normal
    }
    throughput = throughput * next.weight;
    if (!(maxComponent(throughput) > 0) || !isFinite(throughput)) break;
    if (surface.medium && dot(next.wi, n) < 0) {  // through the surface: into it or out of it
      if (outside) {
        if (mediaCount < kMostMedia) media[static_cast<size_t>(mediaCount++)] = hit.object;
      } else {
        for (int k = mediaCount; k-- > 0;) {
          if (media[static_cast<size_t>(k)] == hit.object) {
            for (int j = k; j + 1 < mediaCount; ++j) media[static_cast<size_t>(j)] = media[static_cast<size_t>(j) + 1];
            --mediaCount;
            break;
          }
        }
      }
    }
    lastDelta = next.delta;
    lastPdf = next.pdf;
    lastPoint = hit.point;
    ++bounce;
    const double survive = maxComponent(throughput);
    if (bounce > kRouletteAfter && survive < 1) {
      if (draws.uniform() >= survive) break;
      throughput = throughput / survive;
    }
    ray = Ray{dot(next.wi, n) > 0 ? above : below, next.wi};
  }
  return sum;
}

}  // namespace prt
