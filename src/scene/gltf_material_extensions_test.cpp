// glTF's material extensions beyond the core model, read into the path tracer's surface
// (trace/scene.h's PbrSurface): KHR_materials_volume, _specular and _clearcoat. Each is checked on Blender's cube
// (tests/models/blender-cube.gltf) with the extension written into its material, for the
// values taken, the out-of-range warning, and the trip to a worker (scene text and asset pack).

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>
#include <unistd.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <limits>
#include <string>

#include "scene/asset_pack.h"
#include "scene/model_file.h"
#include "scene/scene_file.h"

namespace prt {
namespace {

namespace fs = std::filesystem;

const fs::path kCube = fs::path(PRT_SOURCE_DIR) / "tests" / "models" / "blender-cube.gltf";

// The cube with `extensions` as its material's, in a file of this process's (the cube holds its
// buffer and image as data: URIs).
class CubeWithExtensions {
 public:
  // `extensionsJson`: the material's "extensions" object, as JSON text.
  explicit CubeWithExtensions(const std::string& extensionsJson) {
    const nlohmann::json extensions = nlohmann::json::parse(extensionsJson);
    nlohmann::json doc;
    std::ifstream(kCube) >> doc;
    nlohmann::json& material = doc["materials"][0];
    material["extensions"] = extensions;
    for (const auto& [name, value] : extensions.items()) doc["extensionsUsed"].push_back(name);
    static int made = 0;
    path_ = fs::temp_directory_path() / ("prt-extensions-" + std::to_string(::getpid()) + "-" +
                                         std::to_string(++made) + ".gltf");
    std::ofstream(path_) << doc.dump();
  }
  ~CubeWithExtensions() {
    std::error_code error;
    fs::remove(path_, error);
  }
  CubeWithExtensions(const CubeWithExtensions&) = delete;
  CubeWithExtensions& operator=(const CubeWithExtensions&) = delete;

  std::string path() const { return path_.string(); }
  ImportedModel read() const { return readModelFile(path_.string()); }

 private:
  fs::path path_;
};

const PbrSurface& surfaceOf(const ImportedModel& model) {
  EXPECT_FALSE(model.objects.empty());
  return model.objects.at(0).material.pbr;
}

std::string outOfRange(const ImportedModel& model) {
  for (const std::string& w : model.warnings) {
    if (w.find("out of range") != std::string::npos) return w;
  }
  return "";
}

// What a worker gets: the scene text and the asset pack, parsed again.
void expectSameOnAWorker(const std::string& file) {
  const Scene scene = loadSceneFile(file);
  const Scene again = parseScene(writeScene(scene), "<from master>", unpackAssets(packAssets(scene)));
  ASSERT_EQ(again.objects.size(), scene.objects.size());
  for (size_t i = 0; i < scene.objects.size(); ++i) {
    EXPECT_EQ(again.objects[i].material, scene.objects[i].material) << i;
  }
}

TEST(GltfMaterialExtensions, VolumeAbsorbsInsideAThickGlass) {
  const CubeWithExtensions cube(R"({"KHR_materials_transmission": {"transmissionFactor": 1},
      "KHR_materials_volume": {"thicknessFactor": 0.5, "attenuationColor": [0.8, 0.5, 0.25],
                               "attenuationDistance": 0.3}})");
  const ImportedModel model = cube.read();
  const PbrSurface& p = surfaceOf(model);
  EXPECT_FALSE(p.thinWalled);
  EXPECT_EQ(p.attenuationColor, Color(0.8, 0.5, 0.25));
  EXPECT_EQ(p.attenuationDistance, 0.3);
  EXPECT_EQ(outOfRange(model), "");
  expectSameOnAWorker(cube.path());
}

// The extension's thickness is 0 unless given: a thin wall, which neither bends light (the
// paper's renderer too: an index of 1) nor absorbs it.
TEST(GltfMaterialExtensions, VolumeOfThicknessZeroIsAThinWall) {
  const CubeWithExtensions cube(R"({"KHR_materials_transmission": {"transmissionFactor": 1},
      "KHR_materials_volume": {"attenuationColor": [0.8, 0.5, 0.25], "attenuationDistance": 0.3}})");
  const ImportedModel model = cube.read();
  const Material& m = model.objects.at(0).material;
  EXPECT_TRUE(m.pbr.thinWalled);
  EXPECT_EQ(m.pbr.attenuationDistance, std::numeric_limits<double>::infinity());
  EXPECT_EQ(m.ior, 1.0);
  EXPECT_GT(m.transmissivity, 0.9);
  expectSameOnAWorker(cube.path());
}

// Values out of range are clamped as the others are, and named in the one warning.
TEST(GltfMaterialExtensions, VolumeValuesOutOfRangeAreClampedAndNamed) {
  const CubeWithExtensions cube(R"({"KHR_materials_transmission": {"transmissionFactor": 1},
      "KHR_materials_volume": {"thicknessFactor": -2, "attenuationColor": [1.5, 0.5, -1],
                               "attenuationDistance": 0}})");
  const ImportedModel model = cube.read();
  const std::string line = outOfRange(model);
  EXPECT_NE(line.find("'CubeGrid': thickness -2 (taken as 0)"), std::string::npos) << line;
  EXPECT_NE(line.find("'CubeGrid': attenuation colour red 1.5 (taken as 1)"), std::string::npos) << line;
  EXPECT_NE(line.find("'CubeGrid': attenuation colour blue -1 (taken as 0)"), std::string::npos) << line;
  EXPECT_NE(line.find("'CubeGrid': attenuation distance 0 (taken as inf)"), std::string::npos) << line;
  EXPECT_TRUE(surfaceOf(model).thinWalled);
}

// KHR_materials_specular: the dielectric's F0 from the index (1.7 here) times the colour, and
// the factor; the paper's renderer reflects the luminance of that.
TEST(GltfMaterialExtensions, SpecularScalesAndColoursTheDielectricsReflection) {
  const CubeWithExtensions cube(R"({"KHR_materials_ior": {"ior": 1.7},
      "KHR_materials_specular": {"specularFactor": 0.5, "specularColorFactor": [1, 0.5, 2]}})");
  const ImportedModel model = cube.read();
  const PbrSurface& p = surfaceOf(model);
  const double f0 = std::pow(0.7 / 2.7, 2);
  EXPECT_NEAR(p.specularLevel, f0 / 0.08, 1e-12);
  EXPECT_EQ(p.specularWeight, 0.5);
  EXPECT_EQ(p.specularColor, Color(1, 0.5, 2));
  EXPECT_EQ(outOfRange(model), "");
  expectSameOnAWorker(cube.path());
  // Out of range: clamped and named.
  const CubeWithExtensions wrong(
      R"({"KHR_materials_specular": {"specularFactor": 3, "specularColorFactor": [-1, 0.5, 2]}})");
  const ImportedModel clamped = wrong.read();
  const std::string line = outOfRange(clamped);
  EXPECT_NE(line.find("'CubeGrid': specular factor 3 (taken as 1)"), std::string::npos) << line;
  EXPECT_NE(line.find("'CubeGrid': specular colour red -1 (taken as 0)"), std::string::npos) << line;
  EXPECT_EQ(surfaceOf(clamped).specularWeight, 1.0);
}

TEST(GltfMaterialExtensions, ClearcoatIsReadWithItsRoughness) {
  const CubeWithExtensions cube(
      R"({"KHR_materials_clearcoat": {"clearcoatFactor": 0.8, "clearcoatRoughnessFactor": 0.15}})");
  const ImportedModel model = cube.read();
  EXPECT_EQ(surfaceOf(model).clearcoat, 0.8);
  EXPECT_EQ(surfaceOf(model).clearcoatRoughness, 0.15);
  EXPECT_EQ(outOfRange(model), "");
  expectSameOnAWorker(cube.path());
  const CubeWithExtensions wrong(
      R"({"KHR_materials_clearcoat": {"clearcoatFactor": 2, "clearcoatRoughnessFactor": -1}})");
  const ImportedModel clamped = wrong.read();
  const std::string line = outOfRange(clamped);
  EXPECT_NE(line.find("'CubeGrid': clearcoat 2 (taken as 1)"), std::string::npos) << line;
  EXPECT_NE(line.find("'CubeGrid': clearcoat roughness -1 (taken as 0)"), std::string::npos) << line;
}

}  // namespace
}  // namespace prt
