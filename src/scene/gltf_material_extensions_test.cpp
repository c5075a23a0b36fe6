// glTF's material extensions beyond the core model, read into the path tracer's surface
// (trace/scene.h's PbrSurface): KHR_materials_volume. Each is checked on Blender's cube
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
  explicit CubeWithExtensions(const nlohmann::json& extensions) {
    nlohmann::json doc;
    std::ifstream(kCube) >> doc;
    nlohmann::json& material = doc["materials"][0];
    material["extensions"] = extensions;
    for (const auto& [name, value] : extensions.items()) doc["extensionsUsed"].push_back(name);
    path_ = fs::temp_directory_path() / ("prt-extensions-" + std::to_string(::getpid()) + ".gltf");
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
  const CubeWithExtensions cube({{"KHR_materials_transmission", {{"transmissionFactor", 1}}},
                                 {"KHR_materials_volume",
                                  {{"thicknessFactor", 0.5},
                                   {"attenuationColor", {0.8, 0.5, 0.25}},
                                   {"attenuationDistance", 0.3}}}});
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
  const CubeWithExtensions cube({{"KHR_materials_transmission", {{"transmissionFactor", 1}}},
                                 {"KHR_materials_volume",
                                  {{"attenuationColor", {0.8, 0.5, 0.25}},
                                   {"attenuationDistance", 0.3}}}});
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
  const CubeWithExtensions cube({{"KHR_materials_transmission", {{"transmissionFactor", 1}}},
                                 {"KHR_materials_volume",
                                  {{"thicknessFactor", -2},
                                   {"attenuationColor", {1.5, 0.5, -1}},
                                   {"attenuationDistance", 0}}}});
  const ImportedModel model = cube.read();
  const std::string line = outOfRange(model);
  EXPECT_NE(line.find("'CubeGrid': thickness -2 (taken as 0)"), std::string::npos) << line;
  EXPECT_NE(line.find("'CubeGrid': attenuation colour red 1.5 (taken as 1)"), std::string::npos) << line;
  EXPECT_NE(line.find("'CubeGrid': attenuation colour blue -1 (taken as 0)"), std::string::npos) << line;
  EXPECT_NE(line.find("'CubeGrid': attenuation distance 0 (taken as inf)"), std::string::npos) << line;
  EXPECT_TRUE(surfaceOf(model).thinWalled);
}

}  // namespace
}  // namespace prt
