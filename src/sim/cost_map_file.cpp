#include "sim/cost_map_file.h"

#include <bit>
#include <cerrno>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <memory>
#include <vector>

#include "core/input_error.h"
#include "core/input_file.h"
#include "image/atomic_file.h"

namespace prt {
namespace {

static_assert(std::endian::native == std::endian::little, "the format is little-endian");

constexpr char kMagic[8] = {'P', 'R', 'T', 'C', 'O', 'S', 'T', '1'};
constexpr uint64_t kHeaderBytes = 16;
constexpr uint64_t kMaxPixels = 1ull << 28;

struct FileCloser {
  void operator()(std::FILE* f) const { std::fclose(f); }
};

[[noreturn]] void fail(const std::string& path, const std::string& why) {
  throw InputError("cost map '" + path + "': " + why);
}

}  // namespace

CostMap readCostMapFile(const std::string& path) {
  checkInputFile(path, "cost map");
  std::unique_ptr<std::FILE, FileCloser> file(std::fopen(path.c_str(), "rb"));
  if (!file) fail(path, std::string("cannot open: ") + std::strerror(errno));
  unsigned char header[kHeaderBytes];
  if (std::fread(header, 1, kHeaderBytes, file.get()) != kHeaderBytes ||
      std::memcmp(header, kMagic, sizeof kMagic) != 0) {
    fail(path,
         "not a cost map (expected the magic \"PRTCOST1\"; write one with "
         "prt render SCENE --cost-map FILE)");
  }
  uint32_t width = 0;
  uint32_t height = 0;
  std::memcpy(&width, header + 8, 4);
  std::memcpy(&height, header + 12, 4);
  const uint64_t pixels = static_cast<uint64_t>(width) * height;
  if (width == 0 || height == 0 || pixels > kMaxPixels) {
    fail(path, "bad size " + std::to_string(width) + "x" + std::to_string(height) +
                   " (each side >= 1, at most 2^28 pixels)");
  }
  std::vector<float> seconds(pixels);
  const size_t got = std::fread(seconds.data(), sizeof(float), pixels, file.get());
  if (got != pixels) {
    fail(path, "truncated: a " + std::to_string(width) + "x" + std::to_string(height) +
                   " map needs " + std::to_string(pixels) + " costs, the file holds " +
                   std::to_string(got));
  }
  if (std::fgetc(file.get()) != EOF) {
    fail(path, "trailing bytes after the " + std::to_string(pixels) + " costs");
  }
  double total = 0;
  for (uint64_t i = 0; i < pixels; ++i) {
    if (!std::isfinite(seconds[i]) || seconds[i] < 0) {
      fail(path, "pixel " + std::to_string(i) + " has an invalid cost " +
                     std::to_string(seconds[i]) + " (costs are finite seconds >= 0)");
    }
    total += seconds[i];
  }
  if (!(total > 0)) fail(path, "every cost is zero");
  return CostMap(static_cast<int>(width), static_cast<int>(height), std::move(seconds));
}

void writeCostMapFile(const std::string& path, const CostMap& map) {
  writeFileAtomically(path, [&](std::FILE* f) {
    const auto width = static_cast<uint32_t>(map.width());
    const auto height = static_cast<uint32_t>(map.height());
    std::fwrite(kMagic, 1, sizeof kMagic, f);
    std::fwrite(&width, 4, 1, f);
    std::fwrite(&height, 4, 1, f);
    std::fwrite(map.secondsPerPixel().data(), sizeof(float), map.pixelCount(), f);
  });
}

}  // namespace prt
