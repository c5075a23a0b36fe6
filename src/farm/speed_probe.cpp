#include "farm/speed_probe.h"

#include <algorithm>

#include "core/speed_index.h"
#include "farm/throttle.h"

namespace prt {

TaskSet probePixels(uint64_t pixelCount) {
  constexpr uint64_t kShare = 64;  // one pixel in 64
  const uint64_t count =
      std::clamp(pixelCount / kShare, std::min<uint64_t>(pixelCount, kShare), kProbePixels);
  if (count == 0) return {};
  return TaskSet::strided(0, count, pixelCount / count);
}

namespace {

// The least of `repeats` (at least one) measurements.
template <typename Measure>
double fastestOf(int repeats, Measure&& seconds) {
  double fastest = seconds();
  for (int i = 1; i < repeats; ++i) fastest = std::min(fastest, seconds());
  return fastest;
}

}  // namespace

double measureProbeSeconds(const Renderer& renderer, int repeats) {
  Throttle plain;  // k = 1: times the probe, waits for nothing
  return fastestOf(repeats, [&] {
    std::vector<Color> colors;
    return probeSeconds(renderer, 1, [&](const TaskSet& piece) {
      return plain.run([&] { renderTasks(renderer, piece, 1, colors); });
    });
  });
}

double serialSpeedIndexSeconds(SpeedIndexKind kind, const Scene& scene,
                               const RenderSettings& settings) {
  constexpr int kRepeats = 5;
  // The workers' placeholder, or the factor of a machine that is not slowed down.
  if (kind == SpeedIndexKind::None || kind == SpeedIndexKind::Slowdown) return 1.0;
  if (kind == SpeedIndexKind::Hanoi) {
    return fastestOf(kRepeats, [] { return measureSpeedIndexSeconds(kSpeedIndexDiscs, 1); });
  }
  const World world(scene);
  return measureProbeSeconds(Renderer(world, settings), kRepeats);
}

}  // namespace prt
