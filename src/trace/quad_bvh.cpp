#include "trace/quad_bvh.h"

#include <algorithm>
#include <numeric>

#include "core/check.h"

namespace prt {
namespace {

constexpr uint32_t kItem = 1u << 31;
// A binary leaf's reference: kItem | begin << kLeafCountBits | (count - 1).
constexpr uint32_t kLeafCountBits = 3;

// Beyond this depth, splits are made at the median: bounds the depth to
// kSahDepth + log2(items) + kClusterItems whatever the boxes.
constexpr int kSahDepth = 30;
// Sets this small are built bottom-up instead, merging the pair of least bounding area first
// (Walter et al. 2008): better than any split plane with a few large or oddly placed objects
// (walls, pedestals), and cheap at this size (cubic in the count).
constexpr uint32_t kClusterItems = 48;

// The binary tree the eight-way one is collapsed from.
class BinaryTree {
 public:
  struct Node {
    Bounds box[2];
    uint32_t child[2] = {0, 0};  // kItem set: an item; otherwise a node
  };

  // Leaves of up to maxLeaf items (1 for the careful build).
  BinaryTree(const std::vector<Bounds>& bounds, BvhBuild how, uint32_t maxLeaf)
      : bounds_(bounds), items_(bounds.size()), maxLeaf_(maxLeaf) {
    std::iota(items_.begin(), items_.end(), 0u);
    Bounds box;
    if (how == BvhBuild::binned) {
      centres_.reserve(bounds.size());
      for (const Bounds& b : bounds) centres_.push_back(b.lo + b.hi);
      nodes.reserve(bounds.size());
      root = binned(0, static_cast<uint32_t>(items_.size()), 1, box);
    } else {
      root = build(0, static_cast<uint32_t>(items_.size()), 1, box);
    }
  }

  // A leaf's reference: the items items()[begin, begin + count).
  static uint32_t leaf(uint32_t begin, uint32_t count) {
    return kItem | begin << kLeafCountBits | (count - 1);
  }
  // What testing n items costs, in tests: blocks of maxLeaf items cost one test each, so a
  // split that fills them is preferred.
  double leafCost(uint32_t n) const { return static_cast<double>((n + maxLeaf_ - 1) / maxLeaf_); }
  static uint32_t leafBegin(uint32_t ref) { return (ref & ~kItem) >> kLeafCountBits; }
  static uint32_t leafCount(uint32_t ref) { return (ref & ((1u << kLeafCountBits) - 1)) + 1; }
  const std::vector<uint32_t>& items() const { return items_; }

  std::vector<Node> nodes;
  uint32_t root = 0;  // the root's reference: a leaf when all the items fit in one
  int depth = 0;

 private:
  // Builds the subtree of items_[begin, end), returns the reference to it and its bounds.
  uint32_t build(uint32_t begin, uint32_t end, int level, Bounds& box);
  uint32_t cluster(uint32_t begin, uint32_t end, int level, Bounds& box);
  uint32_t binned(uint32_t begin, uint32_t end, int level, Bounds& box);
  uint32_t addNode(const Bounds& a, uint32_t childA, const Bounds& b, uint32_t childB);

  const std::vector<Bounds>& bounds_;
  std::vector<uint32_t> items_;
  std::vector<Vec3> centres_;  // twice each box's centre (lo + hi), for the binned build
  uint32_t maxLeaf_;
};

uint32_t BinaryTree::build(uint32_t begin, uint32_t end, int level, Bounds& box) {
  const uint32_t count = end - begin;
  if (count == 1) {
    box = bounds_[items_[begin]];
    return leaf(begin, 1);
  }
  if (count <= kClusterItems) return cluster(begin, end, level, box);
  depth = std::max(depth, level);

  // Sort along each axis by centroid (ties by index, for a build independent of the sort
  // implementation) and sweep for the split of least area-weighted cost.
  auto byCentroid = [&](int axis) {
    std::sort(items_.begin() + begin, items_.begin() + end, [&](uint32_t a, uint32_t b) {
      const double ca = bounds_[a].lo[axis] + bounds_[a].hi[axis];
      const double cb = bounds_[b].lo[axis] + bounds_[b].hi[axis];
      return ca < cb || (ca == cb && a < b);
    });
  };
  int bestAxis = 0;
  uint32_t bestSplit = count / 2;  // items before it go left
  if (level <= kSahDepth) {
    double bestCost = std::numeric_limits<double>::infinity();
    std::vector<double> rightArea(count);
    for (int axis = 0; axis < 3; ++axis) {
      byCentroid(axis);
      Bounds right;
      for (uint32_t i = count; i-- > 1;) {
        right.extend(bounds_[items_[begin + i]]);
        rightArea[i] = right.surfaceArea();
      }
      Bounds left;
      for (uint32_t i = 1; i < count; ++i) {
        left.extend(bounds_[items_[begin + i - 1]]);
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
    for (uint32_t i = begin; i < end; ++i) centroids.extend(bounds_[items_[i]].centroid());
    bestAxis = centroids.longestAxis();
  }
  byCentroid(bestAxis);

  const auto index = static_cast<uint32_t>(nodes.size());
  nodes.emplace_back();
  Bounds left, right;
  const uint32_t first = build(begin, begin + bestSplit, level + 1, left);
  const uint32_t second = build(begin + bestSplit, end, level + 1, right);
  nodes[index] = {{left, right}, {first, second}};
  box = left;
  box.extend(right);
  return index;
}

uint32_t BinaryTree::cluster(uint32_t begin, uint32_t end, int level, Bounds& box) {
  struct Cluster {
    Bounds box;
    int left = -1, right = -1;  // merged clusters; -1 for an item
    uint32_t place = 0;  // of an item, in items_
  };
  std::vector<Cluster> all;
  std::vector<int> open;  // clusters not yet merged
  for (uint32_t i = begin; i < end; ++i) {
    open.push_back(static_cast<int>(all.size()));
    all.push_back({bounds_[items_[i]], -1, -1, i});
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
  auto emit = [&](auto&& self, int c, int at) -> uint32_t {
    if (all[c].left < 0) return leaf(all[c].place, 1);
    depth = std::max(depth, at);
    const auto index = static_cast<uint32_t>(nodes.size());
    nodes.emplace_back();
    const uint32_t first = self(self, all[c].left, at + 1);
    const uint32_t second = self(self, all[c].right, at + 1);
    nodes[index] = {{all[all[c].left].box, all[all[c].right].box}, {first, second}};
    return index;
  };
  box = all[open[0]].box;
  return emit(emit, open[0], level);
}

uint32_t BinaryTree::binned(uint32_t begin, uint32_t end, int level, Bounds& box) {
  const uint32_t count = end - begin;
  if (count <= maxLeaf_) {
    box = Bounds{};
    for (uint32_t i = begin; i < end; ++i) box.extend(bounds_[items_[i]]);
    return leaf(begin, count);
  }
  depth = std::max(depth, level);
  Bounds centres;
  for (uint32_t i = begin; i < end; ++i) centres.extend(centres_[items_[i]]);
  int bestAxis = centres.longestAxis();
  uint32_t mid = 0;
  if (level <= kSahDepth && count > 2) {
    constexpr int kBins = 16;
    Bounds bins[3][kBins];
    uint32_t counts[3][kBins] = {};
    double scale[3];
    // Large sets are binned along their longest axis alone, a third of the work where most
    // of it is; below kAllAxes items every axis is tried.
    constexpr uint32_t kAllAxes = 4096;
    for (int axis = 0; axis < 3; ++axis) {
      const double extent = centres.hi[axis] - centres.lo[axis];
      const bool tried = count < kAllAxes || axis == bestAxis;
      scale[axis] = extent > 0 && tried ? kBins / extent : 0;
    }
    auto binOf = [&](uint32_t item, int axis) {
      const auto b = static_cast<int>((centres_[item][axis] - centres.lo[axis]) * scale[axis]);
      return std::min(b, kBins - 1);
    };
    for (uint32_t i = begin; i < end; ++i) {
      const uint32_t item = items_[i];
      for (int axis = 0; axis < 3; ++axis) {
        if (scale[axis] == 0) continue;
        const int b = binOf(item, axis);
        bins[axis][b].extend(bounds_[item]);
        ++counts[axis][b];
      }
    }
    double bestCost = std::numeric_limits<double>::infinity();
    int bestSplit = 0;  // bins before it go left
    for (int axis = 0; axis < 3; ++axis) {
      if (scale[axis] == 0) continue;
      double rightArea[kBins];
      uint32_t rightCount[kBins];
      Bounds right;
      uint32_t n = 0;
      for (int b = kBins; b-- > 1;) {
        right.extend(bins[axis][b]);
        n += counts[axis][b];
        rightArea[b] = right.surfaceArea();
        rightCount[b] = n;
      }
      Bounds left;
      n = 0;
      for (int b = 1; b < kBins; ++b) {
        left.extend(bins[axis][b - 1]);
        n += counts[axis][b - 1];
        if (n == 0 || rightCount[b] == 0) continue;
        const double cost =
            leafCost(n) * left.surfaceArea() + leafCost(rightCount[b]) * rightArea[b];
        if (cost < bestCost) {
          bestCost = cost;
          bestAxis = axis;
          bestSplit = b;
        }
      }
    }
    if (bestSplit > 0) {
      const auto middle =
          std::partition(items_.begin() + begin, items_.begin() + end,
                         [&](uint32_t item) { return binOf(item, bestAxis) < bestSplit; });
      mid = static_cast<uint32_t>(middle - items_.begin());
    }
  }
  if (mid <= begin || mid >= end) {  // no useful plane (or deep enough): halve at the median
    mid = begin + count / 2;
    std::nth_element(items_.begin() + begin, items_.begin() + mid, items_.begin() + end,
                     [&](uint32_t a, uint32_t b) {
                       const double ca = centres_[a][bestAxis], cb = centres_[b][bestAxis];
                       return ca < cb || (ca == cb && a < b);
                     });
  }
  const auto index = static_cast<uint32_t>(nodes.size());
  nodes.emplace_back();
  Bounds left, right;
  const uint32_t first = binned(begin, mid, level + 1, left);
  const uint32_t second = binned(mid, end, level + 1, right);
  nodes[index] = {{left, right}, {first, second}};
  box = left;
  box.extend(right);
  return index;
}

}  // namespace

QuadBvh::QuadBvh(const std::vector<Bounds>& bounds, BvhBuild how) { build(bounds, how, nullptr); }

QuadBvh::QuadBvh(const std::vector<Bounds>& bounds, std::vector<uint32_t>& blockItems) {
  build(bounds, BvhBuild::binned, &blockItems);
}

void QuadBvh::build(const std::vector<Bounds>& bounds, BvhBuild how,
                    std::vector<uint32_t>* blocks) {
  if (blocks != nullptr) blocks->clear();
  if (bounds.empty()) return;
  // Item and block indices take 28 bits of a reference, and the largest would make kEmpty.
  static_assert(kLeafCountBits == kCountBits);
  PRT_CHECK(bounds.size() <= kMaxItems);
  double maxCoordinate = 0;
  for (const Bounds& b : bounds) maxCoordinate = std::max(maxCoordinate, b.largestMagnitude());
  maxCoordinate_ = floatAbove(maxCoordinate);
  const BinaryTree tree(bounds, how, blocks != nullptr ? kBlockItems : 1);
  PRT_CHECK(tree.depth <= kMaxDepth);
  depth_ = std::max(tree.depth, 1);
  nodes_.reserve(tree.nodes.size() / 2 + 1);

  // A binary leaf becomes an item's reference, or the next block's (its items stored).
  auto leafRef = [&](uint32_t ref) {
    const uint32_t begin = BinaryTree::leafBegin(ref), count = BinaryTree::leafCount(ref);
    if (blocks == nullptr) return kItem | tree.items()[begin] << kCountBits;
    const auto block = static_cast<uint32_t>(blocks->size() / kBlockItems);
    for (uint32_t lane = 0; lane < kBlockItems; ++lane) {
      blocks->push_back(lane < count ? tree.items()[begin + lane] : ~0u);
    }
    return kItem | block << kCountBits | (count - 1);
  };
  if (tree.root & kItem) {  // one leaf: a root node with it in one lane, the others empty
    Bounds box;
    for (const Bounds& b : bounds) box.extend(b);
    nodes_.emplace_back();
    nodes_[0].set(0, box, leafRef(tree.root));
    return;
  }

  // Collapse: a kWidth-way node takes the place of a binary node and its descendants down to
  // kWidth children, opening the child of largest area first (the likeliest to be entered).
  struct Child {
    Bounds box;
    uint32_t ref;
  };
  auto collapse = [&](auto&& self, uint32_t binary) -> uint32_t {
    const auto& b = tree.nodes[binary];
    Child children[kWidth] = {{b.box[0], b.child[0]}, {b.box[1], b.child[1]}};
    int size = 2;
    while (size < kWidth) {
      int open = -1;
      for (int i = 0; i < size; ++i) {
        if (!(children[i].ref & kItem) &&
            (open < 0 || children[i].box.surfaceArea() > children[open].box.surfaceArea())) {
          open = i;
        }
      }
      if (open < 0) break;
      const auto& inner = tree.nodes[children[open].ref];
      children[open] = {inner.box[0], inner.child[0]};
      children[size++] = {inner.box[1], inner.child[1]};
    }
    const auto index = static_cast<uint32_t>(nodes_.size());
    nodes_.emplace_back();
    for (int lane = 0; lane < size; ++lane) {
      const uint32_t ref = (children[lane].ref & kItem) ? leafRef(children[lane].ref)
                                                        : self(self, children[lane].ref);
      nodes_[index].set(lane, children[lane].box, ref);
    }
    return index;
  };
  collapse(collapse, tree.root);
  nodes_.shrink_to_fit();  // a node takes one to kWidth - 1 binary ones
  if (blocks != nullptr) blocks->shrink_to_fit();
}

}  // namespace prt
