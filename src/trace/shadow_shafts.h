#pragma once
// ShadowShafts: for each light, which objects could stand between it and a point of space.
// Shaft culling (Haines & Wallace 1991) over a grid: space around the bounded objects is cut
// into cells, and for each cell and light the objects whose boxes meet the shaft — the convex
// hull of the cell and the light's box — are listed. A shadow ray leaving from inside a cell
// towards a point of that light runs inside the shaft, so only the listed objects can cross
// it. The list replaces a BVH traversal (setting the ray up, a few nodes of four boxes) by a
// few direct tests: in the benchmark scene five shadow rays in six are answered so (the others
// start outside the grid), testing 1.8 objects each on average (none for 3 in 10 of them).
//
// The lists are conservative (they may hold an object the shaft misses, never leave out one
// it meets, cells and light boxes being widened against rounding), so a query answered from
// a list crosses exactly the objects the BVH would report. Cells whose list would be long are
// left to the BVH, as are rays from outside the grid, which spans the objects and the lights
// (the far parts of an infinite plane).
// Built once, then read-only: safe to query from many threads.

#include <algorithm>
#include <cstdint>
#include <optional>
#include <span>
#include <vector>

#include "trace/bounds.h"

namespace prt {

// The convex hull of two boxes, for testing boxes against it.
class Shaft {
 public:
  Shaft(const Bounds& from, const Bounds& to);
  // Whether box `b` meets the hull; false only when proven disjoint (by a separating axis:
  // the normals of the hull's faces), so true when in doubt.
  bool meets(const Bounds& b) const;

 private:
  struct Side {
    Vec3 axis, absAxis;
    double lo, hi;  // the hull's extent along the axis
  };
  Bounds box_;  // the hull's bounding box
  Side sides_[12];
  int count_ = 0;
};

class ShadowShafts {
 public:
  ShadowShafts() = default;
  // `items[i]` is the box of item i, `lights[l]` the box holding every point light l's
  // shadow rays aim at. Lists longer than `longest` are left to the BVH (up to a dozen
  // objects, a list is scanned faster than the BVH is traversed). The grid spans the
  // items' and the lights' boxes in about cellsFor(lights.size()) cells.
  ShadowShafts(const std::vector<Bounds>& items, const std::vector<Bounds>& lights,
               uint32_t longest = 12);

  // The grid cell holding `origin`, or kNoCell outside the grid (or with no grid). A point's
  // cell serves every light's query from it: the shader finds it once per shading point.
  static constexpr size_t kNoCell = ~size_t{0};
  size_t cellOf(const Vec3& origin) const {
    if (lists_.empty()) return kNoCell;
    const Vec3 r = (origin - lo_) * scale_;
    // NaN fails these tests too.
    if (!(r.x >= 0 && r.x < dims_[0] && r.y >= 0 && r.y < dims_[1] && r.z >= 0 && r.z < dims_[2])) {
      return kNoCell;
    }
    return cellIndex(static_cast<int>(r.x), static_cast<int>(r.y), static_cast<int>(r.z));
  }

  // The items a segment from a point of cell `cell` (cellOf) to a point of light `light`'s box
  // can cross, or nothing when the caller must ask the BVH (no cell, long list).
  std::optional<std::span<const uint32_t>> candidatesIn(size_t cell, size_t light) const {
    if (cell == kNoCell) return std::nullopt;
    const List list = lists_[cell * lights_ + light];
    if (list.count == kLong) return std::nullopt;
    return std::span<const uint32_t>(items_.data() + list.begin, list.count);
  }

  // The same for a segment from `origin`.
  std::optional<std::span<const uint32_t>> candidates(size_t light, const Vec3& origin) const {
    return candidatesIn(cellOf(origin), light);
  }

  size_t cellCount() const { return static_cast<size_t>(dims_[0]) * dims_[1] * dims_[2]; }

  // About how many cells the grid has. Small cells make narrow shafts near the shading point,
  // where the objects that shadow it crowd: in the benchmark scene 32768 cells (against 4096)
  // take 2 % off the instructions of a render, a shadow ray costing 17 ns instead of 26, for a
  // build of 2.6 ms instead of 0.5 (bench/trace_bench.cpp); more cells gain nothing there.
  // Every cell holds a list per light: past four lights the grid has fewer cells, so that the
  // lists stay within about kListEntries (1 MB) up to 32 lights; more lights keep
  // kFewestCells, the grid's size before it was refined (3.5 MB of lists for 100 lights).
  static constexpr double kCells = 32768, kFewestCells = 4096, kListEntries = 131072;
  static double cellsFor(size_t lights) {
    return std::clamp(kListEntries / static_cast<double>(std::max<size_t>(lights, 1)),
                      kFewestCells, kCells);
  }

 private:
  // A region whose shaft meets more objects than this is too crowded to be worth splitting:
  // its cells go to the BVH. The whole grid's shaft meets about every object, so scenes of more
  // objects keep the BVH alone, and the build stays cheap however many a scene has (about 20 ms
  // for 250 objects and three lights, which a render of them repays many times over). It
  // grows with the lights, each having its lists: 80 ms for 250 objects and 100 lights.
  static constexpr size_t kCrowded = 256;

  struct Region {
    int lo[3], hi[3];  // cells [lo, hi) per axis
  };
  struct List {
    uint32_t begin, count;  // in items_; count kLong: ask the BVH
  };
  static constexpr uint32_t kLong = ~0u;
  std::vector<uint32_t> items_;  // every list, one after another
  std::vector<List> lists_;      // lists_[cell * lights + light]

  size_t cellIndex(int x, int y, int z) const {
    return (static_cast<size_t>(z) * dims_[1] + static_cast<size_t>(y)) * dims_[0] +
           static_cast<size_t>(x);
  }
  // Lists, for light l, every cell of `region` from the items among `candidates` its shaft
  // meets, splitting the region while that pays.
  void refine(const std::vector<Bounds>& items, const Bounds& light, size_t l, const Region& region,
              const std::vector<uint32_t>& candidates);

  Vec3 lo_;     // the grid's low corner
  Vec3 cell_;   // a cell's size
  Vec3 scale_;  // cells per unit length, per axis
  double margin_ = 0;
  int dims_[3] = {0, 0, 0};
  size_t lights_ = 0;
  uint32_t longest_ = 0;
};

}  // namespace prt
