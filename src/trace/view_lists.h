#pragma once
// ViewLists: for each tile of the image, the objects a camera ray through it can meet (a vista
// buffer, after Weghorst, Hooper and Greenberg 1984). Every object's box is projected onto the
// image once; a camera ray through a tile can only meet the objects whose projections overlap
// the tile, so its nearest-hit query tests those few directly instead of traversing the BVH.
// Tiles of open sky list nothing at all.
//
// The lists are conservative: a projection is widened by half a pixel (rounding in the camera
// and the projection is smaller by many orders), and a box reaching behind the eye covers the
// whole image. A query answered from a list therefore meets the objects the BVH would offer.
// Tiles whose list would be long are left to the BVH. Built once per image, then read-only:
// safe to query from many threads.

#include <cstdint>
#include <optional>
#include <span>
#include <vector>

#include "trace/bounds.h"
#include "trace/camera.h"

namespace prt {

class ViewLists {
 public:
  ViewLists() = default;
  // `items[i]` is the box of item i, seen through `camera` on a width x height image. Lists
  // longer than `longest` are left to the BVH.
  ViewLists(const PinholeCamera& camera, int width, int height, const std::vector<Bounds>& items,
            uint32_t longest = 8);

  // The items a camera ray through pixel (x, y) (anywhere inside it) can meet, or nothing when
  // the caller must ask the BVH.
  std::optional<std::span<const uint32_t>> candidates(int x, int y) const {
    if (lists_.empty() || x < 0 || y < 0 || x >= width_ || y >= height_) return std::nullopt;
    const List list = lists_[static_cast<size_t>(y / kTile) * tilesX_ + x / kTile];
    if (list.count == kLong) return std::nullopt;
    return std::span<const uint32_t>(items_.data() + list.begin, list.count);
  }

  static constexpr int kTile = 8;  // pixels on a side

 private:
  struct List {
    uint32_t begin, count;  // in items_; count kLong: ask the BVH
  };
  static constexpr uint32_t kLong = ~0u;

  int width_ = 0, height_ = 0, tilesX_ = 0;
  std::vector<uint32_t> items_;
  std::vector<List> lists_;  // lists_[tileY * tilesX + tileX]
};

}  // namespace prt
