#include "trace/renderer.h"

#include <algorithm>
#include <chrono>
#include <ctime>
#include <mutex>
#include <numeric>
#include <vector>

#include "core/cpu_allocation.h"
#include "core/cpu_time.h"
#include "core/parallel.h"
#include "trace/sampling.h"

namespace prt {

Renderer::Renderer(const World& world, const RenderSettings& settings)
    : world_(world),
      settings_(settings),
      width_(world.scene().image.width),
      height_(world.scene().image.height),
      camera_(world.scene().camera, width_, height_),
      view_(camera_, width_, height_, world.itemBounds()),
      shader_(world, settings) {
  if (world.scene().environment.integrator == Integrator::path) {
    path_ = std::make_unique<const PathTracer>(world);
  }
}

Color Renderer::renderPixel(uint64_t pixelIndex, uint64_t& rays) const {
  const int x = static_cast<int>(pixelIndex % static_cast<uint64_t>(width_));
  const int y = static_cast<int>(pixelIndex / static_cast<uint64_t>(width_));
  const int n = settings_.samplesPerPixel;
  const auto candidates = view_.candidates(x, y);
  const SampleGrid grid(n);
  Color sum;
  int finite = n;  // samples averaged: those whose value is finite
  for (int s = 0; s < n; ++s) {
    Rng rng = Rng::forSample(pixelIndex, static_cast<uint32_t>(s));
    double dx = 0.5, dy = 0.5;  // one sample looks through the pixel centre
    if (n > 1) {
      const double jx = rng.uniform();
      const double jy = rng.uniform();
      stratifiedSample(s, grid, jx, jy, dx, dy);
    }
    const Ray ray = camera_.generateRay(x + dx, y + dy);
    if (path_) {
      const Color c = path_->radiance(ray, candidates ? &*candidates : nullptr, rng.child(1), rays);
      if (isFinite(c)) {
        sum += c;
      } else {
        --finite;
        nonFinite_.fetch_add(1, std::memory_order_relaxed);
      }
      continue;
    }
    sum += candidates ? shader_.traceAmong(*candidates, ray, rng.child(1), rays)
                      : shader_.trace(ray, 0, rng.child(1), rays);
  }
  return finite > 0 ? meanOf(sum, finite) : Color();
}

namespace {
constexpr int kTileSize = 16;

// --- per-pixel cost recording (renderImage's pixelSeconds) ---------------------------------

// A pixel's wall time includes any time its thread was preempted: on a busy machine, spikes
// of milliseconds on a few pixels that would dwarf the real costs. Reading the thread's CPU
// time around every pixel costs more than a cheap pixel, but once per tile it bounds the
// tile's true total: whatever the pixel times exceed it by is taken off the largest times,
// where the preemptions landed, never below the tile's median.
void removePreemption(std::vector<float>& times, double cpuSeconds) {
  double excess = -cpuSeconds;
  for (float t : times) excess += t;
  if (excess <= 0) return;
  std::vector<float> sorted = times;
  std::sort(sorted.begin(), sorted.end());
  const float median = sorted[sorted.size() / 2];
  std::vector<size_t> order(times.size());
  for (size_t i = 0; i < order.size(); ++i) order[i] = i;
  std::sort(order.begin(), order.end(), [&](size_t a, size_t b) { return times[a] > times[b]; });
  for (size_t i : order) {
    const double cut = std::min(excess, static_cast<double>(times[i] - median));
    if (cut <= 0) break;
    times[i] = static_cast<float>(times[i] - cut);
    excess -= cut;
  }
}

// Renders the tile [x0, x1) x [y0, y1) and records each pixel's seconds in `pixelSeconds`.
void renderTileTimed(const Renderer& renderer, Image& image, int x0, int y0, int x1, int y1,
                     uint64_t& rays, std::vector<float>& pixelSeconds) {
  const auto w = static_cast<uint64_t>(renderer.width());
  std::vector<float> times;
  const double cpu0 = threadCpuSeconds();
  for (int y = y0; y < y1; ++y) {
    for (int x = x0; x < x1; ++x) {
      const uint64_t index = static_cast<uint64_t>(y) * w + static_cast<uint64_t>(x);
      const auto t0 = std::chrono::steady_clock::now();
      image.set(index, renderer.renderPixel(index, rays));
      times.push_back(std::chrono::duration<float>(std::chrono::steady_clock::now() - t0).count());
    }
  }
  removePreemption(times, threadCpuSeconds() - cpu0);
  size_t i = 0;
  for (int y = y0; y < y1; ++y) {
    for (int x = x0; x < x1; ++x) {
      pixelSeconds[static_cast<uint64_t>(y) * w + static_cast<uint64_t>(x)] = times[i++];
    }
  }
}
// --- end per-pixel cost recording ------------------------------------------------------------

// A step coprime with `count` near count times the golden ratio's fraction: tile i * step mod
// count visits every tile once, each next one far from the last, so the first tiles of a
// render sample the whole image.
uint64_t spreadingStep(uint64_t count) {
  if (count < 3) return 1;
  uint64_t step = static_cast<uint64_t>(0.6180339887498949 * static_cast<double>(count));
  step = std::max<uint64_t>(step, 1);
  while (std::gcd(step, count) != 1) ++step;
  return step;
}
}  // namespace

Image renderImage(const Renderer& renderer, int threads, RenderStats* stats,
                  const ProgressFn& progress, std::vector<float>* pixelSeconds) {
  const auto start = std::chrono::steady_clock::now();
  const int w = renderer.width(), h = renderer.height();
  Image image(w, h);
  const int tilesX = (w + kTileSize - 1) / kTileSize;
  const int tilesY = (h + kTileSize - 1) / kTileSize;
  std::atomic<uint64_t> rays{0};
  std::mutex progressMutex;
  uint64_t done = 0;
  if (pixelSeconds) pixelSeconds->assign(renderer.pixelCount(), 0.0f);
  const uint64_t tileCount = static_cast<uint64_t>(tilesX) * static_cast<uint64_t>(tilesY);
  const uint64_t step = spreadingStep(tileCount);
  std::atomic<bool> stopped{false};
  parallelFor(tileCount, threads, [&](uint64_t i) {
    if (stopped.load(std::memory_order_relaxed)) return;
    const uint64_t tile = (i * step) % tileCount;
    const auto tileStart = std::chrono::steady_clock::now();
    const int tx = static_cast<int>(tile % static_cast<uint64_t>(tilesX)) * kTileSize;
    const int ty = static_cast<int>(tile / static_cast<uint64_t>(tilesX)) * kTileSize;
    uint64_t tileRays = 0;
    const int x1 = std::min(w, tx + kTileSize), y1 = std::min(h, ty + kTileSize);
    if (pixelSeconds) {
      renderTileTimed(renderer, image, tx, ty, x1, y1, tileRays, *pixelSeconds);
    } else {
      for (int y = ty; y < y1; ++y) {
        for (int x = tx; x < x1; ++x) {
          const uint64_t index = static_cast<uint64_t>(y) * w + x;
          image.set(index, renderer.renderPixel(index, tileRays));
        }
      }
    }
    rays += tileRays;
    if (progress) {
      const double seconds =
          std::chrono::duration<double>(std::chrono::steady_clock::now() - tileStart).count();
      std::lock_guard lock(progressMutex);
      done += static_cast<uint64_t>(x1 - tx) * (y1 - ty);
      if (!progress(TileDone{tx, ty, x1, y1, seconds, image, done, renderer.pixelCount()})) {
        stopped.store(true, std::memory_order_relaxed);
      }
    }
  });
  if (stats) {
    stats->rays = rays.load();
    stats->seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  }
  return image;
}

uint64_t renderTasks(const Renderer& renderer, const TaskSet& tasks, int threads,
                     std::vector<Color>& colors, double* cpuSeconds) {
  colors.resize(tasks.size());
  // About four pieces per thread, between 8 and 256 pixels: enough to even out pixels of
  // different cost, few enough that a piece is more work than taking it.
  const uint64_t threadCount = static_cast<uint64_t>(threads <= 0 ? allocatedCpuCount() : threads);
  const uint64_t piece =
      std::clamp<uint64_t>((tasks.size() + 4 * threadCount - 1) / (4 * threadCount), 8, 256);
  const uint64_t pieces = (tasks.size() + piece - 1) / piece;
  std::atomic<uint64_t> rays{0};
  std::vector<double> pieceCpu(cpuSeconds != nullptr ? pieces : 0, 0.0);
  // Flatten once so pieces can be addressed by position; a task set here is at most a
  // worker's batch, not the whole image of a huge render.
  const std::vector<uint64_t> pixels = tasks.toVector();
  parallelFor(pieces, threads, [&](uint64_t p) {
    const double cpuStart = cpuSeconds != nullptr ? threadCpuSeconds() : 0.0;
    uint64_t pieceRays = 0;
    const uint64_t end = std::min(pixels.size(), (p + 1) * piece);
    for (uint64_t i = p * piece; i < end; ++i) {
      colors[i] = renderer.renderPixel(pixels[i], pieceRays);
    }
    rays += pieceRays;
    if (cpuSeconds != nullptr) pieceCpu[p] = threadCpuSeconds() - cpuStart;
  });
  if (cpuSeconds != nullptr) {
    for (double c : pieceCpu) *cpuSeconds += c;
  }
  return rays.load();
}

}  // namespace prt
