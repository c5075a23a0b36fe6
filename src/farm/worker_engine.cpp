#include "farm/worker_engine.h"

#include <algorithm>

#include "core/check.h"
#include "core/cpu_time.h"
#include "core/parallel.h"
#include "core/machine.h"
#include "core/speed_index.h"
#include "farm/build_info.h"
#include "farm/speed_probe.h"
#include "scene/scene_file.h"

namespace prt {
namespace {

// Solving for D discs is 2^(D-20) solves for 20 discs plus a few moves. Throttling each
// 20-disc stretch on its own interleaves workers that start measuring at the same moment,
// as their rendering interleaves, instead of making them all compete for the cores at once.
constexpr int kStretchDiscs = 20;

void solveHanoiOnce(int discs) {
  volatile uint64_t sink = solveHanoi(discs);  // the work cannot be optimised away
  (void)sink;
}

}  // namespace

void WorkerEngine::load(const SceneMsg& scene) {
  frames_ = std::make_unique<FrameRenderer>(
      parseScene(scene.sceneText, "<scene from master>", unpackAssets(scene.assets)),
      RenderSettings{scene.samplesPerPixel, scene.drtRate}, scene.frames);
  frames_->frame(0);
}

double WorkerEngine::measureSpeedIndex() {
  if (speedIndexKind_ == SpeedIndexKind::None) return 1.0;  // a placeholder, measured nothing
  if (speedIndexKind_ == SpeedIndexKind::Slowdown) return throttle_.slowdown();  // the truth
  if (speedIndexKind_ == SpeedIndexKind::RenderProbe) {
    PRT_CHECK(frames_ != nullptr);
    const Renderer& renderer = frames_->frame(0);  // the probe's pixels are the first frame's
    // As many stretches as the Hanoi run of the default disc count.
    constexpr int kProbePieces = 1 << (kSpeedIndexDiscs - kStretchDiscs);
    std::vector<Color> colors;
    const uint64_t before = frames_->nonFiniteSamples();
    const double seconds = probeSeconds(renderer, kProbePieces, [&](const TaskSet& piece) {
      return throttle_
          .measureParallel(
              [&] {
                double cpu = 0;
                renderTasks(renderer, piece, threads_, colors, &cpu);
                return cpu;
              },
              threads_)
          .emulatedSeconds;
    });
    nonFiniteOfProbe_ += frames_->nonFiniteSamples() - before;
    return seconds;
  }
  const int discs = std::min(speedIndexDiscs_, kStretchDiscs);
  const uint64_t stretches = 1ull << std::max(0, speedIndexDiscs_ - kStretchDiscs);
  double seconds = 0;
  for (uint64_t i = 0; i < stretches; ++i) {
    if (threads_ == 1) {
      seconds += throttle_.measure([discs] { solveHanoiOnce(discs); }).emulatedSeconds;
      continue;
    }
    // One puzzle per thread at once: the machine's time per puzzle is the stretch over N.
    seconds += throttle_
                   .measureParallel(
                       [&] {
                         std::vector<double> cpu(static_cast<size_t>(threads_), 0.0);
                         parallelFor(static_cast<uint64_t>(threads_), threads_, [&](uint64_t t) {
                           const double start = threadCpuSeconds();
                           solveHanoiOnce(discs);
                           cpu[t] = threadCpuSeconds() - start;
                         });
                         double total = 0;
                         for (double c : cpu) total += c;
                         return total;
                       },
                       threads_)
                   .emulatedSeconds /
               threads_;
  }
  return seconds;
}

WorkerIdentity WorkerEngine::identity() const { return {buildDescription(), hostName()}; }

std::vector<float> WorkerEngine::render(const TaskSet& batch, double& seconds, uint64_t& rays,
                                       const std::function<void()>& between) {
  PRT_CHECK(frames_ != nullptr);
  std::vector<Color> colors;
  if (threads_ == 1 && between) {
    // Pieces of a few pixels, `between` after each: a heartbeat is never more than a few
    // pixels late, and no thread hand-off costs a batch its wake-up latency.
    constexpr uint64_t kPiece = 16;
    // The throttle's wait after the batch calls `between` too.
    seconds = throttle_.run(
        [&] {
          colors.reserve(batch.size());
          TaskSet left = batch;
          std::vector<Color> piece;
          while (!left.empty()) {
            rays += frames_->render(left.takeFront(kPiece), 1, piece);
            colors.insert(colors.end(), piece.begin(), piece.end());
            if (!left.empty()) between();
          }
        },
        between);
  } else if (threads_ == 1) {
    seconds = throttle_.run([&] { rays += frames_->render(batch, 1, colors); });
  } else {
    seconds = throttle_
                  .measureParallel(
                      [&] {
                        double cpu = 0;
                        rays += frames_->render(batch, threads_, colors, &cpu);
                        return cpu;
                      },
                      threads_, between)
                  .wallSeconds;
  }
  return asFloats(colors);
}

}  // namespace prt
