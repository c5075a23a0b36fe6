#include <gtest/gtest.h>

#include <cmath>

#include "scene/scene_file.h"

namespace prt {
namespace {

constexpr const char* kPreamble =
    "camera { eye 0 0 -5 look_at 0 0 0 }\nimage { width 4 height 3 }\n";

Scene parse(const std::string& text) {
  return parseScene(text, "test.scene");
}

// The example scene of docs/scene-format.md.
constexpr const char* kFigure8 = R"(# Figure 8: the basic-features scene
camera { eye 0 1.5 -6  look_at 0 0.8 0  up 0 1 0  fov 40 }
image { width 320 height 240 output "fig8.png" }
environment { background 0.05 0.05 0.1  ambient 0.1 0.1 0.1  max_depth 6 }
sampling { samples 1 drt 1 }          # optional defaults; command line overrides
material glass { color 1 1 1 diffuse 0.05 specular 0.8 phong 200 reflect 0.1 transmit 0.85 ior 1.5 }
light point  { position -4 6 -6 color 1 1 1 }
light sphere { center 4 6 -3 radius 0.6 color 0.8 0.8 0.8 }
light rect   { corner -1 5 -1 edge1 2 0 0 edge2 0 0 2 color 1 1 1 }
sphere { center 0 1 0 radius 1 surface glass }
sphere { center 2 0.5 1 radius 0.5 surface { color 0.2 0.3 1 diffuse 0.8 specular 0.3 phong 30 } }
box    { min -1 0 2 max 0 1 3 surface { color 1 0.9 0.1 } }
plane  { point 0 0 0 normal 0 1 0 surface { color 0.3 0.3 0.3 reflect 0.7 gloss 2 } }
)";

TEST(SceneParser, ParsesTheFullExample) {
  const Scene scene = parse(kFigure8);
  EXPECT_EQ(scene.camera.eye, Vec3(0, 1.5, -6));
  EXPECT_EQ(scene.camera.lookAt, Vec3(0, 0.8, 0));
  EXPECT_EQ(scene.camera.up, Vec3(0, 1, 0));
  EXPECT_EQ(scene.camera.fovDegrees, 40);
  EXPECT_EQ(scene.image.width, 320);
  EXPECT_EQ(scene.image.height, 240);
  EXPECT_EQ(scene.image.output, "fig8.png");
  EXPECT_EQ(scene.environment.background, Color(0.05, 0.05, 0.1));
  EXPECT_EQ(scene.environment.ambient, Color(0.1, 0.1, 0.1));
  EXPECT_EQ(scene.environment.maxDepth, 6);
  EXPECT_EQ(scene.sampling.samplesPerPixel, 1);
  EXPECT_EQ(scene.sampling.drtRate, 1);

  ASSERT_EQ(scene.lights.size(), 3u);
  EXPECT_EQ(scene.lights[0], (Light{PointLight{{-4, 6, -6}}, {1, 1, 1}}));
  EXPECT_EQ(scene.lights[1], (Light{SphereLight{{4, 6, -3}, 0.6}, {0.8, 0.8, 0.8}}));
  EXPECT_EQ(scene.lights[2], (Light{RectLight{{-1, 5, -1}, {2, 0, 0}, {0, 0, 2}}, {1, 1, 1}}));

  ASSERT_EQ(scene.objects.size(), 4u);
  Material glass;
  glass.color = {1, 1, 1};
  glass.diffuse = 0.05;
  glass.specular = 0.8;
  glass.phongExponent = 200;
  glass.reflectivity = 0.1;
  glass.transmissivity = 0.85;
  glass.ior = 1.5;
  EXPECT_EQ(scene.objects[0], (Object{SphereShape{{0, 1, 0}, 1}, glass}));

  Material blue;
  blue.color = {0.2, 0.3, 1};
  blue.diffuse = 0.8;
  blue.specular = 0.3;
  blue.phongExponent = 30;
  EXPECT_EQ(scene.objects[1], (Object{SphereShape{{2, 0.5, 1}, 0.5}, blue}));

  Material yellow;
  yellow.color = {1, 0.9, 0.1};
  EXPECT_EQ(scene.objects[2], (Object{BoxShape{{-1, 0, 2}, {0, 1, 3}}, yellow}));

  Material floor;
  floor.color = {0.3, 0.3, 0.3};
  floor.reflectivity = 0.7;
  floor.glossDegrees = 2;
  EXPECT_EQ(scene.objects[3], (Object{PlaneShape{{0, 0, 0}, {0, 1, 0}}, floor}));
}

TEST(SceneParser, OptionalBlocksAndFieldsTakeTheDefaults) {
  const Scene scene = parse(kPreamble + std::string("sphere { radius 2 center 1 2 3 }"));
  const Scene defaults;
  EXPECT_EQ(scene.camera.up, defaults.camera.up);
  EXPECT_EQ(scene.camera.fovDegrees, defaults.camera.fovDegrees);
  EXPECT_EQ(scene.image.output, defaults.image.output);
  EXPECT_EQ(scene.environment.background, defaults.environment.background);
  EXPECT_EQ(scene.environment.maxDepth, defaults.environment.maxDepth);
  EXPECT_EQ(scene.sampling.samplesPerPixel, defaults.sampling.samplesPerPixel);
  EXPECT_TRUE(scene.lights.empty());
  ASSERT_EQ(scene.objects.size(), 1u);
  EXPECT_EQ(scene.objects[0].material, Material{});
  EXPECT_EQ(std::get<SphereShape>(scene.objects[0].shape).radius, 2);
}

TEST(SceneParser, AllowsAnEmptyWorld) {
  const Scene scene = parse(kPreamble);
  EXPECT_TRUE(scene.objects.empty());
  EXPECT_TRUE(scene.lights.empty());
}

TEST(SceneParser, AcceptsCommentsAndFreeLayout) {
  const Scene scene = parse(R"(# a comment line
camera {   # after a brace
  eye 0 0 -5     # after a value
  look_at
     0 0 0
}
image{width 8 height 6 output "a#b.ppm"}#glued
# sphere { center 0 0 0 radius 1 }   commented out
)");
  EXPECT_EQ(scene.camera.eye, Vec3(0, 0, -5));
  EXPECT_EQ(scene.image.width, 8);
  EXPECT_EQ(scene.image.output, "a#b.ppm");  // '#' inside a string is not a comment
  EXPECT_TRUE(scene.objects.empty());
}

TEST(SceneParser, AcceptsWindowsLineEndings) {
  const Scene scene =
      parse("camera { eye 0 0 -5\r\n look_at 0 0 0 }\r\nimage { width 2 height 2 }\r\n");
  EXPECT_EQ(scene.image.width, 2);
}

TEST(SceneParser, NamedMaterialsCanBeUsedExtendedAndOverridden) {
  const Scene scene = parse(kPreamble + std::string(R"(
material glass { transmit 0.9 ior 1.5 }
material frosted glass { translucency 10 }
sphere { center 0 0 0 radius 1 surface glass }
sphere { center 0 0 0 radius 1 surface glass { ior 1.33 } }
sphere { center 0 0 0 radius 1 surface frosted }
)"));
  ASSERT_EQ(scene.objects.size(), 3u);
  Material glass;
  glass.transmissivity = 0.9;
  glass.ior = 1.5;
  glass.pbr.ior = 1.5;  // `ior` sets the path tracer's index too
  EXPECT_EQ(scene.objects[0].material, glass);
  Material water = glass;
  water.ior = 1.33;
  water.pbr.ior = 1.33;
  EXPECT_EQ(scene.objects[1].material, water);
  Material frosted = glass;
  frosted.translucencyDegrees = 10;
  EXPECT_EQ(scene.objects[2].material, frosted);
}

TEST(SceneParser, NormalisesPlaneNormals) {
  const Scene scene = parse(kPreamble + std::string("plane { point 0 0 0 normal 0 2 2 }"));
  const Vec3 normal = std::get<PlaneShape>(scene.objects[0].shape).normal;
  EXPECT_NEAR(length(normal), 1.0, 1e-15);
  EXPECT_NEAR(normal.y, std::sqrt(0.5), 1e-15);
  EXPECT_NEAR(normal.z, std::sqrt(0.5), 1e-15);
}

TEST(SceneParser, AcceptsBoundaryValues) {
  const Scene scene = parse(R"(
camera { eye 0 0 -5 look_at 0 0 0 up 1 0 0 fov 179.9 }
image { width 32768 height 8192 output "big.PFM" }
environment { background 0 0 0 ambient 0 0 0 max_depth 64 }
sampling { samples 4096 drt 64 }
sphere { center 0 0 0 radius 1e-9 surface { color 0 0 0 ambient 0 diffuse 1 specular 1
         phong 1 reflect 1 transmit 0 ior 10 gloss 89.99 translucency 0 } }
light sphere { center 0 0 0 radius 1 color 100 100 100 }
)");
  EXPECT_EQ(scene.image.width, 32768);
  EXPECT_EQ(scene.image.height, 8192);  // exactly 2^28 pixels
  EXPECT_EQ(scene.sampling.drtRate, 64);
  EXPECT_EQ(scene.objects[0].material.ior, 10);
  EXPECT_EQ(scene.lights[0].color, Color(100, 100, 100));
}

TEST(SceneParser, AcceptsIntegersWithSignAndNumbersInExponentForm) {
  const Scene scene =
      parse("camera { eye +0 0 -5e0 look_at .0 0. 0 }\nimage { width +4 height 3 }\n");
  EXPECT_EQ(scene.camera.eye, Vec3(0, 0, -5));
  EXPECT_EQ(scene.image.width, 4);
}

}  // namespace
}  // namespace prt
