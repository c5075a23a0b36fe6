// Golden images: small renders of every example scene compared with committed references.
// Tolerance: PSNR >= 50 dB and no pixel off by more than 2/255 in 8-bit sRGB. Renders are
// deterministic, so on the machine that made the references they match exactly; the tolerance
// absorbs last-bit differences of another libm or compiler, while any real change in shading
// (a wrong term, a missing shadow) costs far more than that.
// Set PRT_UPDATE_GOLDEN=1 to rewrite the references after an intended change.

#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iterator>

#include "image/image_compare.h"
#include "image/image_io.h"
#include "scene/scene_file.h"
#include "trace/renderer.h"

namespace prt {
namespace {

namespace fs = std::filesystem;

constexpr int kWidth = 64;
constexpr int kHeight = 48;
constexpr int kSamples = 2;

std::vector<std::string> exampleScenes() {
  std::vector<std::string> names;
  for (const auto& entry : fs::directory_iterator(fs::path(PRT_SOURCE_DIR) / "scenes")) {
    if (entry.path().extension() == ".scene") names.push_back(entry.path().stem().string());
  }
  std::sort(names.begin(), names.end());
  return names;
}

class GoldenImageTest : public ::testing::TestWithParam<std::string> {};

// Whether the scene uses the one example model not in the repository (scripts/fetch-bunny.sh
// fetches it) and it is absent.
bool bunnyMissing(const std::string& scene) {
  const fs::path scenes = fs::path(PRT_SOURCE_DIR) / "scenes";
  std::ifstream in(scenes / (scene + ".scene"));
  const std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  return text.find("models/bunny.ply") != std::string::npos &&
         !fs::exists(scenes / "models" / "bunny.ply");
}

TEST_P(GoldenImageTest, MatchesReference) {
  const fs::path source(PRT_SOURCE_DIR);
  if (bunnyMissing(GetParam())) GTEST_SKIP() << "no bunny model: run scripts/fetch-bunny.sh";
  Scene scene = loadSceneFile((source / "scenes" / (GetParam() + ".scene")).string());
  scene.image.width = kWidth;
  scene.image.height = kHeight;
  const World world(scene);
  const Image image = renderImage(Renderer(world, RenderSettings{kSamples, 1}), 0);
  const fs::path golden = source / "tests" / "golden" / (GetParam() + ".png");
  if (std::getenv("PRT_UPDATE_GOLDEN") != nullptr) {
    writeImage(image, golden.string());
    GTEST_SKIP() << "rewrote " << golden;
  }
  ASSERT_TRUE(fs::exists(golden)) << golden << " is missing; run with PRT_UPDATE_GOLDEN=1";
  const Image reference = readImage(golden.string());
  ASSERT_EQ(reference.width(), kWidth);
  const double decibels = psnr(image, reference);
  EXPECT_GE(decibels, 50.0) << GetParam();
  EXPECT_EQ(differingPixelFraction(image, reference, 2), 0.0) << GetParam();
}

INSTANTIATE_TEST_SUITE_P(ExampleScenes, GoldenImageTest, ::testing::ValuesIn(exampleScenes()),
                         [](const auto& param) {
                           std::string name = param.param;
                           for (char& c : name) {
                             if (!std::isalnum(static_cast<unsigned char>(c))) c = '_';
                           }
                           return name;
                         });

}  // namespace
}  // namespace prt
