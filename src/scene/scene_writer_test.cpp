#include <gtest/gtest.h>

#include <bit>
#include <cmath>
#include <cstdint>

#include "scene/scene_file.h"

namespace prt {
namespace {

// Bit-for-bit comparison: operator== on doubles would let -0.0 == 0.0 through.
void expectSameBits(double a, double b, const char* what) {
  EXPECT_EQ(std::bit_cast<uint64_t>(a), std::bit_cast<uint64_t>(b))
      << what << ": " << a << " vs " << b;
}
void expectSameBits(const Vec3& a, const Vec3& b, const char* what) {
  expectSameBits(a.x, b.x, what);
  expectSameBits(a.y, b.y, what);
  expectSameBits(a.z, b.z, what);
}

void expectSameMaterial(const Material& a, const Material& b) {
  expectSameBits(a.color, b.color, "color");
  expectSameBits(a.ambient, b.ambient, "ambient");
  expectSameBits(a.diffuse, b.diffuse, "diffuse");
  expectSameBits(a.specular, b.specular, "specular");
  expectSameBits(a.phongExponent, b.phongExponent, "phong");
  expectSameBits(a.reflectivity, b.reflectivity, "reflect");
  expectSameBits(a.transmissivity, b.transmissivity, "transmit");
  expectSameBits(a.ior, b.ior, "ior");
  expectSameBits(a.glossDegrees, b.glossDegrees, "gloss");
  expectSameBits(a.translucencyDegrees, b.translucencyDegrees, "translucency");
}

void expectSameScene(const Scene& a, const Scene& b) {
  expectSameBits(a.camera.eye, b.camera.eye, "eye");
  expectSameBits(a.camera.lookAt, b.camera.lookAt, "look_at");
  expectSameBits(a.camera.up, b.camera.up, "up");
  expectSameBits(a.camera.fovDegrees, b.camera.fovDegrees, "fov");
  EXPECT_EQ(a.image.width, b.image.width);
  EXPECT_EQ(a.image.height, b.image.height);
  EXPECT_EQ(a.image.output, b.image.output);
  expectSameBits(a.environment.background, b.environment.background, "background");
  expectSameBits(a.environment.ambient, b.environment.ambient, "ambient");
  EXPECT_EQ(a.environment.maxDepth, b.environment.maxDepth);
  EXPECT_EQ(a.sampling.samplesPerPixel, b.sampling.samplesPerPixel);
  EXPECT_EQ(a.sampling.drtRate, b.sampling.drtRate);

  ASSERT_EQ(a.lights.size(), b.lights.size());
  for (size_t i = 0; i < a.lights.size(); ++i) {
    ASSERT_EQ(a.lights[i].shape.index(), b.lights[i].shape.index());
    expectSameBits(a.lights[i].color, b.lights[i].color, "light color");
    if (const auto* point = std::get_if<PointLight>(&a.lights[i].shape)) {
      expectSameBits(point->position, std::get<PointLight>(b.lights[i].shape).position, "position");
    } else if (const auto* sphere = std::get_if<SphereLight>(&a.lights[i].shape)) {
      const auto& other = std::get<SphereLight>(b.lights[i].shape);
      expectSameBits(sphere->center, other.center, "center");
      expectSameBits(sphere->radius, other.radius, "radius");
    } else {
      const auto& rect = std::get<RectLight>(a.lights[i].shape);
      const auto& other = std::get<RectLight>(b.lights[i].shape);
      expectSameBits(rect.corner, other.corner, "corner");
      expectSameBits(rect.edge1, other.edge1, "edge1");
      expectSameBits(rect.edge2, other.edge2, "edge2");
    }
  }

  ASSERT_EQ(a.objects.size(), b.objects.size());
  for (size_t i = 0; i < a.objects.size(); ++i) {
    ASSERT_EQ(a.objects[i].shape.index(), b.objects[i].shape.index());
    expectSameMaterial(a.objects[i].material, b.objects[i].material);
    if (const auto* sphere = std::get_if<SphereShape>(&a.objects[i].shape)) {
      const auto& other = std::get<SphereShape>(b.objects[i].shape);
      expectSameBits(sphere->center, other.center, "center");
      expectSameBits(sphere->radius, other.radius, "radius");
    } else if (const auto* box = std::get_if<BoxShape>(&a.objects[i].shape)) {
      const auto& other = std::get<BoxShape>(b.objects[i].shape);
      expectSameBits(box->min, other.min, "min");
      expectSameBits(box->max, other.max, "max");
    } else {
      const auto& plane = std::get<PlaneShape>(a.objects[i].shape);
      const auto& other = std::get<PlaneShape>(b.objects[i].shape);
      expectSameBits(plane.point, other.point, "point");
      expectSameBits(plane.normal, other.normal, "normal");
    }
  }
}

Scene roundTrip(const Scene& scene) {
  return parseScene(writeScene(scene), "written.scene");
}

// Values chosen to break any writer that prints a fixed number of digits.
Scene awkwardScene() {
  const double third = 1.0 / 3.0;
  Scene scene;
  scene.camera = Camera{{0.1, -1e-300, third}, {0.1 + 0.2, 5e-324, -0.0}, {0, 1, 1e-17}, 33.3};
  scene.image = ImageSpec{641, 479, "dir with space/quote\"back\\slash.pfm"};
  scene.environment = Environment{{third, 0.0, 1e-300}, {2.0 / 3.0, 0.7, 0.1}, 0};
  scene.sampling = Sampling{4096, 64};

  scene.lights.push_back(Light{PointLight{{-4.000000000000001, 6, 1e9}}, {1e-300, 12.5, third}});
  scene.lights.push_back(Light{SphereLight{{third, -third, 0.1}, 1e-7}, {1, 1, 1}});
  scene.lights.push_back(Light{RectLight{{0, 5, 0}, {third, 0, 0}, {0, 0, 0.1 * 3}}, {0, 0, 0}});

  Material odd;
  odd.color = {third, 0.1, 1e-300};
  odd.ambient = 0.1 + 0.2;
  odd.diffuse = 1.0 - 1e-16;
  odd.specular = 5e-324;
  odd.phongExponent = 1.0 + 1e-15;
  odd.reflectivity = third;
  odd.transmissivity = 0.0;
  odd.ior = std::sqrt(2.0);
  odd.glossDegrees = std::nextafter(90.0, 0.0);
  odd.translucencyDegrees = 1e-300;
  scene.objects.push_back(Object{SphereShape{{third, 0.1, -0.7}, third}, odd});
  scene.objects.push_back(Object{BoxShape{{-1e-300, 0.1, third}, {1e-300, 0.2, 0.5}}, Material{}});
  Vec3 normal = normalize(Vec3{1, third, 0.1});
  scene.objects.push_back(Object{PlaneShape{{0.1, 0.2, 0.3}, normal}, odd});
  return scene;
}

TEST(SceneWriter, RoundTripIsBitExact) {
  const Scene scene = awkwardScene();
  expectSameScene(roundTrip(scene), scene);
}

TEST(SceneWriter, SecondRoundTripGivesTheSameText) {
  const Scene scene = awkwardScene();
  const std::string text = writeScene(scene);
  EXPECT_EQ(writeScene(parseScene(text, "a.scene")), text);
}

TEST(SceneWriter, KeepsNegativeZeros) {
  Scene scene = awkwardScene();
  scene.objects[0].material.specular = -0.0;  // equal to the default 0.0, but not in bits
  scene.camera.lookAt.z = -0.0;
  const Scene back = roundTrip(scene);
  expectSameBits(back.objects[0].material.specular, -0.0, "specular");
  expectSameBits(back.camera.lookAt.z, -0.0, "look_at z");
}

TEST(SceneWriter, RoundTripsThePathTracersSettingsAndSurfaces) {
  Scene scene = awkwardScene();
  scene.environment.integrator = Integrator::path;
  scene.environment.maxBounces = 3;
  Material& m = scene.objects[1].material;
  m.pbr.given = true;
  m.pbr.roughness = 1.0 / 3.0;
  m.pbr.transmission = 0.25;
  m.pbr.ior = 1.45;
  m.pbr.specularLevel = 0.1;
  m.pbr.coverage = 0.5;
  m.pbr.attenuationColor = Color(0.7, 1.0 / 3.0, 0);
  m.pbr.attenuationDistance = 0.125;
  m.pbr.specularLevel = 7.25;
  m.pbr.specularWeight = 0.3;
  m.pbr.specularColor = Color(2, 0.5, 1.0 / 3.0);
  m.pbr.clearcoat = 0.75;
  m.pbr.clearcoatRoughness = 0.1;
  Material& wall = scene.objects[0].material;
  wall.pbr.given = true;
  wall.pbr.thinWalled = true;
  const Scene back = roundTrip(scene);
  expectSameScene(back, scene);
  EXPECT_EQ(back.environment.integrator, Integrator::path);
  EXPECT_EQ(back.environment.maxBounces, 3);
  EXPECT_EQ(back.objects[1].material.pbr, m.pbr);
  EXPECT_EQ(back.objects[0].material.pbr, scene.objects[0].material.pbr);  // ior's own
}

TEST(SceneWriter, RoundTripsTheDefaultScene) {
  const Scene scene;
  expectSameScene(roundTrip(scene), scene);
}

TEST(SceneWriter, RoundTripsAParsedScene) {
  const Scene parsed = parseScene(R"(
camera { eye 0 1.5 -6 look_at 0 0.8 0 fov 40 }
image { width 320 height 240 output "fig8.png" }
material glass { color 1 1 1 diffuse 0.05 transmit 0.85 ior 1.5 }
sphere { center 0 1 0 radius 1 surface glass { ior 1.33 } }
plane { point 0 0 0 normal 1 2 3 }
light rect { corner -1 5 -1 edge1 2 0 0 edge2 0 0 2 }
)",
                                  "in.scene");
  expectSameScene(roundTrip(parsed), parsed);
}

TEST(SceneWriter, WritesSurfacesOnlyWithFieldsThatDifferFromDefaults) {
  Scene scene;
  scene.objects.push_back(Object{SphereShape{{0, 0, 0}, 1}, Material{}});
  Material shiny;
  shiny.reflectivity = 0.5;
  scene.objects.push_back(Object{SphereShape{{0, 0, 0}, 2}, shiny});
  const std::string text = writeScene(scene);
  EXPECT_NE(text.find("sphere { center 0 0 0 radius 1 }\n"), std::string::npos) << text;
  EXPECT_NE(text.find("sphere { center 0 0 0 radius 2 surface { reflect 0.5 } }\n"),
            std::string::npos)
      << text;
}

TEST(SceneWriter, WritesReadableText) {
  Scene scene;
  scene.camera.fovDegrees = 40;
  scene.image.output = "fig8.png";
  const std::string text = writeScene(scene);
  EXPECT_EQ(text.substr(0, text.find('\n')), "camera { eye 0 0 -5 look_at 0 0 0 up 0 1 0 fov 40 }");
  EXPECT_NE(text.find("image { width 320 height 240 output \"fig8.png\" }\n"), std::string::npos);
}

}  // namespace
}  // namespace prt
