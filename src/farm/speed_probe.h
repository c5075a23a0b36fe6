#pragma once
// The ray-tracing probe speed index. The paper's is the Towers of Hanoi time (core/speed_index.h):
// cheap, and independent of the scene, but a recursion benchmark only approximates how fast a
// machine ray-traces. The alternative the paper checks it against (its Fig. 17) is a ray-tracing
// probe: the time to render a fixed sample of the image itself, with the run's own scene and
// settings. Both are times: lower is faster.
//
// The probe renders every k-th pixel in scan-line order, so it samples the whole image (sky,
// floor, glass): one pixel in 64, at least 64 (or all of a smaller image) and at most
// kProbePixels. It costs at most 1/64 of a serial render (1.3 % at 640x480), whatever
// the test case.
// Reads the clock: call it from drivers, never from strategies.

#include <cstdint>
#include <vector>

#include "core/task_set.h"
#include "farm/speed_index_kind.h"
#include "trace/renderer.h"

namespace prt {

inline constexpr uint64_t kProbePixels = 4096;

// The probe's pixels, evenly strided from pixel 0: pixelCount / 64 of them, clamped to
// [min(pixelCount, 64), kProbePixels].
TaskSet probePixels(uint64_t pixelCount);

// Renders the probe in `pieces` equal parts one after the other, calling renderPiece(part)
// for each; it renders the part and returns its seconds (through a Throttle, for a worker).
// Returns the total. The split lets a throttled worker's waits interleave with other workers'
// computing, as its rendering does.
template <typename RenderPiece>
double probeSeconds(const Renderer& renderer, int pieces, RenderPiece&& renderPiece) {
  TaskSet remaining = probePixels(renderer.pixelCount());
  const uint64_t perPiece = (remaining.size() + pieces - 1) / static_cast<uint64_t>(pieces);
  double seconds = 0;
  while (!remaining.empty()) seconds += renderPiece(remaining.takeFront(perPiece));
  return seconds;
}

// The serial machine's probe time: the fastest of `repeats` unthrottled runs on this thread.
double measureProbeSeconds(const Renderer& renderer, int repeats = 5);

// The serial machine's speed index of the given kind (the master's, for MASU), measured on
// this thread without a slowdown: the fastest of five runs. Other load on a shared machine
// only ever lengthens a run, so the fastest is the best estimate of the machine's own speed;
// a median of three still moved by a fifth between runs on a busy two-core machine.
double serialSpeedIndexSeconds(SpeedIndexKind kind, const Scene& scene,
                               const RenderSettings& settings);

}  // namespace prt
