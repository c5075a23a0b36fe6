#include "farm/frame_renderer.h"

#include <chrono>
#include <utility>

#include "core/check.h"
#include "scene/animation.h"

namespace prt {

FrameRenderer::FrameRenderer(Scene scene, const RenderSettings& settings,
                             const FrameSequence& frames)
    : scene_(std::move(scene)),
      settings_(settings),
      frames_(frames),
      pixelsPerFrame_(static_cast<uint64_t>(scene_.image.width) * scene_.image.height) {}

const Renderer& FrameRenderer::frame(uint64_t ordinal) {
  PRT_CHECK(ordinal < frames_.count());
  // A scene that does not move is the same at every frame: built once.
  if (!scene_.animation) ordinal = 0;
  if (ordinal == kept_[0].ordinal) return *kept_[0].renderer;
  std::swap(kept_[0], kept_[1]);
  if (ordinal == kept_[0].ordinal) return *kept_[0].renderer;
  // The one used longest ago goes; the new frame takes the meshes' trees of the last one.
  const auto start = std::chrono::steady_clock::now();
  Kept& made = kept_[0];
  if (made.renderer) nonFiniteOfDropped_ += made.renderer->nonFiniteSamples();
  made.renderer.reset();
  made.world.reset();
  made.world =
      std::make_unique<World>(sceneAt(scene_, frames_.seconds(ordinal)), kept_[1].world.get());
  made.renderer = std::make_unique<Renderer>(*made.world, settings_);
  made.ordinal = ordinal;
  const double seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  if (++framesBuilt_ == 1) firstBuildSeconds_ = seconds;
  buildSeconds_ += seconds;
  return *made.renderer;
}

uint64_t FrameRenderer::render(const TaskSet& tasks, int threads, std::vector<Color>& colors,
                               double* cpuSeconds) {
  if (frames_.count() == 1) return renderTasks(frame(0), tasks, threads, colors, cpuSeconds);
  colors.clear();
  colors.reserve(tasks.size());
  uint64_t rays = 0;
  std::vector<Color> piece;
  forEachFrame(tasks, pixelsPerFrame_, [&](uint64_t ordinal, const TaskSet& pixels) {
    rays += renderTasks(frame(ordinal), pixels, threads, piece, cpuSeconds);
    colors.insert(colors.end(), piece.begin(), piece.end());
  });
  return rays;
}

uint64_t FrameRenderer::nonFiniteSamples() const {
  uint64_t count = nonFiniteOfDropped_;
  for (const Kept& k : kept_) {
    if (k.renderer) count += k.renderer->nonFiniteSamples();
  }
  return count;
}

std::vector<float> asFloats(const std::vector<Color>& colors) {
  std::vector<float> rgb(3 * colors.size());
  for (size_t i = 0; i < colors.size(); ++i) {
    rgb[3 * i] = static_cast<float>(colors[i].x);
    rgb[3 * i + 1] = static_cast<float>(colors[i].y);
    rgb[3 * i + 2] = static_cast<float>(colors[i].z);
  }
  return rgb;
}

}  // namespace prt
