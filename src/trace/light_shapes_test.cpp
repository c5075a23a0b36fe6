// The lights and surfaces model files bring: spot cones, directional light, the inverse-square
// law, emission, metallic reflections, and surface colours from textures and vertex colours.

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "trace/shader.h"

namespace prt {
namespace {

Material matte() {
  Material m;
  m.color = Color(1, 1, 1);
  m.ambient = 0;
  m.diffuse = 1;
  return m;
}

Scene floorWith(const Light& light) {
  Scene scene;
  scene.environment.ambient = Color();
  scene.objects.push_back({PlaneShape{{0, 0, 0}, {0, 1, 0}}, matte()});
  scene.lights.push_back(light);
  return scene;
}

// The light the floor at (x, 0, 0) receives, seen from straight above.
double litAt(const Scene& scene, double x) {
  const World world(scene);
  const Shader shader(world, {});
  Hit hit;
  hit.point = {x, 0, 0};
  hit.normal = {0, 1, 0};
  Rng rng(3);
  uint64_t rays = 0;
  return shader.direct(hit, {0, 1, 0}, {0, 1, 0}, rng, rays).x;
}

TEST(LightShapes, SpotIsFullInsideItsInnerConeNoneOutsideItsOuterAndSmoothBetween) {
  // A spot 1 above the floor shining down: the angle off its axis at x is atan(x).
  const Light spot{SpotLight{{0, 1, 0}, {0, -1, 0}, 20, 40}, Color(1)};
  const Scene scene = floorWith(spot);
  const Light point{PointLight{{0, 1, 0}}, Color(1)};
  const Scene plain = floorWith(point);
  const double inside = std::tan(10 * std::numbers::pi / 180);
  EXPECT_DOUBLE_EQ(litAt(scene, inside), litAt(plain, inside));
  EXPECT_EQ(litAt(scene, std::tan(41 * std::numbers::pi / 180)), 0.0);
  // Halfway between the cones' cosines the smooth step is a half.
  const double cosMid = 0.5 * (std::cos(20 * std::numbers::pi / 180) + std::cos(40 * std::numbers::pi / 180));
  const double mid = std::tan(std::acos(cosMid));
  EXPECT_NEAR(litAt(scene, mid) / litAt(plain, mid), 0.5, 1e-6);
}

TEST(LightShapes, InverseSquareFalloffWeakensWithDistance) {
  Light near{PointLight{{0, 1, 0}}, Color(1), Falloff::inverseSquare};
  Light far{PointLight{{0, 3, 0}}, Color(1), Falloff::inverseSquare};
  EXPECT_NEAR(litAt(floorWith(near), 0), 1.0, 1e-6);  // intensity 1 at distance 1
  EXPECT_NEAR(litAt(floorWith(far), 0), 1.0 / 9, 1e-6);
  far.falloff = Falloff::none;  // the paper's lights do not fall off
  EXPECT_NEAR(litAt(floorWith(far), 0), 1.0, 1e-6);
}

TEST(LightShapes, DirectionalLightIsParallelAndCastsShadowsFromInfinitelyFar) {
  const Vec3 down = normalize(Vec3(1, -1, 0));
  Scene scene = floorWith(Light{DirectionalLight{down}, Color(2)});
  EXPECT_NEAR(litAt(scene, 0), 2 * std::sqrt(0.5), 1e-9);
  EXPECT_NEAR(litAt(scene, 1000), 2 * std::sqrt(0.5), 1e-9);  // the same everywhere
  // A box far up the light's way shades the floor below it.
  scene.objects.push_back({BoxShape{{-60, 50, -1}, {-40, 51, 1}}, matte()});
  EXPECT_EQ(litAt(scene, 0), 0.0);
  EXPECT_GT(litAt(scene, 20), 1.0);
  // A light from below the floor lights nothing.
  EXPECT_EQ(litAt(floorWith(Light{DirectionalLight{{0, 1, 0}}, Color(1)}), 0), 0.0);
}

// The colour a camera ray straight down onto a unit square at the origin sees, where the
// square is an instance with texture coordinates and the material shows only its albedo
// (ambient 1 in an ambient light of 1) plus its emission.
Color seenOnSquare(const Material& m, const Scene& base, double x, double z) {
  Scene scene = base;
  auto square = std::make_shared<TriangleMesh>();
  square->vertices = {{0, 0, 0}, {1, 0, 0}, {1, 0, 1}, {0, 0, 1}};
  square->triangles = {{0, 2, 1}, {0, 3, 2}};
  square->uvs = {{0, 1}, {1, 1}, {1, 0}, {0, 0}};
  scene.objects.push_back({InstanceShape{square, Transform::identity()}, m});
  scene.environment.ambient = Color(1);
  scene.environment.maxDepth = 0;
  const World world(scene);
  const Shader shader(world, {});
  uint64_t rays = 0;
  return shader.trace(Ray{{x, 1, z}, {0, -1, 0}}, 0, Rng(1), rays);
}

TEST(LightShapes, TexturesColourTheSurfaceAtItsCoordinates) {
  Scene scene;
  auto image = std::make_shared<TextureImage>();
  image->width = 2;
  image->height = 1;
  image->channels = 3;
  image->texels = {255, 0, 0, 0, 255, 0};  // red on the left, green on the right
  Texture texture;
  texture.image = image;
  texture.nearest = true;
  scene.textures.push_back(texture);
  Material m;
  m.ambient = 1;
  m.diffuse = 0;
  m.color = Color(0.5, 1, 1);
  m.colorTexture.texture = 0;
  const Color left = seenOnSquare(m, scene, 0.2, 0.5), right = seenOnSquare(m, scene, 0.8, 0.5);
  EXPECT_NEAR(left.x, 0.5, 1e-12);  // the texture times the material's colour
  EXPECT_NEAR(left.y, 0, 1e-12);
  EXPECT_NEAR(right.y, 1, 1e-12);
  // A transform of the coordinates (here: u mirrored) moves the texture on the surface.
  m.colorTexture.uv.m = {-1, 0, 1, 0, 1, 0};
  EXPECT_NEAR(seenOnSquare(m, scene, 0.2, 0.5).y, 1, 1e-12);
}

TEST(LightShapes, EmissionIsAddedWhateverTheLights) {
  Material m;
  m.ambient = 0;
  m.diffuse = 0;
  m.emission = Color(0.25, 0.5, 2);
  const Color c = seenOnSquare(m, Scene{}, 0.5, 0.5);
  EXPECT_EQ(c, Color(0.25, 0.5, 2));
}

TEST(LightShapes, MetalsTintTheirReflectionsByTheirColour) {
  Scene scene;
  scene.environment.background = Color(1);
  Material metal;
  metal.ambient = metal.diffuse = 0;
  metal.reflectivity = 1;
  metal.color = Color(1, 0.5, 0.25);
  scene.objects.push_back({PlaneShape{{0, 0, 0}, {0, 1, 0}}, metal});
  auto seen = [](Scene s) {
    const World world(s);
    const Shader shader(world, {});
    uint64_t rays = 0;
    return shader.trace(Ray{{0, 1, 0}, normalize(Vec3(0, -1, 1))}, 0, Rng(1), rays);
  };
  EXPECT_EQ(seen(scene), Color(1));  // metallic 0: the background as it is
  scene.objects[0].material.metallic = 1;
  EXPECT_EQ(seen(scene), Color(1, 0.5, 0.25));
}

}  // namespace
}  // namespace prt
