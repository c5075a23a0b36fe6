#include "trace/pair_bvh.h"

#include <algorithm>
#include <numeric>

#include "core/check.h"

namespace prt {
namespace {

// Beyond this depth, splits are made at the median: bounds the depth (and the traversal
// stack) to kSahDepth + log2(items) + kClusterItems whatever the boxes.
constexpr int kSahDepth = 30;
// Sets this small are built bottom-up instead, merging the pair of least bounding area first
// (Walter et al. 2008): better than any split plane with a few large or oddly placed objects
// (walls, pedestals), and cheap at this size (cubic in the count).
constexpr uint32_t kClusterItems = 48;

}  // namespace

PairBvh::PairBvh(const std::vector<Bounds>& bounds) {
  if (bounds.empty()) return;
  PRT_CHECK(bounds.size() < kItem);
  std::vector<uint32_t> items(bounds.size());
  std::iota(items.begin(), items.end(), 0u);
  nodes_.reserve(bounds.size());
  Bounds box;
  if (bounds.size() == 1) {  // a root node with the item in one lane, an empty box in the other
    nodes_.emplace_back();
    nodes_[0].boxes.set(0, bounds[0]);
    nodes_[0].child[0] = kItem;
    depth_ = 1;
    return;
  }
  build(bounds, items, 0, static_cast<uint32_t>(items.size()), 1, box);
  PRT_CHECK(depth_ <= kMaxDepth);
}

// Builds the subtree of items[begin, end) and returns the reference to it; `box` receives its
// bounds.
uint32_t PairBvh::build(const std::vector<Bounds>& bounds, std::vector<uint32_t>& items,
                        uint32_t begin, uint32_t end, int depth, Bounds& box) {
  const uint32_t count = end - begin;
  if (count == 1) {
    box = bounds[items[begin]];
    return items[begin] | kItem;
  }
  if (count <= kClusterItems) return cluster(bounds, items, begin, end, depth, box);
  depth_ = std::max(depth_, depth);
  const auto index = static_cast<uint32_t>(nodes_.size());
  nodes_.emplace_back();

  // Sort along each axis by centroid (ties by index, for a build independent of the sort
  // implementation) and sweep for the split of least area-weighted cost.
  auto byCentroid = [&](int axis) {
    std::sort(items.begin() + begin, items.begin() + end, [&](uint32_t a, uint32_t b) {
      const double ca = bounds[a].lo[axis] + bounds[a].hi[axis];
      const double cb = bounds[b].lo[axis] + bounds[b].hi[axis];
      return ca < cb || (ca == cb && a < b);
    });
  };
  int bestAxis = 0;
  uint32_t bestSplit = count / 2;  // items before it go left
  if (depth <= kSahDepth) {
    double bestCost = std::numeric_limits<double>::infinity();
    std::vector<double> rightArea(count);
    for (int axis = 0; axis < 3; ++axis) {
      byCentroid(axis);
      Bounds right;
      for (uint32_t i = count; i-- > 1;) {
        right.extend(bounds[items[begin + i]]);
        rightArea[i] = right.surfaceArea();
      }
      Bounds left;
      for (uint32_t i = 1; i < count; ++i) {
        left.extend(bounds[items[begin + i - 1]]);
        const double cost = i * left.surfaceArea() + (count - i) * rightArea[i];
        if (cost < bestCost) {
          bestCost = cost;
          bestAxis = axis;
          bestSplit = i;
        }
      }
    }
  } else {
    Bounds centroids;
    for (uint32_t i = begin; i < end; ++i) centroids.extend(bounds[items[i]].centroid());
    bestAxis = centroids.longestAxis();
  }
  byCentroid(bestAxis);

  Bounds left, right;
  const uint32_t first = build(bounds, items, begin, begin + bestSplit, depth + 1, left);
  const uint32_t second = build(bounds, items, begin + bestSplit, end, depth + 1, right);
  Node& n = nodes_[index];
  n.boxes.set(0, left);
  n.boxes.set(1, right);
  n.child[0] = first;
  n.child[1] = second;
  box = left;
  box.extend(right);
  return index;
}

// Bottom-up build of items[begin, end): see kClusterItems.
uint32_t PairBvh::cluster(const std::vector<Bounds>& bounds, const std::vector<uint32_t>& items,
                          uint32_t begin, uint32_t end, int depth, Bounds& box) {
  struct Cluster {
    Bounds box;
    int left = -1, right = -1;  // merged clusters; -1 for an item
    uint32_t item = 0;
  };
  std::vector<Cluster> all;
  std::vector<int> open;  // clusters not yet merged
  for (uint32_t i = begin; i < end; ++i) {
    open.push_back(static_cast<int>(all.size()));
    all.push_back({bounds[items[i]], -1, -1, items[i]});
  }
  while (open.size() > 1) {
    double best = std::numeric_limits<double>::infinity();
    size_t bi = 0, bj = 1;
    for (size_t i = 0; i < open.size(); ++i) {
      for (size_t j = i + 1; j < open.size(); ++j) {
        Bounds u = all[open[i]].box;
        u.extend(all[open[j]].box);
        const double area = u.surfaceArea();
        if (area < best) {
          best = area;
          bi = i;
          bj = j;
        }
      }
    }
    Cluster merged;
    merged.box = all[open[bi]].box;
    merged.box.extend(all[open[bj]].box);
    merged.left = open[bi];
    merged.right = open[bj];
    open[bi] = static_cast<int>(all.size());
    open.erase(open.begin() + static_cast<std::ptrdiff_t>(bj));
    all.push_back(merged);
  }
  // Emit parents before children, as the top-down build does.
  auto emit = [&](auto&& self, int c, int level) -> uint32_t {
    if (all[c].left < 0) return all[c].item | kItem;
    depth_ = std::max(depth_, level);
    const auto index = static_cast<uint32_t>(nodes_.size());
    nodes_.emplace_back();
    const uint32_t first = self(self, all[c].left, level + 1);
    const uint32_t second = self(self, all[c].right, level + 1);
    Node& n = nodes_[index];
    n.boxes.set(0, all[all[c].left].box);
    n.boxes.set(1, all[all[c].right].box);
    n.child[0] = first;
    n.child[1] = second;
    return index;
  };
  box = all[open[0]].box;
  return emit(emit, open[0], depth);
}

}  // namespace prt
