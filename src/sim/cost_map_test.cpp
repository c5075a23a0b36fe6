// Cost maps: range queries against brute force, the file format and its errors, and the
// synthetic complex-scene shape.

#include "sim/cost_map.h"

#include <gtest/gtest.h>

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <random>
#include <string>

#include "core/input_error.h"
#include "sim/cost_map_file.h"
#include "sim/synthetic_cost.h"

namespace prt {
namespace {

CostMap randomMap(int width, int height, uint32_t seed) {
  std::mt19937 rng(seed);
  std::vector<float> seconds(static_cast<size_t>(width) * static_cast<size_t>(height));
  for (float& s : seconds) s = static_cast<float>(rng() % 1000) * 1e-6f;
  return CostMap(width, height, std::move(seconds));
}

double bruteForce(const CostMap& map, const TaskRun& run) {
  double sum = 0;
  for (uint64_t i = 0; i < run.count; ++i) sum += map.pixelSeconds(run.at(i));
  return sum;
}

std::string costMapTempPath(const std::string& name) {
  return (std::filesystem::temp_directory_path() /
          ("prt-costmap-" + std::to_string(::testing::UnitTest::GetInstance()->random_seed()) +
           "-" + name))
      .string();
}

void writeBytes(const std::string& path, const std::string& bytes) {
  std::ofstream(path, std::ios::binary) << bytes;
}

// Expects readCostMapFile(path) to throw InputError whose message contains `what`.
void expectReadError(const std::string& path, const std::string& what) {
  try {
    readCostMapFile(path);
    ADD_FAILURE() << "no error for " << path;
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find(what), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find(path), std::string::npos) << e.what();
  }
}

std::string header(uint32_t width, uint32_t height) {
  std::string h = "PRTCOST1";
  h.append(reinterpret_cast<const char*>(&width), 4);
  h.append(reinterpret_cast<const char*>(&height), 4);
  return h;
}

TEST(CostMapTest, RangeQueriesMatchBruteForce) {
  const CostMap map = randomMap(37, 23, 7);
  std::mt19937 rng(11);
  for (int i = 0; i < 2000; ++i) {
    TaskRun run;
    run.stride = (i % 3 == 0) ? 1 : 1 + rng() % 50;
    run.first = rng() % map.pixelCount();
    const uint64_t room = (map.pixelCount() - 1 - run.first) / run.stride + 1;
    run.count = rng() % (room + 1);
    EXPECT_NEAR(map.seconds(run), bruteForce(map, run), 1e-12) << i;
  }
  EXPECT_NEAR(map.seconds(TaskSet::range(0, map.pixelCount())), map.totalSeconds(), 1e-12);
  TaskSet scatterShare = TaskSet::strided(3, map.pixelCount() / 4, 4);
  scatterShare.append(TaskRun{0, 2, 1});
  EXPECT_NEAR(map.seconds(scatterShare),
              bruteForce(map, scatterShare.runs()[0]) + bruteForce(map, scatterShare.runs()[1]),
              1e-12);
}

TEST(CostMapTest, ScaledToKeepsTheShape) {
  const CostMap map = randomMap(10, 10, 3);
  const CostMap scaled = map.scaledTo(60);
  EXPECT_NEAR(scaled.totalSeconds(), 60, 1e-6);
  EXPECT_NEAR(scaled.pixelSeconds(17) / scaled.pixelSeconds(42),
              map.pixelSeconds(17) / map.pixelSeconds(42), 1e-5);
}

TEST(CostMapTest, FileRoundTrip) {
  const std::string path = costMapTempPath("roundtrip.cost");
  const CostMap map = randomMap(13, 5, 5);
  writeCostMapFile(path, map);
  EXPECT_EQ(std::filesystem::file_size(path), 16u + 4u * 13 * 5);
  const CostMap back = readCostMapFile(path);
  EXPECT_EQ(back.width(), 13);
  EXPECT_EQ(back.height(), 5);
  EXPECT_EQ(back.secondsPerPixel(), map.secondsPerPixel());
  std::filesystem::remove(path);
}

TEST(CostMapTest, FileErrorsNameTheFileAndTheProblem) {
  expectReadError(costMapTempPath("does-not-exist.cost"), "does not exist");

  const std::string path = costMapTempPath("bad.cost");
  writeBytes(path, "P6\n2 2\n255\n");
  expectReadError(path, "not a cost map");

  const float one = 1e-3f, negative = -1.0f;
  const std::string cost(reinterpret_cast<const char*>(&one), 4);
  writeBytes(path, header(2, 2) + cost + cost + cost);
  expectReadError(path, "truncated");
  writeBytes(path, header(2, 2) + cost + cost + cost + cost + "x");
  expectReadError(path, "trailing bytes");
  writeBytes(path, header(0, 2));
  expectReadError(path, "bad size");
  writeBytes(path, header(1, 2) + cost + std::string(reinterpret_cast<const char*>(&negative), 4));
  expectReadError(path, "invalid cost");
  const float zero = 0;
  writeBytes(path, header(1, 1) + std::string(reinterpret_cast<const char*>(&zero), 4));
  expectReadError(path, "every cost is zero");
  std::filesystem::remove(path);
}

TEST(CostMapTest, SyntheticComplexSceneHasItsShapeAtAnySize) {
  for (const auto& [w, h] : {std::pair{640, 480}, std::pair{384, 216}, std::pair{7, 5}}) {
    const CostMap map = complexSceneCostMap(w, h, 60);
    EXPECT_NEAR(map.totalSeconds(), 60, 1e-4) << w << "x" << h;
  }
  const CostMap map = complexSceneCostMap(384, 216, 60);
  // Total cost of the region [u0, u1) x [v0, v1) in normalised image coordinates.
  auto total = [&](double u0, double u1, double v0, double v1) {
    const auto x0 = static_cast<uint64_t>(u0 * 384), x1 = static_cast<uint64_t>(u1 * 384);
    const auto y0 = static_cast<uint64_t>(v0 * 216), y1 = static_cast<uint64_t>(v1 * 216);
    double sum = 0;
    for (uint64_t y = y0; y < y1; ++y) sum += map.seconds(TaskRun{y * 384 + x0, x1 - x0, 1});
    return sum;
  };
  auto mean = [&](double u0, double u1, double v0, double v1) {
    return total(u0, u1, v0, v1) / ((u1 - u0) * 384 * (v1 - v0) * 216);
  };
  const double sky = mean(0, 1, 0, 0.15);
  const double floor = mean(0, 0.3, 0.7, 1);
  const double cluster = mean(0.45, 0.75, 0.42, 0.56);
  EXPECT_GT(floor, 3 * sky);
  EXPECT_GT(cluster, 10 * floor);
  EXPECT_GT(total(0.5, 1, 0, 1), 2 * total(0, 0.5, 0, 1));  // expensive right of centre
  EXPECT_GT(total(0.35, 0.92, 0.24, 0.7), 0.78 * 60);       // the cluster holds about 80 %
}

TEST(CostMapTest, UniformMap) {
  const CostMap map = uniformCostMap(4, 3, 6);
  EXPECT_NEAR(map.totalSeconds(), 6, 1e-6);
  EXPECT_NEAR(map.pixelSeconds(5), 0.5, 1e-7);
}

}  // namespace
}  // namespace prt
