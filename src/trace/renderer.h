#pragma once
// Renderer: colours pixels. A pixel's value depends only on the scene, the settings and the
// pixel's index — never on the thread, process or order that renders it — because every
// random number is drawn from a counter-based stream keyed by (pixel, sample, path position).
// That is what makes parallel images bit-identical to serial ones.
// Immutable after construction; renderPixel may be called from many threads at once.

#include <atomic>
#include <cstdint>
#include <functional>
#include <memory>
#include <vector>

#include "core/task_set.h"
#include "image/image.h"
#include "trace/camera.h"
#include "trace/path_tracer.h"
#include "trace/shader.h"
#include "trace/view_lists.h"

namespace prt {

class Renderer {
 public:
  Renderer(const World& world, const RenderSettings& settings);

  int width() const { return width_; }
  int height() const { return height_; }
  uint64_t pixelCount() const { return static_cast<uint64_t>(width_) * height_; }
  const RenderSettings& settings() const { return settings_; }

  // The pixel at index y * width + x; adds the rays it traced to `rays`. A sample whose value
  // is not finite (which only the path tracer could give) is left out of the pixel's mean,
  // and counted; a pixel with no finite sample is black.
  Color renderPixel(uint64_t pixelIndex, uint64_t& rays) const;
  // The samples renderPixel found not finite so far, over every thread.
  uint64_t nonFiniteSamples() const { return nonFinite_.load(std::memory_order_relaxed); }
  Integrator integrator() const { return path_ ? Integrator::path : Integrator::hall; }

 private:
  const World& world_;
  RenderSettings settings_;
  int width_, height_;
  PinholeCamera camera_;
  ViewLists view_;
  Shader shader_;
  std::unique_ptr<const PathTracer> path_;  // when the scene asks for the path tracer
  mutable std::atomic<uint64_t> nonFinite_{0};
};

// A tile just rendered, for progress reports: its pixels, the wall seconds its thread spent
// on them, the image so far (only finished tiles' pixels may be read: other threads are
// writing the rest) and the count of pixels finished.
struct TileDone {
  int x0, y0, x1, y1;  // [x0, x1) x [y0, y1)
  double seconds;
  const Image& image;
  uint64_t pixelsDone, pixelsTotal;
};
// Called after each tile; may be called from any rendering thread, but never concurrently
// with itself (calls are ordered after the tiles they report). Returning false stops the
// render: tiles not started are left black (a render stopped by a signal).
using ProgressFn = std::function<bool(const TileDone&)>;

struct RenderStats {
  uint64_t rays = 0;
  double seconds = 0;
};

// Renders the whole image with one parallel-for over 16x16 tiles on `threads` threads
// (<= 0: all cores), taken in an order spread over the image (every part of it is seen
// early, which an estimate of the time left needs; the pixels do not depend on it). With `pixelSeconds`, also records each pixel's wall time in seconds
// (index y * width + x; resized to the pixel count): the per-pixel cost map the simulator
// replays. Timing reads the clock around each pixel and never changes the image.
Image renderImage(const Renderer& renderer, int threads, RenderStats* stats = nullptr,
                  const ProgressFn& progress = {}, std::vector<float>* pixelSeconds = nullptr);

// Renders the given pixels, in parallel over pieces of the set, storing colour i of
// `colors` for task i of `tasks` (colors.size() == tasks.size()). Returns rays traced. With
// `cpuSeconds`, also adds the CPU time every rendering thread spent on them (for a throttle
// that paces a multi-threaded worker); the pieces are small enough to keep `threads` busy.
uint64_t renderTasks(const Renderer& renderer, const TaskSet& tasks, int threads,
                     std::vector<Color>& colors, double* cpuSeconds = nullptr);

}  // namespace prt
