#include "trace/bvh.h"

#include <algorithm>
#include <numeric>

#include "core/check.h"

namespace prt {
namespace {

constexpr int kBvhBins = 12;
constexpr uint32_t kMaxLeafItems = 4;

}  // namespace

Bvh::Bvh(const std::vector<Bounds>& bounds) {
  if (bounds.empty()) return;
  PRT_CHECK(bounds.size() < (1u << 31));
  items_.resize(bounds.size());
  std::iota(items_.begin(), items_.end(), 0u);
  nodes_.reserve(2 * bounds.size());
  build(bounds, 0, static_cast<uint32_t>(bounds.size()));
}

std::vector<uint32_t> Bvh::visitOrder(int octant) const {
  std::vector<uint32_t> order;
  if (nodes_.empty()) return order;
  // traverse() with every box hit.
  std::vector<uint32_t> stack{0};
  while (!stack.empty()) {
    const Node& n = nodes_[stack.back()];
    const uint32_t node = stack.back();
    stack.pop_back();
    if (n.itemCount > 0) {
      for (uint32_t i = 0; i < n.itemCount; ++i) order.push_back(items_[n.firstOrSecondChild + i]);
    } else {
      const bool reversed = (octant >> n.axis) & 1;
      stack.push_back(reversed ? node + 1 : n.firstOrSecondChild);
      stack.push_back(reversed ? n.firstOrSecondChild : node + 1);
    }
  }
  return order;
}

uint32_t Bvh::build(const std::vector<Bounds>& bounds, uint32_t begin, uint32_t end) {
  const uint32_t index = static_cast<uint32_t>(nodes_.size());
  nodes_.push_back({});
  Bounds box, centroids;
  for (uint32_t i = begin; i < end; ++i) {
    box.extend(bounds[items_[i]]);
    centroids.extend(bounds[items_[i]].centroid());
  }
  nodes_[index].box = box;
  const uint32_t count = end - begin;
  const int axis = centroids.longestAxis();
  const double lo = centroids.lo[axis];
  const double extent = centroids.hi[axis] - lo;

  auto makeLeaf = [&] {
    nodes_[index].firstOrSecondChild = begin;
    nodes_[index].itemCount = static_cast<uint16_t>(count);
  };
  if (count <= kMaxLeafItems && (count == 1 || extent <= 0)) {
    makeLeaf();
    return index;
  }

  uint32_t mid = begin + count / 2;
  if (extent > 0) {
    // Binned surface-area heuristic along the longest centroid axis.
    auto binOf = [&](uint32_t item) {
      const int b = static_cast<int>(kBvhBins * (bounds[item].centroid()[axis] - lo) / extent);
      return std::min(b, kBvhBins - 1);
    };
    Bounds binBox[kBvhBins];
    uint32_t binCount[kBvhBins] = {};
    for (uint32_t i = begin; i < end; ++i) {
      const int b = binOf(items_[i]);
      binBox[b].extend(bounds[items_[i]]);
      ++binCount[b];
    }
    double bestCost = std::numeric_limits<double>::infinity();
    int bestSplit = -1;
    for (int split = 1; split < kBvhBins; ++split) {
      Bounds left, right;
      uint32_t nl = 0, nr = 0;
      for (int b = 0; b < split; ++b) { left.extend(binBox[b]); nl += binCount[b]; }
      for (int b = split; b < kBvhBins; ++b) { right.extend(binBox[b]); nr += binCount[b]; }
      if (nl == 0 || nr == 0) continue;
      const double cost = nl * left.surfaceArea() + nr * right.surfaceArea();
      if (cost < bestCost) { bestCost = cost; bestSplit = split; }
    }
    const double leafCost = count * box.surfaceArea();
    if (count <= kMaxLeafItems && bestCost >= leafCost) {
      makeLeaf();
      return index;
    }
    if (bestSplit > 0) {
      const auto midIt = std::partition(items_.begin() + begin, items_.begin() + end,
                                        [&](uint32_t item) { return binOf(item) < bestSplit; });
      mid = static_cast<uint32_t>(midIt - items_.begin());
    } else {
      std::nth_element(items_.begin() + begin, items_.begin() + mid, items_.begin() + end,
                       [&](uint32_t a, uint32_t b) {
                         return bounds[a].centroid()[axis] < bounds[b].centroid()[axis];
                       });
    }
  }
  if (mid == begin || mid == end) mid = begin + count / 2;
  nodes_[index].axis = static_cast<uint16_t>(axis);
  build(bounds, begin, mid);  // the first child follows its parent
  nodes_[index].firstOrSecondChild = build(bounds, mid, end);
  return index;
}

}  // namespace prt
