#include "scene/environment_file.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <string>

#include "core/input_error.h"
#include "scene/asset_pack.h"
#include "scene/scene_file.h"
#include "trace/environment_light.h"

namespace prt {
namespace {

namespace fs = std::filesystem;

const fs::path kMaps = fs::path(PRT_SOURCE_DIR) / "scenes/maps";

class EnvironmentFileTest : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::temp_directory_path() /
           ("prt-envmap-" + std::to_string(::testing::UnitTest::GetInstance()->random_seed()) +
            "-" + ::testing::UnitTest::GetInstance()->current_test_info()->name());
    fs::create_directories(dir_);
  }
  void TearDown() override { fs::remove_all(dir_); }
  std::string write(const std::string& name, const std::string& bytes) {
    const fs::path p = dir_ / name;
    std::ofstream(p, std::ios::binary) << bytes;
    return p.string();
  }
  std::string errorOf(const std::string& path, size_t budget = kEnvironmentBudgetBytes) {
    try {
      readEnvironmentMap(path, budget);
    } catch (const InputError& e) {
      return e.what();
    }
    return "";
  }
  fs::path dir_;
};

// Files prt did not write (scripts/make-environment-maps.py: RGBE by its specification, EXR by ffmpeg): the sun's 2 x 2 texels at
// columns 47-48 and rows 7-8 from the top, the sky above the horizon, the ground below.
TEST_F(EnvironmentFileTest, ReadsRadianceAndOpenExrMapsOtherToolsWrote) {
  const auto hdr = readEnvironmentMap((kMaps / "sky.hdr").string());
  const auto exr = readEnvironmentMap((kMaps / "sky.exr").string());
  for (const auto& map : {hdr, exr}) {
    ASSERT_EQ(map->width(), 64);
    ASSERT_EQ(map->height(), 32);
    int bestX = 0, bestY = 0;
    for (int y = 0; y < 32; ++y) {
      for (int x = 0; x < 64; ++x) {
        if (map->at(x, y).x > map->at(bestX, bestY).x) bestX = x, bestY = y;
      }
    }
    EXPECT_TRUE(bestX == 47 || bestX == 48) << bestX;
    EXPECT_TRUE(bestY == 7 || bestY == 8) << bestY;
    EXPECT_NEAR(map->at(bestX, bestY).x, 400, 4);
    EXPECT_NEAR(map->at(0, 0).z, 0.9, 0.01);   // the sky, top row
    EXPECT_NEAR(map->at(0, 31).x, 0.12, 0.01);  // the ground, bottom row
  }
  // The two encodings agree within RGBE's 8-bit mantissa (half floats are finer).
  for (int y = 0; y < 32; ++y) {
    for (int x = 0; x < 64; ++x) {
      EXPECT_NEAR(hdr->at(x, y).y, exr->at(x, y).y, 0.01 * exr->at(x, y).y + 1e-3);
    }
  }
  // And the light it makes: the sun at azimuth 90 degrees (+z), 45 degrees up.
  Environment e;
  e.map.image = hdr;
  const EnvironmentLight light(e);
  EXPECT_GT(light.radiance(normalize(Vec3(0, 1, 1))).x, 100);
  EXPECT_LT(light.radiance(normalize(Vec3(0, 1, -1))).x, 1);
}

TEST_F(EnvironmentFileTest, BadMapsAreRefusedNamingTheFile) {
  const std::string missing = (dir_ / "nowhere.hdr").string();
  EXPECT_NE(errorOf(missing).find("nowhere.hdr' does not exist"), std::string::npos) << errorOf(missing);
  const std::string png = write("sky.png", "\x89PNG");
  EXPECT_NE(errorOf(png).find("not a kind of file"), std::string::npos);
  const std::string text = write("notes.hdr", "not an image at all");
  EXPECT_NE(errorOf(text).find("notes.hdr' is not a Radiance HDR image"), std::string::npos)
      << errorOf(text);
  const std::string exr = write("broken.exr", "v/1\x01 not really");
  EXPECT_NE(errorOf(exr).find("broken.exr"), std::string::npos);
  // A header that claims 60000 x 60000 texels (43 GB decoded) is refused before decoding.
  const std::string huge =
      write("huge.hdr", std::string("#?RADIANCE\nFORMAT=32-bit_rle_rgbe\n\n-Y 60000 +X 60000\n") +
                            std::string(64, '\x01'));
  EXPECT_NE(errorOf(huge).find("over the budget"), std::string::npos) << errorOf(huge);
  // So is the sky map under a budget too small for it (64 x 32 x 12 bytes).
  EXPECT_NE(errorOf((kMaps / "sky.hdr").string(), 1000).find("over the budget"),
            std::string::npos);
  EXPECT_NE(errorOf((kMaps / "sky.exr").string(), 1000).find("too large"),
            std::string::npos);
  EXPECT_EQ(errorOf(dir_.string() + "/"), errorOf(dir_.string() + "/"));  // no crash on a folder
}

// The scene language names a map relative to the scene file; the text prt writes for workers
// names it again, and the assets carry its texels so that a worker needs no copy.
TEST_F(EnvironmentFileTest, TheSceneLanguageReadsWritesAndShipsTheMap) {
  fs::copy_file(kMaps / "sky.exr", dir_ / "sky.exr");
  const std::string path = write(
      "a.scene",
      "camera { eye 0 1 -4 look_at 0 0 0 }\nimage { width 8 height 6 }\n"
      "environment { integrator path map \"sky.exr\" map_strength 2.5 map_rotate -30 }\n"
      "sphere { center 0 0 0 radius 1 }\n");
  const Scene scene = loadSceneFile(path);
  const EnvironmentMap& map = scene.environment.map;
  ASSERT_TRUE(map.image);
  EXPECT_EQ(map.file, (dir_ / "sky.exr").string());
  EXPECT_EQ(map.strength, 2.5);
  EXPECT_EQ(map.rotateDegrees, -30);
  const std::string text = writeScene(scene);
  EXPECT_NE(text.find("map \"" + (dir_ / "sky.exr").string() + "\""), std::string::npos) << text;
  // A worker: the text and the assets, no file (the map's file is gone).
  const std::vector<uint8_t> assets = packAssets(scene);
  fs::remove(dir_ / "sky.exr");
  const Scene worker = parseScene(text, "sent.scene", unpackAssets(assets));
  EXPECT_TRUE(worker.environment.map == map);
  // Without the assets, the missing file is an error at the map's place in the text.
  const std::string again = write("b.scene", "image { width 8 height 6 }\n"
                                             "environment {\n  map \"sky.exr\" }\n");
  try {
    loadSceneFile(again);
    FAIL() << "a missing map was accepted";
  } catch (const InputError& e) {
    EXPECT_NE(e.format().find("b.scene:3:7: error: "), std::string::npos) << e.format();
    EXPECT_NE(std::string(e.what()).find("sky.exr' does not exist"), std::string::npos) << e.what();
  }
  // Assets that claim a map of negative radiance are refused.
  std::vector<uint8_t> bad = assets;
  const size_t lastFloat = bad.size() - 4;
  const float negative = -1;
  std::memcpy(&bad[lastFloat], &negative, 4);
  EXPECT_THROW(unpackAssets(bad), std::runtime_error);
}

}  // namespace
}  // namespace prt
