#include "export/pov_exporter.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <numbers>
#include <regex>
#include <string>

#include "trace/camera.h"

namespace prt {
namespace {

bool contains(const std::string& text, const std::string& part) {
  return text.find(part) != std::string::npos;
}

// The vector after `keyword` (as in "direction <1, 2, 3>") in `text`.
Vec3 vectorAfter(const std::string& text, const std::string& keyword) {
  const std::regex pattern(keyword + " <([^,>]+), ([^,>]+), ([^,>]+)>");
  std::smatch m;
  EXPECT_TRUE(std::regex_search(text, m, pattern)) << keyword;
  if (m.empty()) return {};
  return {std::strtod(m[1].str().c_str(), nullptr), std::strtod(m[2].str().c_str(), nullptr),
          std::strtod(m[3].str().c_str(), nullptr)};
}

Scene testScene() {
  Scene scene;
  scene.camera.eye = Vec3(1, 2, -6);
  scene.camera.lookAt = Vec3(0, 1, 0);
  scene.camera.up = Vec3(0, 1, 0);
  scene.camera.fovDegrees = 45;
  scene.image.width = 320;
  scene.image.height = 240;
  scene.environment.background = Color(0.25, 0.5, 0.75);
  scene.environment.ambient = Color(0.1, 0.2, 0.3);
  scene.environment.maxDepth = 5;
  scene.lights.push_back({PointLight{{-4, 7, -6}}, Color(1, 0.9, 0.8)});
  scene.lights.push_back({SphereLight{{0, 8, 0}, 0.5}, Color(0.5, 0.5, 0.5)});
  scene.lights.push_back({RectLight{{2, 6, -3}, {1.5, 0, 0}, {0, 0, 1}}, Color(0.4, 0.4, 0.4)});

  Material glass;
  glass.color = Color(1, 1, 1);
  glass.ambient = 0.2;
  glass.diffuse = 0.1;
  glass.specular = 0.9;
  glass.phongExponent = 300;
  glass.reflectivity = 0.1;
  glass.transmissivity = 0.5;
  glass.ior = 1.5;
  scene.objects.push_back({SphereShape{{1, 2, 3}, 0.5}, glass});

  Material blue;
  blue.color = Color(0.15, 0.25, 0.95);
  blue.ambient = 1;
  blue.diffuse = 0.8;
  blue.specular = 0.5;
  blue.phongExponent = 60;
  scene.objects.push_back({BoxShape{{-1, 0, 2}, {0.5, 1.5, 3}}, blue});

  Material floor;
  floor.color = Color(0.3, 0.3, 0.3);
  floor.diffuse = 0.25;
  floor.reflectivity = 0.7;
  floor.glossDegrees = 5;
  scene.objects.push_back({PlaneShape{{0, 2, 0}, {0, 1, 0}}, floor});
  return scene;
}

// The number right after the first `keyword` in `text`.
double numberAfter(const std::string& text, const std::string& keyword) {
  const size_t at = text.find(keyword);
  EXPECT_NE(at, std::string::npos) << keyword;
  return at == std::string::npos ? 0 : std::strtod(text.c_str() + at + keyword.size(), nullptr);
}

TEST(PovExporter, HorizontalAngleFromVerticalFov) {
  // 45 degrees vertical on a 4:3 image: 2 atan(tan(22.5) 4/3) = 57.82 degrees.
  EXPECT_NEAR(horizontalFovDegrees(45, 4.0 / 3.0), 57.8224, 1e-4);
  EXPECT_NEAR(horizontalFovDegrees(40, 1.0), 40.0, 1e-12);
  EXPECT_NEAR(horizontalFovDegrees(90, 2.0), 2 * std::atan(2.0) * 180 / std::numbers::pi, 1e-12);
  const std::string text = toPovray(testScene(), {});
  EXPECT_NEAR(numberAfter(text, "angle "), 57.8224016, 1e-6) << text;
  EXPECT_TRUE(contains(text, "right x*1.33333333333")) << text;
  EXPECT_TRUE(contains(text, "up y\n"));
  EXPECT_TRUE(contains(text, "location <1, 2, -6>"));
  EXPECT_TRUE(contains(text, "sky <0, 1, 0>"));
  EXPECT_TRUE(contains(text, "look_at <0, 1, 0>"));
}

// POV-Ray's perspective camera as its documentation defines it: look_at turns `direction`
// towards the point, right = sky x direction and up = direction x right keep their lengths,
// `angle` sets |direction| = |right| / 2 / tan(angle / 2); a pixel's ray passes through
// direction + (u - 1/2) right + (1/2 - v) up for the pixel centre's image coordinates u, v.
// That must be PRT's ray through the same pixel centre.
TEST(PovExporter, CameraRaysArePrtRays) {
  Scene scene = testScene();
  scene.camera.up = Vec3(0.2, 1, 0.1);  // not perpendicular to the view: look_at fixes it
  const std::string text = toPovray(scene, {});
  const Vec3 location = vectorAfter(text, "location");
  const Vec3 lookAt = vectorAfter(text, "look_at");
  const Vec3 sky = vectorAfter(text, "sky");
  const double aspect = numberAfter(text, "right x*");
  const double angle = numberAfter(text, "angle ") * std::numbers::pi / 180;
  const Vec3 forward = normalize(lookAt - location);
  const Vec3 right = aspect * normalize(cross(sky, forward));
  const Vec3 up = normalize(cross(forward, right));
  const Vec3 direction = forward * (aspect / 2 / std::tan(angle / 2));

  const PinholeCamera camera(scene.camera, scene.image.width, scene.image.height);
  const double w = scene.image.width, h = scene.image.height;
  for (const auto& [x, y] :
       {std::pair{0, 0}, {319, 0}, {0, 239}, {319, 239}, {160, 120}, {7, 200}}) {
    const double u = (x + 0.5) / w, v = (y + 0.5) / h;
    const Vec3 pov = normalize(direction + (u - 0.5) * right + (0.5 - v) * up);
    const Vec3 prt = camera.generateRay(x + 0.5, y + 0.5).direction;
    EXPECT_NEAR(pov.x, prt.x, 1e-9) << x << "," << y;
    EXPECT_NEAR(pov.y, prt.y, 1e-9) << x << "," << y;
    EXPECT_NEAR(pov.z, prt.z, 1e-9) << x << "," << y;
  }
}

TEST(PovExporter, GlobalSettingsKeepLinearMathsAndPrtDepth) {
  const std::string text = toPovray(testScene(), {});
  EXPECT_TRUE(contains(text, "#version 3.7;"));
  EXPECT_TRUE(contains(text, "assumed_gamma 1.0"));
  EXPECT_TRUE(contains(text, "ambient_light rgb <0.1, 0.2, 0.3>"));
  EXPECT_TRUE(contains(text, "max_trace_level 6"));  // PRT max_depth 5: generations 0..5
  EXPECT_TRUE(contains(text, "adc_bailout 0"));
  EXPECT_TRUE(contains(text, "background { rgb <0.25, 0.5, 0.75> }"));
  EXPECT_EQ(povMaxTraceLevel(0), 1);
  EXPECT_EQ(povMaxTraceLevel(64), 65);
}

TEST(PovExporter, Lights) {
  RenderSettings settings;
  const std::string text = toPovray(testScene(), settings);
  EXPECT_TRUE(contains(text, "light_source { <-4, 7, -6> color rgb <1, 0.9, 0.8> }"));
  // Sphere light: a disc of the sphere's radius facing the shaded point.
  EXPECT_TRUE(contains(text, "<0, 8, 0> color rgb <0.5, 0.5, 0.5>"));
  EXPECT_TRUE(contains(text,
                       "area_light <1, 0, 0>, <0, 1, 0>, 9, 9 adaptive 3 "
                       "area_illumination on circular orient"))
      << text;
  // Rectangle light: centred, spanned by its edges.
  EXPECT_TRUE(contains(text, "<2.75, 6, -2.5> color rgb <0.4, 0.4, 0.4>"));
  EXPECT_TRUE(contains(text, "area_light <1.5, 0, 0>, <0, 0, 1>, 9, 9 adaptive 3"));

  PovOptions one;
  one.areaLightGrid = 1;
  const std::string points = toPovray(testScene(), settings, one);
  EXPECT_FALSE(contains(points, "area_light"));
  EXPECT_TRUE(contains(points, "a point light at the centre"));
}

TEST(PovExporter, AreaLightGridGrowsWithPrtSamples) {
  EXPECT_EQ(povAreaLightGrid({1, 1}), 9);
  EXPECT_EQ(povAreaLightGrid({16, 4}), 9);    // 64 <= 81
  EXPECT_EQ(povAreaLightGrid({16, 16}), 17);  // 256 <= 289
  PovOptions fixed;
  fixed.areaLightGrid = 5;
  EXPECT_EQ(povAreaLightGrid({16, 16}, fixed), 5);
}

TEST(PovExporter, AllThreeShapes) {
  const std::string text = toPovray(testScene(), {});
  EXPECT_TRUE(contains(text, "sphere {\n  <1, 2, 3>, 0.5\n"));
  EXPECT_TRUE(contains(text, "box {\n  <-1, 0, 2>, <0.5, 1.5, 3>\n"));
  // A plane through (0, 2, 0) facing +y: POV-Ray's normal and distance from the origin.
  EXPECT_TRUE(contains(text, "<0, 1, 0>, 2\n"));
  EXPECT_TRUE(contains(text, "one-sided"));
}

TEST(PovExporter, MaterialsMapHallsTerms) {
  const std::string text = toPovray(testScene(), {});
  // Glass: transmit 0.5 halves POV-Ray's ambient and diffuse, so they are doubled.
  EXPECT_TRUE(contains(text, "pigment { rgbt <1, 1, 1, 0.5> }"));
  EXPECT_TRUE(contains(text,
                       "finish { ambient 0.4 diffuse 0.2 brilliance 1 phong 0.9 "
                       "phong_size 300 reflection { 0.1 } }"))
      << text;
  EXPECT_TRUE(contains(text, "interior { ior 1.5 }"));
  // Opaque: the weights as they are.
  EXPECT_TRUE(contains(text, "pigment { rgb <0.15, 0.25, 0.95> }"));
  EXPECT_TRUE(contains(text,
                       "finish { ambient 1 diffuse 0.8 brilliance 1 phong 0.5 "
                       "phong_size 60 }"));
  // Mirror with gloss: reflection kept, the blur noted as not reproduced.
  EXPECT_TRUE(contains(text, "finish { ambient 1 diffuse 0.25 brilliance 1 reflection { 0.7 } }"));
  EXPECT_TRUE(contains(text, "gloss 5 degrees"));
}

TEST(PovExporter, FullTransmissionIsCappedWhileThereIsLocalLight) {
  Scene scene = testScene();
  Material& m = scene.objects[0].material;
  m.transmissivity = 1;
  m.ambient = 0;
  m.diffuse = 0.05;
  const std::string text = toPovray(scene, {});
  EXPECT_TRUE(contains(text, "rgbt <1, 1, 1, 0.999>"));
  EXPECT_TRUE(contains(text, "finish { ambient 0 diffuse 50 "));
  m.diffuse = 0;
  EXPECT_TRUE(contains(toPovray(scene, {}), "rgbt <1, 1, 1, 1>"));
}

TEST(PovExporter, AntialiasingDepth) {
  EXPECT_EQ(povAntialiasDepth(1), 0);
  EXPECT_EQ(povAntialiasDepth(2), 1);
  EXPECT_EQ(povAntialiasDepth(8), 3);   // 10 samples
  EXPECT_EQ(povAntialiasDepth(16), 4);  // 17 samples
  EXPECT_EQ(povAntialiasDepth(4096), 9);
}

TEST(PovExporter, CommandLine) {
  PovRun run;
  run.sceneFile = "a.pov";
  run.imageFile = "a.png";
  run.width = 160;
  run.height = 120;
  auto args = povrayArguments(run);
  auto has = [&](const std::string& a) {
    return std::find(args.begin(), args.end(), a) != args.end();
  };
  EXPECT_TRUE(has("+Ia.pov") && has("+Oa.png") && has("+W160") && has("+H120"));
  EXPECT_TRUE(has("+FN") && has("-D") && has("File_Gamma=sRGB") && has("-A"));
  EXPECT_FALSE(has("+WT1"));
  run.samplesPerPixel = 16;
  run.threads = 1;
  run.imageFile = "a.ppm";
  args = povrayArguments(run);
  EXPECT_TRUE(has("+A0.0") && has("+AM1") && has("+R4") && has("-J") && has("+WT1"));
  EXPECT_TRUE(has("+FP"));
  // The header names the file and the matching command.
  PovOptions options;
  options.fileName = "fig.pov";
  const std::string text = toPovray(testScene(), {16, 1}, options);
  EXPECT_TRUE(contains(text, "povray +Ifig.pov +Ofig.png +W320 +H240")) << text;
}

}  // namespace
}  // namespace prt

namespace prt {
namespace {

// A mesh goes out as mesh2: each vertex once, the normals when it has them, the triangles by
// index, with the object's texture.
TEST(PovExporter, MeshesAreMesh2) {
  Scene scene = testScene();
  auto mesh = std::make_shared<TriangleMesh>();
  mesh->vertices = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
  mesh->triangles = {{0, 2, 1}, {0, 1, 3}};
  Material red;
  red.color = {1, 0, 0};
  scene.objects.push_back({MeshShape{mesh, {}}, red});
  std::string text = toPovray(scene, {});
  EXPECT_TRUE(contains(text, "mesh2 {")) << text;
  EXPECT_TRUE(contains(text, "vertex_vectors { 4,")) << text;
  EXPECT_TRUE(contains(text, "<0, 2, 1>, <0, 1, 3>")) << text;
  EXPECT_TRUE(contains(text, "face_indices { 2,")) << text;
  EXPECT_FALSE(contains(text, "normal_vectors")) << text;
  EXPECT_TRUE(contains(text.substr(text.find("mesh2 {")), "rgb <1, 0, 0>")) << text;
  mesh->normals.assign(4, Vec3(0, 0, 1));
  text = toPovray(scene, {});
  EXPECT_TRUE(contains(text, "normal_vectors { 4,")) << text;
}

}  // namespace
}  // namespace prt

namespace prt {
namespace {

// POV-Ray's image maps only repeat. A texture mirrored along u (glTF's MIRRORED_REPEAT, which
// Khronos's BoxTextured uses to show its logo the right way round on every face) is written
// with its mirror image beside it and u halved: texel (x, y) of the mirrored texture at u in
// [1, 2) is texel (2w - 1 - x, y) of the written image at u / 2, as PRT samples it.
TEST(PovExporter, MirroredTextureIsWrittenWithItsMirrorImage) {
  Scene scene = testScene();
  auto image = std::make_shared<TextureImage>();
  image->width = 2;
  image->height = 1;
  image->channels = 3;
  image->texels = {255, 0, 0, 0, 0, 255};  // red, blue
  Texture texture;
  texture.image = image;
  texture.wrapU = TextureWrap::mirror;
  scene.textures.push_back(texture);
  auto mesh = std::make_shared<TriangleMesh>();
  mesh->vertices = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
  mesh->triangles = {{0, 1, 2}};
  mesh->uvs = {{{1.5f, 0.25f}}, {{2.0f, 0.25f}}, {{1.0f, 0.75f}}};
  Material m;
  m.color = {1, 1, 1};
  m.colorTexture.texture = 0;
  scene.objects.push_back({InstanceShape{mesh, Transform::identity()}, m});
  const PovExport out = exportPovray(scene, {});
  ASSERT_EQ(out.images.size(), 1u);
  const Image& written = out.images[0].image;
  ASSERT_EQ(written.width(), 4);
  ASSERT_EQ(written.height(), 1);
  EXPECT_EQ(written.at(0, 0), Color(1, 0, 0));
  EXPECT_EQ(written.at(1, 0), Color(0, 0, 1));
  EXPECT_EQ(written.at(2, 0), Color(0, 0, 1));
  EXPECT_EQ(written.at(3, 0), Color(1, 0, 0));
  // u halved; v turned to POV-Ray's v up.
  EXPECT_TRUE(contains(out.text, "<0.75, 0.75>, <1, 0.75>, <0.5, 0.25>")) << out.text;
  EXPECT_FALSE(contains(out.text, "POV-Ray repeats it")) << out.text;
  // A clamped texture is written as it is, with a note that POV-Ray repeats it.
  scene.textures[0].wrapU = TextureWrap::clamp;
  const PovExport clamped = exportPovray(scene, {});
  EXPECT_EQ(clamped.images[0].image.width(), 2);
  EXPECT_TRUE(contains(clamped.text, "<1.5, 0.75>, <2, 0.75>, <1, 0.25>")) << clamped.text;
  EXPECT_TRUE(contains(clamped.text, "PRT clamps this texture; POV-Ray repeats it")) << clamped.text;
}

}  // namespace
}  // namespace prt
