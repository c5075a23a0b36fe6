// End-to-end tests of environment maps through the prt command: --environment and its
// strength and turn on a model file and on a .scene file's own map, the same bits serially and
// under the thread driver with every kind of strategy, and bad maps refused with the file named
// and nothing written.

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>

#include "image/image_compare.h"
#include "image/image_io.h"
#include "prt_command.h"

namespace prt {
namespace {

namespace fs = std::filesystem;

using prt::e2e::Result;
using prt::e2e::run;
using EnvironmentCliTest = prt::e2e::ScratchDirTest;

const fs::path kEnvSource(PRT_SOURCE_DIR);
const std::string kSkyHdr = (kEnvSource / "scenes/maps/sky.hdr").string();
const std::string kSkyExr = (kEnvSource / "scenes/maps/sky.exr").string();

double meanGreenOf(const Image& image) {
  double sum = 0;
  for (size_t p = 0; p < image.pixelCount(); ++p) sum += image.at(p).y;
  return sum / static_cast<double>(image.pixelCount());
}

TEST_F(EnvironmentCliTest, AMapLightsAModelFileAndTurnsAndScalesAsAsked) {
  const std::string model = (kEnvSource / "tests/models/blender-cube.glb").string();
  const std::string size = " --width 40 --height 30 --spp 4 -q -o ";
  ASSERT_EQ(run("render " + model + size + path("plain.pfm")).exitCode, 0);
  Result r = run("render " + model + " --environment " + kSkyHdr + size + path("sky.pfm"));
  ASSERT_EQ(r.exitCode, 0) << r.output;
  ASSERT_EQ(run("render " + model + " --environment " + kSkyExr + size + path("exr.pfm")).exitCode, 0);
  ASSERT_EQ(run("render " + model + " --environment " + kSkyHdr + " --environment-rotate 180" + size +
                path("turned.pfm")).exitCode, 0);
  ASSERT_EQ(run("render " + model + " --environment " + kSkyHdr + " --environment-strength 2" + size +
                path("double.pfm")).exitCode, 0);
  const Image plain = readImage(path("plain.pfm")), sky = readImage(path("sky.pfm"));
  const Image exr = readImage(path("exr.pfm")), turned = readImage(path("turned.pfm"));
  const Image twice = readImage(path("double.pfm"));
  EXPECT_GT(meanGreenOf(sky), 1.5 * meanGreenOf(plain));  // the sky lights it
  EXPECT_GT(psnr(sky, exr), 30.0);                     // the same sky in either file
  EXPECT_LT(psnr(sky, turned), 30.0);                  // the sun elsewhere
  // Twice the strength is twice the light (the model's own lights as well: less than twice).
  EXPECT_GT(meanGreenOf(twice), 1.5 * meanGreenOf(sky));
  // The paper's renderer shows the map where rays leave the scene.
  ASSERT_EQ(run("render " + model + " --integrator hall --environment " + kSkyHdr + size +
                path("hall.pfm")).exitCode, 0);
  ASSERT_EQ(run("render " + model + " --integrator hall" + size + path("hall-plain.pfm")).exitCode, 0);
  EXPECT_GT(meanGreenOf(readImage(path("hall.pfm"))), meanGreenOf(readImage(path("hall-plain.pfm"))));
}

TEST_F(EnvironmentCliTest, TheSkySceneIsTheSameBitsUnderTheThreadDriver) {
  const std::string scene = (kEnvSource / "scenes/sky.scene").string();
  const std::string size = " --width 32 --height 20 --spp 2 -q";
  ASSERT_EQ(run("render " + scene + size + " -o " + path("serial.pfm")).exitCode, 0);
  for (const char* strategy : {"adaptive", "reservoir", "hybrid"}) {
    const std::string out = path(std::string(strategy) + ".pfm");
    const Result r = run("render " + scene + size + " --workers 3 --strategy " + strategy + " -o " + out);
    ASSERT_EQ(r.exitCode, 0) << r.output;
    EXPECT_TRUE(readImage(out) == readImage(path("serial.pfm"))) << strategy;
  }
}

TEST_F(EnvironmentCliTest, BadMapsAreErrorsThatNameTheFileAndWriteNothing) {
  const std::string model = (kEnvSource / "tests/models/blender-cube.glb").string();
  const std::string out = " -q -o " + path("x.png");
  Result r = run("render " + model + " --environment " + path("nowhere.hdr") + out);
  EXPECT_EQ(r.exitCode, 2);
  EXPECT_NE(r.output.find("nowhere.hdr' does not exist"), std::string::npos) << r.output;
  std::ofstream(path("fake.exr")) << "not an EXR";
  r = run("render " + model + " --environment " + path("fake.exr") + out);
  EXPECT_EQ(r.exitCode, 2);
  EXPECT_NE(r.output.find("fake.exr"), std::string::npos) << r.output;
  r = run("render " + model + " --environment-strength 3" + out);
  EXPECT_EQ(r.exitCode, 2);
  EXPECT_NE(r.output.find("--environment FILE"), std::string::npos) << r.output;
  r = run("render " + model + " --environment " + kSkyHdr + " --environment-strength -1" + out);
  EXPECT_NE(r.exitCode, 0);
  std::ofstream(path("bad.scene")) << "image { width 8 height 6 }\n"
                                      "environment { integrator path\n    map \"missing.exr\" }\n";
  r = run("render " + path("bad.scene") + out);
  EXPECT_EQ(r.exitCode, 2);
  EXPECT_NE(r.output.find("bad.scene:3:9"), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("missing.exr' does not exist"), std::string::npos) << r.output;
  EXPECT_FALSE(fs::exists(path("x.png")));
}

}  // namespace
}  // namespace prt
