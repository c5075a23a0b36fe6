#include "trace/shader.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "trace/light_sampling.h"

namespace prt {
namespace {

constexpr double kShaderInf = std::numeric_limits<double>::infinity();

// A floor plane through the origin facing +y with the given material, plus extra objects.
Scene floorScene(const Material& m) {
  Scene scene;
  scene.environment.ambient = Color(0.1, 0.2, 0.3);
  scene.environment.background = Color(0.25, 0.5, 0.75);
  scene.objects.push_back({PlaneShape{{0, 0, 0}, {0, 1, 0}}, m});
  return scene;
}

Hit floorHit() {
  Hit h;
  h.point = Vec3(0, 0, 0);
  h.normal = Vec3(0, 1, 0);
  h.object = 0;
  return h;
}

// Shadow rays start a hair off the surface (see surfaceEpsilon), so directions differ from
// the hand computation in the tenth digit.
void expectColorNear(const Color& a, const Color& b) {
  EXPECT_NEAR(a.x, b.x, 1e-9);
  EXPECT_NEAR(a.y, b.y, 1e-9);
  EXPECT_NEAR(a.z, b.z, 1e-9);
}

TEST(ShaderTest, AmbientTerm) {
  Material m;
  m.color = Color(0.5, 0.4, 0.2);
  m.ambient = 0.8;
  const World world(floorScene(m));
  const Shader shader(world, {});
  Rng rng(1);
  uint64_t rays = 0;
  const Color c = shader.direct(floorHit(), {0, 1, 0}, {0, 1, 0}, rng, rays);
  expectColorNear(c, Color(0.8 * 0.5 * 0.1, 0.8 * 0.4 * 0.2, 0.8 * 0.2 * 0.3));
  EXPECT_EQ(rays, 0u);
}

TEST(ShaderTest, DiffuseTermFollowsLambertCosine) {
  Material m;
  m.color = Color(1, 0.5, 0.25);
  m.ambient = 0;
  m.diffuse = 0.6;
  Scene scene = floorScene(m);
  scene.lights.push_back({PointLight{{10, 10, 0}}, Color(2, 2, 2)});  // 45 degrees
  const World world(scene);
  const Shader shader(world, {});
  Rng rng(1);
  uint64_t rays = 0;
  const Color c = shader.direct(floorHit(), {0, 1, 0}, {0, 1, 0}, rng, rays);
  const double k = 2 * 0.6 * std::sqrt(0.5);
  expectColorNear(c, Color(k * 1, k * 0.5, k * 0.25));
  EXPECT_EQ(rays, 1u);  // one shadow ray
}

TEST(ShaderTest, PhongHighlightTakesTheLightColour) {
  Material m;
  m.color = Color(0, 0, 0);
  m.ambient = 0;
  m.diffuse = 0;
  m.specular = 0.5;
  m.phongExponent = 10;
  Scene scene = floorScene(m);
  scene.lights.push_back({PointLight{{-10, 10, 0}}, Color(1, 0.5, 1)});
  const World world(scene);
  const Shader shader(world, {});
  Rng rng(1);
  uint64_t rays = 0;
  // Eye exactly along the mirror direction: (R.V)^n = 1.
  const Vec3 mirror = normalize(Vec3(1, 1, 0));
  expectColorNear(shader.direct(floorHit(), {0, 1, 0}, mirror, rng, rays), Color(0.5, 0.25, 0.5));
  // Eye straight up: R.V = cos 45 degrees.
  const double k = 0.5 * std::pow(std::sqrt(0.5), 10);
  expectColorNear(shader.direct(floorHit(), {0, 1, 0}, {0, 1, 0}, rng, rays),
                  Color(k, k * 0.5, k));
}

TEST(ShaderTest, OpaqueOccluderCastsShadowTransmissiveOneAttenuates) {
  Material m;
  m.ambient = 0;
  m.diffuse = 1;
  m.color = Color(1, 1, 1);
  Scene scene = floorScene(m);
  scene.lights.push_back({PointLight{{0, 10, 0}}, Color(1, 1, 1)});
  Material occluder;
  occluder.transmissivity = 0.5;
  scene.objects.push_back({SphereShape{{0, 5, 0}, 1}, occluder});
  {
    const World world(scene);
    Rng rng(1);
    uint64_t rays = 0;
    // Two crossings of a surface with k_t = 0.5: a quarter of the light arrives.
    expectColorNear(Shader(world, {}).direct(floorHit(), {0, 1, 0}, {0, 1, 0}, rng, rays),
                    Color(0.25));
  }
  scene.objects.back().material.transmissivity = 0;
  const World world(scene);
  Rng rng(1);
  uint64_t rays = 0;
  expectColorNear(Shader(world, {}).direct(floorHit(), {0, 1, 0}, {0, 1, 0}, rng, rays),
                  Color(0));
}

TEST(ShaderTest, LightBehindSurfaceContributesNothing) {
  Material m;
  m.ambient = 0;
  Scene scene = floorScene(m);
  scene.lights.push_back({PointLight{{0, -10, 0}}, Color(1)});
  const World world(scene);
  Rng rng(1);
  uint64_t rays = 0;
  expectColorNear(Shader(world, {}).direct(floorHit(), {0, 1, 0}, {0, 1, 0}, rng, rays),
                  Color(0));
}

TEST(ShaderTest, MirrorReflectsTheBackgroundScaledByReflectivity) {
  Material mirror;
  mirror.ambient = 0;
  mirror.diffuse = 0;
  mirror.reflectivity = 0.8;
  const World world(floorScene(mirror));
  uint64_t rays = 0;
  const Color c = Shader(world, {}).trace(Ray{{0, 1, 0}, normalize(Vec3(1, -1, 0))}, 0, Rng(3), rays);
  expectColorNear(c, 0.8 * Color(0.25, 0.5, 0.75));
  EXPECT_EQ(rays, 2u);  // the camera ray and its reflection
}

TEST(ShaderTest, RecursionStopsAtMaximumDepth) {
  Material mirror;
  mirror.ambient = 0;
  mirror.diffuse = 0;
  mirror.reflectivity = 1;
  Scene scene = floorScene(mirror);
  scene.environment.maxDepth = 0;
  const World world(scene);
  uint64_t rays = 0;
  expectColorNear(Shader(world, {}).trace(Ray{{0, 1, 0}, {0, -1, 0}}, 0, Rng(3), rays), Color(0));
  EXPECT_EQ(rays, 1u);
}

TEST(ShaderTest, SnellsLaw) {
  // 30 degrees in air into glass (1.5): sin t = sin 30 / 1.5.
  const double theta = std::numbers::pi / 6;
  const Vec3 d(std::sin(theta), -std::cos(theta), 0);
  Vec3 t;
  ASSERT_TRUE(refract(d, {0, 1, 0}, 1 / 1.5, t));
  EXPECT_NEAR(t.x, std::sin(theta) / 1.5, 1e-12);
  EXPECT_LT(t.y, 0);
  EXPECT_NEAR(length(t), 1, 1e-12);
  // Normal incidence goes straight through.
  ASSERT_TRUE(refract({0, -1, 0}, {0, 1, 0}, 1 / 1.5, t));
  EXPECT_NEAR(t.y, -1, 1e-12);
}

TEST(ShaderTest, TotalInternalReflectionBeyondCriticalAngle) {
  // Glass to air: critical angle asin(1/1.5) = 41.8 degrees.
  const auto dir = [](double degrees) {
    const double r = degrees * std::numbers::pi / 180;
    return Vec3(std::sin(r), -std::cos(r), 0);
  };
  Vec3 t;
  EXPECT_TRUE(refract(dir(41), {0, 1, 0}, 1.5, t));
  EXPECT_FALSE(refract(dir(43), {0, 1, 0}, 1.5, t));
}

TEST(ShaderTest, ClearGlassWithUnitIndexIsInvisible) {
  Scene scene;
  scene.environment.background = Color(0.3, 0.6, 0.9);
  Material clear;
  clear.ambient = 0;
  clear.diffuse = 0;
  clear.transmissivity = 1;
  clear.ior = 1;
  scene.objects.push_back({SphereShape{{0, 0, 5}, 1}, clear});
  const World world(scene);
  uint64_t rays = 0;
  const Color c = Shader(world, {}).trace(Ray{{0, 0, 0}, {0, 0, 1}}, 0, Rng(1), rays);
  expectColorNear(c, scene.environment.background);
  EXPECT_EQ(rays, 3u);  // in, through, out
}

TEST(ShaderTest, GlossyReflectionSpawnsDrtRays) {
  Material glossy;
  glossy.ambient = 0;
  glossy.diffuse = 0;
  glossy.reflectivity = 1;
  glossy.glossDegrees = 5;
  const World world(floorScene(glossy));
  uint64_t rays = 0;
  RenderSettings settings;
  settings.drtRate = 4;
  const Color c = Shader(world, settings).trace(Ray{{0, 1, 0}, normalize(Vec3(1, -1, 0))}, 0,
                                                Rng(3), rays);
  EXPECT_EQ(rays, 5u);
  expectColorNear(c, Color(0.25, 0.5, 0.75));  // every perturbed ray sees the background
}

// Two mirrors facing each other across y in [0, 2]: a ray between them never escapes.
Scene mirrorCorridor(double reflectivity, double glossDegrees) {
  Material mirror;
  mirror.ambient = 0;
  mirror.diffuse = 0;
  mirror.reflectivity = reflectivity;
  mirror.glossDegrees = glossDegrees;
  Scene scene;
  scene.environment.maxDepth = 64;
  scene.objects.push_back({PlaneShape{{0, 0, 0}, {0, 1, 0}}, mirror});
  scene.objects.push_back({PlaneShape{{0, 2, 0}, {0, -1, 0}}, mirror});
  return scene;
}

TEST(ShaderTest, RecursionStopsWhenThePathWeightFallsBelowTheCutoff) {
  ASSERT_EQ(kMinPathWeight, 1.0 / 65536);
  const World world(mirrorCorridor(0.5, 0));
  uint64_t rays = 0;
  Shader(world, {}).trace(Ray{{0, 1, 0}, normalize(Vec3(1, -1, 0))}, 0, Rng(3), rays);
  // The reflection of depth d weighs 2^-d: depths 1 to 16 are traced, not 17, though
  // max_depth is 64.
  EXPECT_EQ(rays, 17u);
}

TEST(ShaderTest, GlassInGlassTreeOfRaysIsBounded) {
  // Each hit spawns a reflected and a transmitted ray: 2^64 rays at max_depth 64 without the
  // cut-off, 2^d rays of weight 2^-d at depth d with it.
  Material glass;
  glass.reflectivity = 0.5;
  glass.transmissivity = 0.5;
  glass.ior = 1.5;
  Scene scene;
  scene.environment.maxDepth = 64;
  scene.objects.push_back({SphereShape{{0, 0, 0}, 1}, glass});
  glass.ior = 1.3;
  scene.objects.push_back({BoxShape{{-3, -3, -3}, {3, 3, 3}}, glass});
  scene.lights.push_back({PointLight{{2, 2, -2}}, Color(1)});
  const World world(scene);
  uint64_t rays = 0;
  const Color c =
      Shader(world, {}).trace(Ray{{0.3, 0.2, -5}, normalize(Vec3(0, 0, 1))}, 0, Rng(3), rays);
  EXPECT_GT(rays, 1000u);            // it did branch deep
  EXPECT_LT(rays, 2u * (2u << 16));  // at most 2^17 rays and one shadow ray each
  EXPECT_TRUE(std::isfinite(c.x) && std::isfinite(c.y) && std::isfinite(c.z));
}

TEST(ShaderTest, ConeOfTooLightRaysIsSampledByOne) {
  // Glossy mirrors at DRT 64: 64^64 rays without the cut-off. Depth 1 has 64 rays of weight
  // 1/64, depth 2 has 4096 of weight 1/4096; below that each cone is one ray of its whole
  // weight: 4096 chains to depth 64.
  const World world(mirrorCorridor(1, 5));
  RenderSettings settings;
  settings.drtRate = 64;
  uint64_t rays = 0;
  Shader(world, settings).trace(Ray{{0, 1, 0}, normalize(Vec3(1, -1, 0))}, 0, Rng(3), rays);
  EXPECT_EQ(rays, 1u + 64u + 4096u * 63u);
}

TEST(ShaderTest, NegligibleSpecularTermChangesNoBit) {
  Rng rng(17);
  int negligible = 0;
  for (int i = 0; i < 200000; ++i) {
    const double h = rng.uniform() < 0.1 ? 1 - rng.uniform() * 1e-3 : rng.uniform();
    const double n = 1 + std::floor(rng.uniform() * 500);
    const double specular = rng.uniform() < 0.1 ? 1e-300 : rng.uniform();
    const double scale = std::ldexp(1.0, -static_cast<int>(rng.uniform() * 60));
    const Color diffuse(rng.uniform() * scale, rng.uniform() * scale, rng.uniform() * scale);
    if (!specularIsNegligible(h, n, specular, diffuse)) continue;
    ++negligible;
    const Color term(specular * std::pow(h, n));
    ASSERT_EQ(diffuse + term, diffuse) << "h " << h << " n " << n << " specular " << specular;
  }
  EXPECT_GT(negligible, 50000);  // and it is the common case
  // Never when the term can matter: no diffuse light, a full highlight, exponent <= 0.
  EXPECT_FALSE(specularIsNegligible(0.1, 100, 1, Color(0.5, 0, 0.5)));
  EXPECT_FALSE(specularIsNegligible(1, 400, 1, Color(0.5)));
  EXPECT_FALSE(specularIsNegligible(0.1, 0, 1, Color(0.5)));
  EXPECT_FALSE(specularIsNegligible(0.1, -2, 1, Color(0.5)));
}

// A light said to be surely behind a surface has no sample that direct() would trace: each has
// a computed cosine of at most 0 (or no length). Lights are placed across the tangent plane,
// many of them a hair behind it, at scales from a thousandth to a thousand.
TEST(ShaderTest, LightsSurelyBehindHaveNoSampleInFront) {
  Rng rng(41);
  auto between = [&](double lo, double hi) { return lo + (hi - lo) * rng.uniform(); };
  auto unit = [&] {
    return normalize(Vec3(between(-1, 1), between(-1, 1), between(-1, 1)) + Vec3(1e-3));
  };
  int behind = 0, nearMiss = 0;
  for (int config = 0; config < 20000; ++config) {
    const double scale = std::pow(10.0, between(-3, 3));
    const Vec3 origin = scale * Vec3(between(-5, 5), between(-5, 5), between(-5, 5));
    const Vec3 n = unit();
    const double radius = scale * between(0, 1) * (config % 3 == 0 ? 0 : 1);
    // The light's centre: `depth` behind the plane (negative: in front), somewhere along it.
    const double depth =
        radius + scale * (config % 2 == 0 ? std::pow(10.0, between(-14, 0)) : between(-2, 2));
    const Vec3 along = cross(n, unit());
    const Vec3 center = origin - depth * n + scale * between(0, 5) * along;
    LightShape shape;
    if (config % 3 == 0) {
      shape = PointLight{center};
    } else if (config % 3 == 1) {
      shape = SphereLight{center, radius};
    } else {  // a square of half-diagonal `radius` around the centre, in a random plane
      const Vec3 e1 = unit(), e2 = normalize(cross(e1, unit()));
      const double half = radius / std::sqrt(2.0);
      shape = RectLight{center - half * (e1 + e2), 2 * half * e1, 2 * half * e2};
    }
    if (!surelyBehind(reachOf(shape), origin, n, dot(n, n))) {
      if (depth > radius) ++nearMiss;
      continue;
    }
    ++behind;
    for (int s = 0; s < 16; ++s) {
      Vec3 toLight = aimAt(shape, origin, s, 16, rng) - origin;
      const double distance = length(toLight);
      if (distance <= 0) continue;
      toLight /= distance;
      ASSERT_LE(dot(n, toLight), 0.0) << "configuration " << config;
    }
  }
  EXPECT_GT(behind, 5000);    // the common case, a light well behind, is recognised
  EXPECT_GT(nearMiss, 1000);  // a light a hair behind is left to the samples
  // In front of the plane, across it, on it: never.
  const Vec3 up(0, 1, 0);
  EXPECT_FALSE(surelyBehind(reachOf(PointLight{{0, 1, 0}}), {}, up, 1));
  EXPECT_FALSE(surelyBehind(reachOf(PointLight{{5, 0, 0}}), {}, up, 1));
  EXPECT_FALSE(surelyBehind(reachOf(SphereLight{{0, -1, 0}, 1.5}), {}, up, 1));
  EXPECT_FALSE(surelyBehind(reachOf(RectLight{{-1, -1, 0}, {0, 2, 0}, {1, 0, 0}}), {}, up, 1));
  EXPECT_TRUE(surelyBehind(reachOf(SphereLight{{0, -2, 0}, 1.5}), {}, up, 1));
  EXPECT_TRUE(surelyBehind(reachOf(RectLight{{-1, -3, 0}, {0, 2, 0}, {1, 0, 0}}), {}, up, 1));
}

// direct() passes over a light behind the surface, but takes the random numbers its samples
// would have drawn: the next light's samples, and everything after, see the same numbers.
TEST(ShaderTest, SkippedLightDrawsItsSamplesRandomNumbers) {
  Material m;
  Scene scene = floorScene(m);
  scene.lights.push_back({SphereLight{{0, -10, 0}, 1}, Color(1)});                   // behind
  scene.lights.push_back({RectLight{{-1, 5, -1}, {2, 0, 0}, {0, 0, 2}}, Color(1)});  // above
  const World world(scene);
  RenderSettings settings;
  settings.drtRate = 3;
  ASSERT_TRUE(surelyBehind(reachOf(scene.lights[0].shape), floorHit().point, {0, 1, 0}, 1));
  Rng rng(8);
  uint64_t rays = 0;
  Shader(world, settings).direct(floorHit(), {0, 1, 0}, {0, 1, 0}, rng, rays);
  EXPECT_EQ(rays, 3u);  // the rectangle's three samples only
  Rng expected(8);
  expected.skip(2 * 3 + 2 * 3);
  EXPECT_EQ(rng.uniform(), expected.uniform());
}

}  // namespace
}  // namespace prt
