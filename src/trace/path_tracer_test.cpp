#include "trace/path_tracer.h"

#include <gtest/gtest.h>

#include <cmath>
#include <memory>

#include "trace/renderer.h"
#include "trace/tangents.h"

namespace prt {
namespace {

// A ball of the given surface inside a uniform white environment, seen by the path tracer.
Scene furnace(const Material& ball) {
  Scene scene;
  scene.camera.eye = Vec3(0, 0, -4);
  scene.camera.fovDegrees = 30;
  scene.image.width = 16;
  scene.image.height = 16;
  scene.environment.background = Color(1);
  scene.environment.integrator = Integrator::path;
  scene.objects.push_back({SphereShape{{0, 0, 0}, 1}, ball});
  return scene;
}

Material pbr(const Color& base, double metallic, double roughness, double transmission) {
  Material m;
  m.color = base;
  m.metallic = metallic;
  m.pbr.given = true;
  m.pbr.roughness = roughness;
  m.pbr.transmission = transmission;
  return m;
}

double meanOfImage(const Image& image) {
  double sum = 0;
  for (uint64_t p = 0; p < image.pixelCount(); ++p) sum += image.at(p).x;
  return sum / static_cast<double>(image.pixelCount());
}

// pbrt-v4's white furnace: an object that absorbs nothing, inside a uniform environment,
// disappears. A clear glass and a smooth white metal are deltas that lose nothing, so every
// pixel is 1 up to rounding (and up to paths longer than max_bounces, which end black).
TEST(PathTracerTest, WhiteFurnaceLosslessBallsVanish) {
  Material wall = pbr(Color(1), 0, 0, 1);
  wall.pbr.thinWalled = true;
  Material coated = pbr(Color(1), 1, 0, 0);  // a mirror under a clear coat: still all of it
  coated.pbr.clearcoat = 1;
  for (const Material& m : {pbr(Color(1), 1, 0, 0), pbr(Color(1), 0, 0, 1), wall, coated}) {
    const World world(furnace(m));
    const Renderer renderer(world, RenderSettings{4, 1});
    const Image image = renderImage(renderer, 1);
    double least = 2, most = 0;
    for (uint64_t p = 0; p < image.pixelCount(); ++p) {
      least = std::min(least, image.at(p).x);
      most = std::max(most, image.at(p).x);
    }
    EXPECT_NEAR(most, 1.0, 1e-6);
    // The glass's paths that bounce inside more than max_bounces times end black: a few
    // samples at the rim.
    EXPECT_GT(least, m.pbr.transmission > 0 ? 0.7 : 1 - 1e-6);
    EXPECT_GT(meanOfImage(image), m.pbr.transmission > 0 ? 0.99 : 1 - 1e-6);
  }
}

// A rough white metal or frosted glass loses only what single-scattering GGX loses (the
// light that would bounce between microfacets), a few per cent at these roughnesses: the
// image stays within that of the environment and never above it.
TEST(PathTracerTest, WhiteFurnaceRoughBallsLoseLittleAndGainNothing) {
  Material wall = pbr(Color(1), 0, 0.3, 1);
  wall.pbr.thinWalled = true;
  Material coated = pbr(Color(1), 1, 0.3, 0);
  coated.pbr.clearcoat = 1;
  coated.pbr.clearcoatRoughness = 0.2;
  for (const Material& m : {pbr(Color(1), 1, 0.3, 0), pbr(Color(1), 0, 0.3, 1), wall, coated}) {
    const World world(furnace(m));
    const Renderer renderer(world, RenderSettings{64, 1});
    const double mean = meanOfImage(renderImage(renderer, 2));
    EXPECT_LT(mean, 1.01);
    EXPECT_GT(mean, 0.93);
  }
}

// Beer and Lambert (KHR_materials_volume): a ray through the middle of a clear ball of index
// 1 (no Fresnel reflection, no bending) travels its diameter inside and keeps
// attenuationColor^(diameter / attenuationDistance) of the environment, per channel; a
// thin-walled ball of the same medium has no inside and absorbs nothing.
TEST(PathTracerTest, AVolumeAbsorbsAlongThePathInsideByBeerLambert) {
  Material glass = pbr(Color(1), 0, 0, 1);
  glass.pbr.ior = 1;
  glass.pbr.attenuationColor = Color(0.5, 0.25, 1);
  glass.pbr.attenuationDistance = 1;
  for (const bool thin : {false, true}) {
    glass.pbr.thinWalled = thin;
    const World world(furnace(glass));
    const PathTracer tracer(world);
    uint64_t rays = 0;
    const Color c = tracer.radiance(Ray{Vec3(0, 0, -4), Vec3(0, 0, 1)}, nullptr, Rng(5), rays);
    const Color expected = thin ? Color(1) : Color(0.25, 0.0625, 1);  // 2 units inside
    EXPECT_NEAR(c.x, expected.x, 1e-6) << thin;
    EXPECT_NEAR(c.y, expected.y, 1e-6) << thin;
    EXPECT_NEAR(c.z, expected.z, 1e-6) << thin;
  }
  // An absorbing glass in the furnace gives back less than the environment, never more.
  glass.pbr.ior = 1.5;
  glass.pbr.thinWalled = false;
  const World world(furnace(glass));
  const double mean = meanOfImage(renderImage(Renderer(world, RenderSettings{16, 1}), 2));
  EXPECT_LT(mean, 0.9);
  EXPECT_GT(mean, 0.2);
}

// The medium is the path's, not the surface's that ends a segment: a glowing ball inside an
// absorbing clear one (index 1) is seen through half a unit of the medium, though the segment
// ends on the glowing ball's outside.
TEST(PathTracerTest, APathInsideAMediumIsAbsorbedWhateverItMeets) {
  Material glass = pbr(Color(1), 0, 0, 1);
  glass.pbr.ior = 1;
  glass.pbr.attenuationColor = Color(0.5, 0.25, 1);
  glass.pbr.attenuationDistance = 1;
  Material glow = pbr(Color(0), 0, 1, 0);
  glow.emission = Color(1);
  Scene scene = furnace(glass);
  scene.environment.background = Color(0);
  scene.objects.push_back({SphereShape{{0, 0, 0}, 0.5}, glow});
  const World world(scene);
  const PathTracer tracer(world);
  uint64_t rays = 0;
  const Color c = tracer.radiance(Ray{Vec3(0, 0, -4), Vec3(0, 0, 1)}, nullptr, Rng(5), rays);
  EXPECT_NEAR(c.x, std::sqrt(0.5), 1e-6);
  EXPECT_NEAR(c.y, 0.5, 1e-6);
  EXPECT_NEAR(c.z, 1, 1e-6);
}

// A map of uniform radiance 1 is the world colour 1 by another road: next-event estimation
// aims at it and multiple importance sampling weighs those shadow rays against the BSDF's. The
// two images agree within noise for rough and smooth, metal, dielectric and glass balls on a
// rough floor — no light counted twice or missed.
TEST(PathTracerTest, AUniformMapLightsAsTheSameWorldColourDoes) {
  auto uniform = std::make_shared<Image>(16, 8);
  for (int y = 0; y < 8; ++y) {
    for (int x = 0; x < 16; ++x) uniform->set(x, y, Color(1));
  }
  for (const Material& m : {pbr(Color(0.9, 0.5, 0.3), 0, 1, 0), pbr(Color(0.9), 1, 0.25, 0),
                            pbr(Color(1), 0, 0.2, 1)}) {
    Scene scene = furnace(m);
    scene.objects.push_back({PlaneShape{{0, -1, 0}, {0, 1, 0}}, pbr(Color(0.6), 0, 0.9, 0)});
    scene.camera.eye = Vec3(0, 1.5, -4);
    const World world(scene);
    const double colour = meanOfImage(renderImage(Renderer(world, RenderSettings{128, 1}), 2));
    scene.environment.map.image = uniform;
    const World mapped(scene);
    ASSERT_TRUE(mapped.environment().sampled());
    const Renderer renderer(mapped, RenderSettings{128, 1});
    const double map = meanOfImage(renderImage(renderer, 2));
    EXPECT_NEAR(map / colour, 1, 0.01) << m.metallic << " " << m.pbr.transmission;
    EXPECT_EQ(renderer.nonFiniteSamples(), 0u);
  }
}

// The image is a function of the pixels alone: any number of threads, any order of tasks.
TEST(PathTracerTest, PixelsDoNotDependOnThreadsOrOrder) {
  Scene scene = furnace(pbr(Color(0.8, 0.3, 0.2), 0, 0.5, 0));
  scene.environment.background = Color(0.2, 0.3, 0.4);
  Material floor = pbr(Color(0.5), 0, 0.8, 0);
  floor.pbr.clearcoat = 0.7;  // and glTF's extensions: a coat, a coloured specular, a volume
  floor.pbr.clearcoatRoughness = 0.1;
  scene.objects.push_back({PlaneShape{{0, -1, 0}, {0, 1, 0}}, floor});
  scene.objects[0].material.pbr.specularColor = Color(2, 1, 0.5);
  scene.objects[0].material.pbr.specularWeight = 0.8;
  Material amber = pbr(Color(1), 0, 0.1, 1);
  amber.pbr.attenuationColor = Color(0.9, 0.5, 0.2);
  amber.pbr.attenuationDistance = 0.3;
  scene.objects.push_back({SphereShape{{1.2, -0.6, -0.5}, 0.4}, amber});
  Light sun;
  sun.shape = DirectionalLight{normalize(Vec3(1, -2, 1))};
  scene.lights.push_back(sun);
  // And a map with a bright spot, sampled by next-event estimation.
  auto map = std::make_shared<Image>(8, 4);
  for (int y = 0; y < 4; ++y) {
    for (int x = 0; x < 8; ++x) map->set(x, y, x == 5 && y == 1 ? Color(50, 40, 30) : Color(0.3));
  }
  scene.environment.map.image = map;
  scene.environment.map.rotateDegrees = 33;
  const World world(scene);
  const Renderer renderer(world, RenderSettings{8, 1});
  const Image one = renderImage(renderer, 1);
  const Image two = renderImage(renderer, 2);
  for (uint64_t p = 0; p < renderer.pixelCount(); ++p) ASSERT_EQ(one.at(p), two.at(p)) << p;
  // Every other pixel, odd ones first, as tasks of a worker.
  const uint64_t half = renderer.pixelCount() / 2;
  for (const uint64_t first : {1u, 0u}) {
    std::vector<Color> colors(half);
    renderTasks(renderer, TaskSet::strided(first, half, 2), 2, colors);
    for (uint64_t i = 0; i < half; ++i) {  // at the image's precision
      const Color a = one.at(first + 2 * i), b = colors[i];
      ASSERT_EQ(static_cast<float>(a.x), static_cast<float>(b.x)) << i;
      ASSERT_EQ(static_cast<float>(a.y), static_cast<float>(b.y)) << i;
      ASSERT_EQ(static_cast<float>(a.z), static_cast<float>(b.z)) << i;
    }
  }
  EXPECT_EQ(renderer.nonFiniteSamples(), 0u);
  EXPECT_GT(meanOfImage(one), 0.05);
}

// A sample whose radiance is not finite (here an emitter of NaN, which no reader lets through)
// never reaches a pixel: it is counted and left out of the pixel's mean.
TEST(PathTracerTest, NonFiniteSamplesAreCountedAndLeftOut) {
  Scene scene = furnace(pbr(Color(0.5), 0, 0.5, 0));
  Material bad = pbr(Color(0.5), 0, 0.5, 0);
  bad.emission = Color(std::nan(""), 0, 0);
  scene.objects.push_back({SphereShape{{0.9, 0.9, -0.5}, 0.3}, bad});
  const World world(scene);
  const Renderer renderer(world, RenderSettings{4, 1});
  const Image image = renderImage(renderer, 2);
  EXPECT_GT(renderer.nonFiniteSamples(), 0u);
  for (uint64_t p = 0; p < image.pixelCount(); ++p) ASSERT_TRUE(isFinite(image.at(p))) << p;
  // The pixels around the emitter keep the light of their finite samples: not black.
  EXPECT_GT(meanOfImage(image), 0.2);
}

// The rule for scenes written for the paper's renderer: a mirror becomes a metal, a glass a
// glass, a matte surface a rough dielectric.
TEST(PathTracerTest, HallMaterialsMapToTheModelByTheWrittenRule) {
  Material matte;
  EXPECT_EQ(pbrFromHall(matte).roughness, 1.0);
  Material mirror;
  mirror.reflectivity = 0.8;
  EXPECT_EQ(pbrFromHall(mirror).roughness, 0.0);
  Material glass;
  glass.transmissivity = 0.9;
  glass.ior = 1.5;
  const PbrSurface g = pbrFromHall(glass);
  EXPECT_EQ(g.transmission, 0.9);
  EXPECT_EQ(g.ior, 1.5);
  EXPECT_EQ(g.coverage, 1.0);
  Material sheer;
  sheer.transmissivity = 0.25;  // ior 1: light passes straight through
  EXPECT_EQ(pbrFromHall(sheer).coverage, 0.75);
  Material given = pbr(Color(1), 1, 0.25, 0);
  EXPECT_EQ(pbrFromHall(given), given.pbr);
}

// A 4 x 4 floor facing +y, mapped twice over, with its tangents, under a sun, seen from
// above at an angle; `floor` its material, `textures` the scene's.
Scene mappedFloor(const Material& floor, std::vector<Texture> textures) {
  auto mesh = std::make_shared<TriangleMesh>();
  mesh->vertices = {{-2, 0, -2}, {2, 0, -2}, {2, 0, 2}, {-2, 0, 2}};
  mesh->triangles = {{0, 2, 1}, {0, 3, 2}};
  mesh->normals.assign(4, Vec3(0, 1, 0));
  mesh->uvs = {{0, 0}, {2, 0}, {2, 2}, {0, 2}};
  mesh->tangents = computeTangents(*mesh);
  Scene scene;
  scene.camera.eye = Vec3(0, 3, -4);
  scene.camera.lookAt = Vec3(0, 0, 0.5);
  scene.image.width = 16;
  scene.image.height = 12;
  scene.environment.background = Color(0.2, 0.25, 0.3);
  scene.environment.integrator = Integrator::path;
  scene.objects.push_back({MeshShape{mesh, MeshSource{}}, floor});
  Light sun;
  sun.shape = DirectionalLight{normalize(Vec3(1, -2, 1.5))};
  scene.lights.push_back(sun);
  scene.textures = std::move(textures);
  return scene;
}

// A 2 x 2 data texture of one RGB texel value.
Texture dataTexture(uint8_t r, uint8_t g, uint8_t b) {
  auto image = std::make_shared<TextureImage>();
  image->width = 2;
  image->height = 2;
  image->channels = 3;
  image->texels.resize(12);
  for (size_t i = 0; i < 12; i += 3) {
    image->texels[i] = r;
    image->texels[i + 1] = g;
    image->texels[i + 2] = b;
  }
  Texture t;
  t.image = image;
  t.linear = true;
  return t;
}

Image renderSmall(const Scene& scene) {
  const World world(scene);
  return renderImage(Renderer(world, RenderSettings{4, 1}), 2);
}

bool sameBits(const Image& a, const Image& b) {
  for (uint64_t p = 0; p < a.pixelCount(); ++p) {
    if (!(a.at(p) == b.at(p))) return false;
  }
  return true;
}

// The flat texel (128, 128, 255) is no tilt at all: the same bits as no normal map. A tilted
// map changes the image.
TEST(PathTracerTest, AFlatNormalMapRendersTheSameBitsAsNone) {
  const Material plain = pbr(Color(0.7, 0.6, 0.5), 0, 0.4, 0);
  const Image none = renderSmall(mappedFloor(plain, {}));
  Material flat = plain;
  flat.pbr.normalTexture.texture = 0;
  const Image mapped = renderSmall(mappedFloor(flat, {dataTexture(128, 128, 255)}));
  EXPECT_TRUE(sameBits(none, mapped));
  // Tilted along -x (u grows along +x), towards the sun, whose light travels along +x:
  // brighter; along +x, away from it: darker.
  const Image towards = renderSmall(mappedFloor(flat, {dataTexture(56, 128, 230)}));
  EXPECT_FALSE(sameBits(none, towards));
  EXPECT_GT(meanOfImage(towards), meanOfImage(none));
  EXPECT_LT(meanOfImage(renderSmall(mappedFloor(flat, {dataTexture(200, 128, 230)}))), meanOfImage(none));
  flat.pbr.normalScale = 0;  // a scale of 0 flattens any map
  EXPECT_TRUE(sameBits(none, renderSmall(mappedFloor(flat, {dataTexture(200, 128, 230)}))));
}

// A metallic-roughness texture multiplies the factors, B metallic and G roughness: one of
// constant value renders the same bits as those values given as the factors; the
// transmission texture's R multiplies the transmission likewise.
TEST(PathTracerTest, AConstantMetallicRoughnessTextureIsItsFactors) {
  const Image factors = renderSmall(mappedFloor(pbr(Color(0.8, 0.7, 0.3), 200 / 255.0, 100 / 255.0, 0), {}));
  Material textured = pbr(Color(0.8, 0.7, 0.3), 1, 1, 0);
  textured.pbr.metallicRoughnessTexture.texture = 0;
  EXPECT_TRUE(sameBits(factors, renderSmall(mappedFloor(textured, {dataTexture(17, 100, 200)}))));
  // Swapped channels: another surface.
  EXPECT_FALSE(sameBits(factors, renderSmall(mappedFloor(textured, {dataTexture(17, 200, 100)}))));

  const Image glass = renderSmall(mappedFloor(pbr(Color(0.9), 0, 0.3, 128 / 255.0), {}));
  Material clearing = pbr(Color(0.9), 0, 0.3, 1);
  clearing.pbr.transmissionTexture.texture = 0;
  EXPECT_TRUE(sameBits(glass, renderSmall(mappedFloor(clearing, {dataTexture(128, 9, 9)}))));
}

}  // namespace
}  // namespace prt
