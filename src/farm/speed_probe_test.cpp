#include "farm/speed_probe.h"

#include <gtest/gtest.h>

#include "core/input_error.h"

namespace prt {
namespace {

TEST(SpeedProbe, TinyImagesProbeEveryPixel) {
  EXPECT_EQ(probePixels(50), TaskSet::range(0, 50));
  EXPECT_EQ(probePixels(64), TaskSet::range(0, 64));
}

TEST(SpeedProbe, MidSizeImagesProbeOnePixelInSixtyFour) {
  const TaskSet probe = probePixels(160 * 120);
  EXPECT_EQ(probe.size(), 160u * 120 / 64);
  EXPECT_EQ(probe.at(1), 64u);
  EXPECT_EQ(probePixels(100).size(), 64u);
}

TEST(SpeedProbe, LargeImagesProbeAnEvenSpreadOfPixels) {
  const uint64_t pixels = 640 * 480;
  const TaskSet probe = probePixels(pixels);
  EXPECT_EQ(probe.size(), kProbePixels);
  EXPECT_EQ(probe.at(0), 0u);
  EXPECT_EQ(probe.at(1), pixels / kProbePixels);
  EXPECT_LT(probe.at(kProbePixels - 1), pixels);
  // The spread reaches the last rows, not just the top of the image.
  EXPECT_GT(probe.at(kProbePixels - 1), pixels - 2 * (pixels / kProbePixels));
}

TEST(SpeedProbe, RendersTheProbeInTheRequestedPieces) {
  Scene scene;
  scene.image.width = 8;
  scene.image.height = 6;
  scene.objects.push_back({SphereShape{{0, 0, 0}, 1}, Material{}});
  const World world(scene);
  const Renderer renderer(world, RenderSettings{});
  int pieces = 0;
  uint64_t pixels = 0;
  const double seconds = probeSeconds(renderer, 5, [&](const TaskSet& piece) {
    ++pieces;
    pixels += piece.size();
    return 0.25;
  });
  EXPECT_EQ(pieces, 5);
  EXPECT_EQ(pixels, probePixels(renderer.pixelCount()).size());
  EXPECT_DOUBLE_EQ(seconds, 1.25);
  EXPECT_GT(measureProbeSeconds(renderer, 1), 0.0);
}

TEST(SpeedIndexKind, NamesRoundTripAndUnknownNamesListTheValidOnes) {
  for (const std::string& name : speedIndexKindNames()) {
    EXPECT_EQ(speedIndexKindName(parseSpeedIndexKind(name)), name);
  }
  try {
    parseSpeedIndexKind("dhrystone");
    FAIL();
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("hanoi, probe"), std::string::npos);
  }
}

}  // namespace
}  // namespace prt
