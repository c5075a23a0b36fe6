#include "trace/renderer.h"

#include <chrono>
#include <mutex>

#include "core/parallel.h"
#include "trace/sampling.h"

namespace prt {

Renderer::Renderer(const World& world, const RenderSettings& settings)
    : world_(world),
      settings_(settings),
      width_(world.scene().image.width),
      height_(world.scene().image.height),
      camera_(world.scene().camera, width_, height_),
      shader_(world, settings) {}

Color Renderer::renderPixel(uint64_t pixelIndex, uint64_t& rays) const {
  const int x = static_cast<int>(pixelIndex % static_cast<uint64_t>(width_));
  const int y = static_cast<int>(pixelIndex / static_cast<uint64_t>(width_));
  const int n = settings_.samplesPerPixel;
  Color sum;
  for (int s = 0; s < n; ++s) {
    Rng rng = Rng::forSample(pixelIndex, static_cast<uint32_t>(s));
    double dx = 0.5, dy = 0.5;  // one sample looks through the pixel centre
    if (n > 1) {
      const double jx = rng.uniform();
      const double jy = rng.uniform();
      stratifiedSample(s, n, jx, jy, dx, dy);
    }
    const Ray ray = camera_.generateRay(x + dx, y + dy);
    sum += shader_.trace(ray, 0, rng.child(1), rays);
  }
  return sum / n;
}

namespace {
constexpr int kTileSize = 16;
}

Image renderImage(const Renderer& renderer, int threads, RenderStats* stats,
                  const ProgressFn& progress) {
  const auto start = std::chrono::steady_clock::now();
  const int w = renderer.width(), h = renderer.height();
  Image image(w, h);
  const int tilesX = (w + kTileSize - 1) / kTileSize;
  const int tilesY = (h + kTileSize - 1) / kTileSize;
  std::atomic<uint64_t> rays{0};
  std::mutex progressMutex;
  uint64_t done = 0;
  parallelFor(static_cast<uint64_t>(tilesX) * tilesY, threads, [&](uint64_t tile) {
    const int tx = static_cast<int>(tile % static_cast<uint64_t>(tilesX)) * kTileSize;
    const int ty = static_cast<int>(tile / static_cast<uint64_t>(tilesX)) * kTileSize;
    uint64_t tileRays = 0;
    const int x1 = std::min(w, tx + kTileSize), y1 = std::min(h, ty + kTileSize);
    for (int y = ty; y < y1; ++y) {
      for (int x = tx; x < x1; ++x) {
        const uint64_t index = static_cast<uint64_t>(y) * w + x;
        image.set(index, renderer.renderPixel(index, tileRays));
      }
    }
    rays += tileRays;
    if (progress) {
      std::lock_guard lock(progressMutex);
      done += static_cast<uint64_t>(x1 - tx) * (y1 - ty);
      progress(done, renderer.pixelCount());
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
                     std::vector<Color>& colors) {
  colors.resize(tasks.size());
  constexpr uint64_t kPiece = 256;
  const uint64_t pieces = (tasks.size() + kPiece - 1) / kPiece;
  std::atomic<uint64_t> rays{0};
  // Flatten once so pieces can be addressed by position; a task set here is at most a
  // worker's batch, not the whole image of a huge render.
  const std::vector<uint64_t> pixels = tasks.toVector();
  parallelFor(pieces, threads, [&](uint64_t piece) {
    uint64_t pieceRays = 0;
    const uint64_t end = std::min(pixels.size(), (piece + 1) * kPiece);
    for (uint64_t i = piece * kPiece; i < end; ++i) {
      colors[i] = renderer.renderPixel(pixels[i], pieceRays);
    }
    rays += pieceRays;
  });
  return rays.load();
}

}  // namespace prt
