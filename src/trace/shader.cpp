#include "trace/shader.h"

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdint>
#include <limits>
#include <numbers>

#include "core/portable_math.h"
#include "trace/light_sampling.h"
#include "trace/sampling.h"

namespace prt {
namespace {

constexpr double kDegrees = std::numbers::pi / 180.0;

// e with 2^e <= x < 2^(e + 1), for finite x > 0 (a subnormal reports -1023, which is lower:
// safe below).
int binaryExponent(double x) {
  return static_cast<int>((std::bit_cast<uint64_t>(x) >> 52) & 0x7ff) - 1023;
}

// What a metal's reflections are multiplied by: its colour, by its metallic share.
Color metallicTint(const Material& m, const Color& albedo) {
  return Color(1 - m.metallic) + m.metallic * albedo;
}

}  // namespace

bool specularIsNegligible(double highlight, double exponent, double specular,
                          const Color& diffuse) {
  // log2 of h^n is at most n (h - 1) / ln 2 (as ln h <= h - 1, for n > 0), log2(specular) is
  // below e_s + 1, and a quarter of the last place of d is 2^(e_d - 54); one more factor of
  // two covers the rounding of powNonNegative and of this estimate.
  const double least = std::min({diffuse.x, diffuse.y, diffuse.z});
  if (!(least > 0 && exponent > 0 && highlight < 1)) return false;
  return exponent * (1 - highlight) * 1.4426 >
         binaryExponent(specular) + 56 - binaryExponent(least);
}

bool refract(const Vec3& d, const Vec3& n, double eta, Vec3& transmitted) {
  const double cosI = -dot(d, n);
  const double sin2T = eta * eta * (1.0 - cosI * cosI);
  if (sin2T > 1.0) return false;
  const double cosT = std::sqrt(1.0 - sin2T);
  transmitted = normalize(eta * d + (eta * cosI - cosT) * n);
  return true;
}

bool surelyBehind(const LightReach& reach, const Vec3& origin, const Vec3& n, double nn) {
  // With c the centre, R the radius and d = dot(n, c - origin) as computed: a point t aimed at
  // is within R (1 + 1e-14) of c, plus the rounding of c + offset (below 1e-15 (|c| + R) in
  // each coordinate), so dot(n, t - origin) <= d + |n| (R + ...) + 1e-15 |c - origin|_1.
  // Asking d < -(R (1 + 1e-6) max(1, n.n) + 1e-9 (|c - origin|_1 + |c|_1)) leaves the exact
  // cosine below -1e-10 (|t - origin| is at most 2.8 |c - origin|_1 there, |c - origin|_1
  // being at least about R), far beyond the 1e-14 or so that rounding the direction and the
  // cosine can move it: the computed cosine is negative too.
  const Vec3 v = reach.center - origin;
  const double d = dot(n, v);
  const double spread = std::abs(v.x) + std::abs(v.y) + std::abs(v.z);
  const double margin =
      reach.radius * (1 + 1e-6) * std::max(1.0, nn) + 1e-9 * (spread + reach.magnitude);
  return d < -margin;
}

Shader::Shader(const World& world, const RenderSettings& settings)
    : world_(world), settings_(settings) {
  auto spread = [](double degrees) {
    const double radians = degrees * kDegrees;
    return Spread{radians, cosRadians(radians)};
  };
  const Scene& scene = world.scene();
  auto texture = [&](const TextureRef& ref) -> const Texture* {
    return ref.texture >= 0 ? &scene.textures[static_cast<size_t>(ref.texture)] : nullptr;
  };
  for (const Object& o : scene.objects) {
    Surface surface{spread(o.material.glossDegrees), spread(o.material.translucencyDegrees),
                    1.0 / o.material.ior};
    surface.colorTexture = texture(o.material.colorTexture);
    surface.emissionTexture = texture(o.material.emissionTexture);
    const TriangleMesh* mesh = nullptr;
    if (const auto* m = std::get_if<MeshShape>(&o.shape)) mesh = m->mesh.get();
    if (const auto* i = std::get_if<InstanceShape>(&o.shape)) mesh = i->mesh.get();
    surface.vertexColors = mesh != nullptr && !mesh->colors.empty();
    const bool textured = surface.colorTexture != nullptr || surface.emissionTexture != nullptr;
    surface.attributes = surface.vertexColors || (textured && mesh != nullptr && !mesh->uvs.empty());
    surface.emits = o.material.emission != Color();
    surfaces_.push_back(surface);
  }
  for (const Light& light : scene.lights) {
    reaches_.push_back(reachOf(light.shape));
    LightTerms terms;
    terms.inverseSquare = light.falloff == Falloff::inverseSquare;
    if (const auto* sun = std::get_if<DirectionalLight>(&light.shape)) {
      terms.directional = true;
      terms.sunward = -sun->direction;
    } else if (const auto* spot = std::get_if<SpotLight>(&light.shape)) {
      terms.spot = true;
      terms.axis = spot->direction;
      terms.cosOuter = cosRadians(spot->outerDegrees * kDegrees);
      terms.cosInner = cosRadians(spot->innerDegrees * kDegrees);
    }
    lightTerms_.push_back(terms);
  }
}

double Shader::LightTerms::scale(const Vec3& toLight, double distance) const {
  double s = 1;
  if (spot) {
    const double along = -dot(axis, toLight);  // cosine of the angle off the cone's axis
    if (!(along > cosOuter)) return 0;
    if (along < cosInner) {
      const double t = (along - cosOuter) / (cosInner - cosOuter);
      s = t * t * (3 - 2 * t);  // smooth step
    }
  }
  if (inverseSquare) s /= distance * distance;
  return s;
}

Color Shader::albedoAt(const Ray& ray, const Hit& hit, const Surface& surface, const Material& m,
                       Color* emission) const {
  if (!surface.attributes) {
    if (surface.emits && emission != nullptr) *emission = m.emission;
    return m.color;
  }
  const SurfaceAttributes a = world_.attributesAt(ray, hit);
  auto lookup = [&](const Texture& texture, const TextureRef& ref) {
    const auto& t = ref.uv.m;
    return sampleTexture(texture, t[0] * a.u + t[1] * a.v + t[2], t[3] * a.u + t[4] * a.v + t[5]);
  };
  Color albedo = m.color;
  if (surface.vertexColors) albedo = albedo * a.color;
  if (surface.colorTexture != nullptr) albedo = albedo * lookup(*surface.colorTexture, m.colorTexture);
  if (surface.emits && emission != nullptr) {
    *emission = m.emission;
    if (surface.emissionTexture != nullptr) {
      *emission = *emission * lookup(*surface.emissionTexture, m.emissionTexture);
    }
  }
  return albedo;
}

Color Shader::direct(const Hit& hit, const Vec3& n, const Vec3& toEye, Rng& rng,
                     uint64_t& rays) const {
  return direct(hit, world_.material(hit.object).color, n, toEye, surfaceEpsilon(hit.point), rng,
                rays);
}

Color Shader::direct(const Hit& hit, const Color& albedo, const Vec3& n, const Vec3& toEye,
                     double eps, Rng& rng, uint64_t& rays) const {
  const Scene& scene = world_.scene();
  const Material& m = world_.material(hit.object);
  Color result = m.ambient * scene.environment.ambient * albedo;
  const Vec3 origin = hit.point + eps * n;
  const double nn = dot(n, n);
  const World::ShadowOrigin from = world_.shadowOrigin(origin);

  // Plain pointers: the shadow ray's call would make the vectors' be loaded again each time.
  const Light* const lights = scene.lights.data();
  const LightReach* const reaches = reaches_.data();
  const LightTerms* const terms = lightTerms_.data();
  const size_t lightCount = scene.lights.size();
  const Color tint = metallicTint(m, albedo);
  // The diffuse and Phong terms of light arriving from unit direction toLight.
  auto local = [&](const Vec3& toLight, double cosine) {
    const Color diffuse = (m.diffuse * cosine) * albedo;
    // +0^n is +0 for n > 0 (scene files require n >= 1): the power is skipped then, and when
    // the term could not change the sum anyway; a surface with no specular term skips the
    // highlight too.
    bool needed = false;
    double highlight = 0;
    if (m.specular > 0) {
      highlight = std::max(0.0, dot(reflect(-toLight, n), toEye));
      const bool lit = highlight > 0 || !(m.phongExponent > 0);
      needed = lit && !specularIsNegligible(highlight, m.phongExponent, m.specular, diffuse);
    }
    const double phong = needed ? m.specular * powNonNegative(highlight, m.phongExponent) : 0.0;
    if (m.metallic > 0) return diffuse + phong * tint;
    return diffuse + Color(phong);
  };
  for (size_t l = 0; l < lightCount; ++l) {
    const Light& light = lights[l];
    const LightTerms& shape = terms[l];
    if (shape.directional) {  // one shadow ray, to infinity
      const double cosine = dot(n, shape.sunward);
      if (cosine <= 0) continue;
      ++rays;
      const double visible = world_.transmittanceToLight(
          from, l, Ray{origin, shape.sunward}, std::numeric_limits<double>::infinity());
      if (visible <= 0) continue;
      result += visible * light.color * local(shape.sunward, cosine);
      continue;
    }
    const int samples = isPointLike(light.shape) ? 1 : settings_.drtRate;
    // A light wholly behind the surface: every sample would be skipped below for its cosine.
    // Only the random numbers they would draw are taken.
    if (surelyBehind(reaches[l], origin, n, nn)) {
      rng.skip(aimDraws(light.shape) * static_cast<uint64_t>(samples));
      continue;
    }
    Color sum;
    for (int s = 0; s < samples; ++s) {
      Vec3 toLight = aimAt(light.shape, hit.point, s, samples, rng) - origin;
      const double distance = length(toLight);
      if (distance <= 0) continue;
      toLight /= distance;
      const double cosine = dot(n, toLight);
      if (cosine <= 0) continue;
      // A spot's cone and the fall with distance (1 for the paper's lights, left out).
      const double scale = shape.shaped() ? shape.scale(toLight, distance) : 1.0;
      if (!(scale > 0)) continue;
      ++rays;
      double visible = world_.transmittanceToLight(from, l, Ray{origin, toLight}, distance);
      if (visible <= 0) continue;
      if (shape.shaped()) visible *= scale;
      sum += visible * light.color * local(toLight, cosine);
    }
    result += meanOf(sum, samples);
  }
  return result;
}

Color Shader::spawn(uint32_t inside, const Vec3& origin, const Vec3& direction,
                    const Spread& spread, const Vec3& normal, bool above, PathState path,
                    Rng rng, uint64_t& rays) const {
  const int n = settings_.drtRate;
  const double branchWeight = path.weight / n;
  // One ray when the surface spreads none, or when each of n rays would weigh too little to
  // be traced: then one ray of the cone carries the whole weight.
  if (spread.radians <= 0 || branchWeight < kMinPathWeight) {
    Rng branch = rng.child(0);
    Vec3 d = direction;
    if (spread.radians > 0) {
      d = sampleCone(direction, spread.cosine, branch.uniform(), branch.uniform());
      if ((dot(d, normal) > 0) != above) d = direction;
    }
    return traceFrom(inside, Ray{origin, d}, path, branch, rays);
  }
  Color sum;
  for (int i = 0; i < n; ++i) {
    Rng branch = rng.child(static_cast<uint64_t>(i));
    const double u1 = stratum(i, n, branch.uniform());  // stratified in the cone's polar angle
    Vec3 d = sampleCone(direction, spread.cosine, u1, branch.uniform());
    // A perturbed ray must stay on the side of the surface it was meant for.
    if ((dot(d, normal) > 0) != above) d = direction;
    sum += traceFrom(inside, Ray{origin, d}, {path.depth, branchWeight}, branch, rays);
  }
  return meanOf(sum, n);
}

// One ray: counted, met by `intersect` (the way the ray's origin allows), shaded.
template <typename Intersect>
Color Shader::traceWith(Intersect&& intersect, const Ray& ray, PathState path, Rng rng,
                        uint64_t& rays) const {
  ++rays;
  Hit hit;
  if (!intersect(hit)) return world_.environment().radiance(ray.direction);
  return shade(ray, hit, path, rng, rays);
}

Color Shader::trace(const Ray& ray, int depth, Rng rng, uint64_t& rays) const {
  return traceAt(ray, {depth, 1.0}, rng, rays);
}

Color Shader::traceAt(const Ray& ray, PathState path, Rng rng, uint64_t& rays) const {
  return traceWith(
      [&](Hit& hit) {
        return world_.intersect(ray, 0.0, std::numeric_limits<double>::infinity(), hit);
      },
      ray, path, rng, rays);
}

Color Shader::traceFrom(uint32_t inside, const Ray& ray, PathState path, Rng rng,
                        uint64_t& rays) const {
  if (inside == kOutside) return traceAt(ray, path, rng, rays);
  return traceWith([&](Hit& hit) { return world_.intersectFromInside(inside, ray, hit); }, ray,
                   path, rng, rays);
}

Color Shader::traceAmong(std::span<const uint32_t> candidates, const Ray& ray, Rng rng,
                         uint64_t& rays) const {
  return traceWith(
      [&](Hit& hit) {
        return world_.intersectAmong(candidates, ray, 0.0, std::numeric_limits<double>::infinity(),
                                     hit);
      },
      ray, PathState{}, rng, rays);
}

Color Shader::shade(const Ray& ray, const Hit& hit, PathState path, Rng rng,
                    uint64_t& rays) const {
  const Scene& scene = world_.scene();
  const Material& m = world_.material(hit.object);
  const bool entering = dot(ray.direction, hit.normal) < 0;
  const Vec3 n = entering ? hit.normal : -hit.normal;  // faces the incoming ray
  const Vec3 toEye = -ray.direction;

  const double eps = surfaceEpsilon(hit.point);
  const Surface& surface = surfaces_[hit.object];
  Color emission;
  const Color albedo = albedoAt(ray, hit, surface, m, &emission);
  Color color = direct(hit, albedo, n, toEye, eps, rng, rays);
  if (surface.emits) color += emission;
  if (path.depth >= scene.environment.maxDepth) return color;
  // Rays spawned back to the side the ray came from, and through to the other side: one of the
  // two is inside the object (a convex one: a sphere or a box; World knows which it is).
  const uint32_t sameSide = entering ? kOutside : hit.object;
  const uint32_t otherSide = entering ? hit.object : kOutside;

  // A spawned ray too light to change the pixel is not traced (see kMinPathWeight).
  const PathState reflected{path.depth + 1, path.weight * m.reflectivity};
  if (m.reflectivity > 0 && reflected.weight >= kMinPathWeight) {
    const Vec3 r = reflect(ray.direction, n);
    const Color weight =
        m.metallic > 0 ? m.reflectivity * metallicTint(m, albedo) : Color(m.reflectivity);
    color += weight * spawn(sameSide, hit.point + eps * n, r, surface.reflection, n, true,
                                    reflected, rng.child(1000), rays);
  }
  const PathState transmitted{path.depth + 1, path.weight * m.transmissivity};
  if (m.transmissivity > 0 && transmitted.weight >= kMinPathWeight) {
    const double eta = entering ? surface.inverseIor : m.ior;
    Vec3 t;
    if (refract(ray.direction, n, eta, t)) {
      color += m.transmissivity * spawn(otherSide, hit.point - eps * n, t, surface.transmission, n,
                                        false, transmitted, rng.child(2000), rays);
    } else {  // total internal reflection: the transmitted light is reflected back inside
      color += m.transmissivity * spawn(sameSide, hit.point + eps * n, reflect(ray.direction, n),
                                        surface.transmission, n, true, transmitted,
                                        rng.child(2000), rays);
    }
  }
  return color;
}

}  // namespace prt
