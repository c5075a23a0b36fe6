#include "drive/speed_probe.h"

#include <algorithm>
#include <chrono>

#include "core/speed_index.h"

namespace prt {

TaskSet probePixels(uint64_t pixelCount) {
  constexpr uint64_t kShare = 64;  // one pixel in 64
  const uint64_t count =
      std::clamp(pixelCount / kShare, std::min<uint64_t>(pixelCount, kShare), kProbePixels);
  if (count == 0) return {};
  return TaskSet::strided(0, count, pixelCount / count);
}

double measureProbeSeconds(const Renderer& renderer, int repeats) {
  std::vector<double> times;
  for (int i = 0; i < std::max(1, repeats); ++i) {
    times.push_back(probeSeconds(renderer, 1, [](auto&& render) {
      const auto start = std::chrono::steady_clock::now();
      render();
      return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    }));
  }
  return *std::min_element(times.begin(), times.end());
}

double serialSpeedIndexSeconds(SpeedIndexKind kind, const Scene& scene,
                               const RenderSettings& settings) {
  constexpr int kRepeats = 5;
  if (kind == SpeedIndexKind::Hanoi) {
    double fastest = measureSpeedIndexSeconds(kSpeedIndexDiscs, 1);
    for (int i = 1; i < kRepeats; ++i) {
      fastest = std::min(fastest, measureSpeedIndexSeconds(kSpeedIndexDiscs, 1));
    }
    return fastest;
  }
  const World world(scene);
  return measureProbeSeconds(Renderer(world, settings), kRepeats);
}

}  // namespace prt
