#include "trace/view_lists.h"

#include <algorithm>
#include <cmath>

namespace prt {
namespace {

// The tiles [x0, x1] x [y0, y1] (inclusive, clamped to the image) that a box's projection,
// widened by half a pixel, overlaps; all of them when part of the box is not in front.
struct TileRange {
  int x0, y0, x1, y1;
};

TileRange tilesCovered(const PinholeCamera& camera, const Bounds& b, int tilesX, int tilesY) {
  constexpr double kMargin = 0.5;  // pixels
  const TileRange all{0, 0, tilesX - 1, tilesY - 1};
  double lo[2] = {HUGE_VAL, HUGE_VAL}, hi[2] = {-HUGE_VAL, -HUGE_VAL};
  for (int c = 0; c < 8; ++c) {
    double p[2];
    if (!camera.project(b.corner(c), p[0], p[1]) || !std::isfinite(p[0]) || !std::isfinite(p[1])) {
      return all;
    }
    for (int a = 0; a < 2; ++a) {
      lo[a] = std::min(lo[a], p[a]);
      hi[a] = std::max(hi[a], p[a]);
    }
  }
  // Far outside the image, the floor division below would overflow an int: clamp first.
  auto tile = [](double pixel, int tiles) {
    const double t = std::floor(pixel / ViewLists::kTile);
    return static_cast<int>(std::clamp(t, -1.0, static_cast<double>(tiles)));
  };
  TileRange r{tile(lo[0] - kMargin, tilesX), tile(lo[1] - kMargin, tilesY),
              tile(hi[0] + kMargin, tilesX), tile(hi[1] + kMargin, tilesY)};
  r.x0 = std::max(r.x0, 0);
  r.y0 = std::max(r.y0, 0);
  r.x1 = std::min(r.x1, tilesX - 1);
  r.y1 = std::min(r.y1, tilesY - 1);
  return r;
}

}  // namespace

ViewLists::ViewLists(const PinholeCamera& camera, int width, int height,
                     const std::vector<Bounds>& items, uint32_t longest)
    : width_(width), height_(height), tilesX_((width + kTile - 1) / kTile) {
  if (width <= 0 || height <= 0 || items.empty()) return;
  const int tilesY = (height + kTile - 1) / kTile;
  const size_t tiles = static_cast<size_t>(tilesX_) * tilesY;
  // The work is the tiles each item covers; a scene of very many objects, large on screen,
  // would spend longer here than the lists could save: it keeps the BVH alone.
  const size_t budget = 64 * tiles + 64 * items.size();
  size_t work = 0;
  std::vector<TileRange> ranges;
  ranges.reserve(items.size());
  std::vector<uint32_t> counts(tiles, 0);
  for (const Bounds& b : items) {
    const TileRange r = tilesCovered(camera, b, tilesX_, tilesY);
    ranges.push_back(r);
    if (r.x0 > r.x1 || r.y0 > r.y1) continue;
    work += static_cast<size_t>(r.x1 - r.x0 + 1) * (r.y1 - r.y0 + 1);
    if (work > budget) return;
    for (int ty = r.y0; ty <= r.y1; ++ty) {
      for (int tx = r.x0; tx <= r.x1; ++tx) ++counts[static_cast<size_t>(ty) * tilesX_ + tx];
    }
  }
  // Lay the lists out one after another, then fill them in item order.
  lists_.resize(tiles);
  uint32_t total = 0;
  for (size_t t = 0; t < tiles; ++t) {
    if (counts[t] > longest) {
      lists_[t] = {0, kLong};
    } else {
      lists_[t] = {total, 0};
      total += counts[t];
    }
  }
  items_.resize(total);
  for (uint32_t i = 0; i < items.size(); ++i) {
    const TileRange& r = ranges[i];
    for (int ty = r.y0; ty <= r.y1; ++ty) {
      for (int tx = r.x0; tx <= r.x1; ++tx) {
        List& list = lists_[static_cast<size_t>(ty) * tilesX_ + tx];
        if (list.count != kLong) items_[list.begin + list.count++] = i;
      }
    }
  }
}

}  // namespace prt
