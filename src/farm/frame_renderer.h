#pragma once
// FrameRenderer: renders tasks of a frame sequence (core/frame_sequence.h) — pixel p of the
// i-th frame is task i * pixelsPerFrame + p — from the scene as read once. The scene of a
// frame is evaluated at that frame's time (scene/animation.h sceneAt) when a task of it is
// first asked for; what that costs is the top of the tree, the lights' shadow shafts and the
// camera's view lists: the meshes' trees are taken from the frame before, as meshes move but
// keep their shape. The two frames used last are kept (tasks come mostly in order, and a spot
// check of another worker's pixels is mostly of the frame before the one being rendered: one
// frame kept would be built again for every check). A still is a sequence of one frame, which
// is built once.
// Not thread-safe itself (one per worker); render() renders on many threads.

#include <array>
#include <cstdint>
#include <memory>
#include <vector>

#include "core/frame_sequence.h"
#include "core/task_set.h"
#include "trace/renderer.h"
#include "trace/scene.h"

namespace prt {

class FrameRenderer {
 public:
  FrameRenderer(Scene scene, const RenderSettings& settings, const FrameSequence& frames);

  uint64_t pixelsPerFrame() const { return pixelsPerFrame_; }
  uint64_t taskCount() const { return pixelsPerFrame_ * frames_.count(); }
  const FrameSequence& frames() const { return frames_; }

  // The renderer of the ordinal-th frame (built if it is not one of those kept).
  const Renderer& frame(uint64_t ordinal);
  const World& world(uint64_t ordinal) {
    frame(ordinal);
    return *kept_[0].world;
  }

  // Renders tasks (each below taskCount()) on `threads` threads into colors (one per task, in
  // order), splitting them at frame boundaries; returns the rays traced. `cpuSeconds` as for
  // renderTasks.
  uint64_t render(const TaskSet& tasks, int threads, std::vector<Color>& colors,
                  double* cpuSeconds = nullptr);

  // What preparing frames has cost: how many were built and their seconds in all, and the
  // first build's seconds (it builds the meshes' trees, which later frames keep).
  uint64_t framesBuilt() const { return framesBuilt_; }
  double buildSeconds() const { return buildSeconds_; }
  double firstBuildSeconds() const { return firstBuildSeconds_; }
  // The samples found not finite so far (Renderer::nonFiniteSamples), over every frame.
  uint64_t nonFiniteSamples() const;

  // The tasks of `tasks` that fall in each frame, as pixel indices of that frame, in order:
  // calls f(ordinal, pixels) for each frame met (a frame may be met again after another).
  template <typename F>
  static void forEachFrame(const TaskSet& tasks, uint64_t pixelsPerFrame, F&& f);

 private:
  Scene scene_;
  RenderSettings settings_;
  FrameSequence frames_;
  uint64_t pixelsPerFrame_;
  struct Kept {
    uint64_t ordinal = UINT64_MAX;
    std::unique_ptr<World> world;
    std::unique_ptr<Renderer> renderer;
  };
  std::array<Kept, 2> kept_;  // the frame used last first
  uint64_t framesBuilt_ = 0;
  double buildSeconds_ = 0;
  double firstBuildSeconds_ = 0;
  uint64_t nonFiniteOfDropped_ = 0;  // of the frames' renderers no longer kept
};

// Colours as the protocol carries them: 3 floats each, in order.
std::vector<float> asFloats(const std::vector<Color>& colors);

template <typename F>
void FrameRenderer::forEachFrame(const TaskSet& tasks, uint64_t pixelsPerFrame, F&& f) {
  uint64_t frame = UINT64_MAX;
  TaskSet pixels;
  for (const TaskRun& run : tasks.runs()) {
    TaskRun left = run;
    while (left.count > 0) {
      const uint64_t ordinal = left.first / pixelsPerFrame;
      const uint64_t offset = ordinal * pixelsPerFrame;
      const uint64_t end = offset + pixelsPerFrame;  // the frame's tasks end here
      // How many of the run's tasks fall before `end`.
      const uint64_t inFrame =
          left.stride == 0 ? left.count
                           : std::min(left.count, (end - 1 - left.first) / left.stride + 1);
      if (ordinal != frame && !pixels.empty()) {
        f(frame, pixels);
        pixels = TaskSet();
      }
      frame = ordinal;
      pixels.append(TaskRun{left.first - offset, inFrame, left.stride});
      left.first += inFrame * left.stride;
      left.count -= inFrame;
    }
  }
  if (!pixels.empty()) f(frame, pixels);
}

}  // namespace prt
