#include "report/ownership_map.h"

#include <gtest/gtest.h>

namespace prt {
namespace {

TEST(OwnershipMap, RoundTripsExactly) {
  const int w = 37, h = 23;
  std::vector<int32_t> owner(static_cast<size_t>(w * h));
  for (size_t p = 0; p < owner.size(); ++p) owner[p] = static_cast<int32_t>((p / 5) % 300) - 1;
  const nlohmann::json map = ownershipJson(owner, w, h);
  EXPECT_EQ(map["width"], w);
  EXPECT_EQ(map["height"], h);
  EXPECT_EQ(map["step"], 1);
  EXPECT_EQ(decodeOwnership(map), owner);
}

TEST(OwnershipMap, BlocksAreSmall) {
  const int w = 640, h = 480;
  std::vector<int32_t> owner(static_cast<size_t>(w * h));
  for (size_t p = 0; p < owner.size(); ++p) owner[p] = static_cast<int32_t>(p * 4 / owner.size());
  const nlohmann::json map = ownershipJson(owner, w, h);
  EXPECT_LT(map["data"].get<std::string>().size(), 64u);  // four runs
  EXPECT_EQ(decodeOwnership(map), owner);
}

TEST(OwnershipMap, LargeMapsAreSampledKeepingOwnersExact) {
  const int w = 3840, h = 2160;
  std::vector<int32_t> owner(static_cast<size_t>(w) * h);
  for (int y = 0; y < h; ++y) {
    for (int x = 0; x < w; ++x) owner[static_cast<size_t>(y) * w + x] = (x / 7 + y / 3) % 1024;
  }
  const nlohmann::json map = ownershipJson(owner, w, h, 800);
  const int step = map["step"];
  EXPECT_EQ(step, 5);
  EXPECT_EQ(map["width"], 768);
  EXPECT_EQ(map["height"], 432);
  const std::vector<int32_t> samples = decodeOwnership(map);
  for (int y = 0; y < 432; y += 37) {
    for (int x = 0; x < 768; x += 41) {
      EXPECT_EQ(samples[static_cast<size_t>(y) * 768 + x],
                owner[static_cast<size_t>(y * step) * w + x * step]);
    }
  }
}

TEST(OwnershipMap, MalformedMapsAreRejected) {
  nlohmann::json map = ownershipJson({0, 0, 1, 1}, 2, 2);
  nlohmann::json truncated = map;
  truncated["height"] = 3;  // runs no longer fill it
  EXPECT_THROW(decodeOwnership(truncated), std::invalid_argument);
  nlohmann::json bad = map;
  bad["data"] = "!!!";
  EXPECT_THROW(decodeOwnership(bad), std::invalid_argument);
  EXPECT_THROW(decodeOwnership(nlohmann::json::object()), std::invalid_argument);
}

}  // namespace
}  // namespace prt
