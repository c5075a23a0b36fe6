#pragma once
// QuadBvh: a bounding volume hierarchy of eight-way nodes, each holding its children's boxes in
// one BoxOct tested at once in single precision (conservatively: see box_quad.h); a
// child is another node or a leaf: a single item, or (for a mesh's triangles) a block of up to
// eight items the caller tests at once. The tree is built binary — top-down by a full-sweep
// surface area heuristic over the three axes, bottom-up by greedy merging for small sets, so
// large objects (floors, walls, pedestals) end up near the root instead of deep under boxes
// that overlap them — then collapsed to eight children per node: a ray's way down is a chain
// of dependent loads and tests, and wider nodes make it shorter (30 % fewer node visits
// than four-way nodes for the bunny's rays, bench/mesh_bench.cpp). Traversal visits the leaves
// a node's test meets at once, goes on with the nearest node met and skips a stacked node
// once the search distance has shrunk below its entry distance.
// Built once, then read-only: safe to query from many threads.

#include <bit>
#include <cstddef>
#include <cstring>
#include <cstdint>
#include <vector>

#include "trace/box_quad.h"

namespace prt {

// How the binary tree is split. `careful` sweeps every split along the three axes and merges
// small sets bottom-up: the best trees for the few hundred objects of a scene, but time and
// memory grow faster than the count. `binned` evaluates the surface area heuristic at 16
// planes per axis (Wald 2007; for sets of 4096 items or more, along the longest axis only),
// linear per level: a million triangles of a mesh in about half a second (bench/mesh_bench.cpp).
enum class BvhBuild { careful, binned };

class QuadBvh {
 public:
  // Leaves of blocks: up to this many items each.
  static constexpr uint32_t kBlockItems = 8;
  // The most items a tree holds (their indices share a reference with a leaf's item count).
  static constexpr size_t kMaxItems = (size_t{1} << 28) - 2;

  QuadBvh() = default;
  // `bounds[i]` is the box of item i; items are referred to by their index, one per leaf.
  explicit QuadBvh(const std::vector<Bounds>& bounds, BvhBuild how = BvhBuild::careful);
  // A binned tree whose leaves are blocks of up to kBlockItems items: block k holds the items
  // blockItems[kBlockItems * k + lane], an unused lane ~0u (the items of a block lie close in
  // space, and the blocks a ray meets close in memory).
  QuadBvh(const std::vector<Bounds>& bounds, std::vector<uint32_t>& blockItems);

  // Calls visit(item) for (a superset of) the items whose boxes hitsBounds says the ray meets
  // within (tMin, tMax()). visit returns the new tMax (to shrink the search for the nearest
  // hit) or a negative value to stop the traversal. A box whose entry equals tMax() is still
  // visited, so equal distances can be compared. With `nearestFirst`, the nodes met are
  // entered in order of entry distance, so that the search shrinks early (the leaves a node's
  // test meets are visited at once, in lane order); without, in any order (for queries that
  // need every item, or any).
  template <bool nearestFirst, typename Visit>
  void traverse(const Ray& ray, double tMin, double tMax, Visit&& visit) const {
    traverseLeaves<nearestFirst>(ray, tMin, tMax,
                                 [&](uint32_t item, uint32_t) { return visit(item); });
  }
  // The same for a tree of blocks: visit(block, count) for each block met, its first `count`
  // lanes used.
  template <bool nearestFirst, typename Visit>
  void traverseBlocks(const Ray& ray, double tMin, double tMax, Visit&& visit) const {
    traverseLeaves<nearestFirst>(ray, tMin, tMax, visit);
  }

  size_t nodeCount() const { return nodes_.size(); }
  int depth() const { return depth_; }
  size_t bytes() const { return nodes_.capacity() * sizeof(Node); }

 private:
  // A child reference: kItem set for a leaf, kItem | index << kCountBits | (count - 1), the
  // index an item's or a block's; otherwise a node's index. kEmpty: an unused lane.
  static constexpr uint32_t kItem = 1u << 31;
  static constexpr uint32_t kCountBits = 3, kCountMask = (1u << kCountBits) - 1;
  static_assert(kBlockItems <= kCountMask + 1);
  static_assert(kMaxItems < (size_t{1} << (31 - kCountBits)) - 1);
  static constexpr uint32_t kEmpty = ~0u;
  static constexpr int kMaxDepth = 128;  // of the binary tree; the build guarantees it

  // A node's children: the eight lanes of a BoxOct, tested at once.
  static constexpr int kWidth = 8;

  struct alignas(64) Node {  // 256 bytes, a power of two: cheap indexing, four cache lines
    BoxOct boxes;
    uint32_t child[kWidth];
    int leafLanes = 0, nodeLanes = 0;  // bit i set when child i is a leaf, or a node
    Node() {
      for (uint32_t& c : child) c = kEmpty;
    }
    void set(int lane, const Bounds& box, uint32_t ref) {
      boxes.set(lane, box);
      child[lane] = ref;
      ((ref & kItem) ? leafLanes : nodeLanes) |= 1 << lane;
    }
  };

  static_assert(sizeof(Node) == 256);

  // Both constructors: blocks null for leaves of one item.
  void build(const std::vector<Bounds>& bounds, BvhBuild how, std::vector<uint32_t>* blocks);
  // visit(index, count) for each leaf met.
  template <bool nearestFirst, typename Visit>
  void traverseLeaves(const Ray& ray, double tMin, double tMax, Visit&& visit) const;

  std::vector<Node> nodes_;
  float maxCoordinate_ = 0;  // of any box, rounded up: QuadRay's error bound needs it
  int depth_ = 0;
};

template <bool nearestFirst, typename Visit>
void QuadBvh::traverseLeaves(const Ray& r, double tMin, double tMax, Visit&& visit) const {
  if (nodes_.empty()) return;
  const QuadRay ray(r, maxCoordinate_);
  const float tMinF = floatBelow(tMin);
  float tMaxF = floatAbove(tMax);
  struct Pending {
    uint32_t child;
    float entry;  // a lower bound of the distance at which the child's box is entered
  };
  // Each node stacks at most kWidth - 1 children, and the tree is no deeper than its binary
  // form.
  Pending stack[(kWidth - 1) * kMaxDepth + kWidth];
  int top = 0;
  uint32_t child = 0;  // the root node
  // One loop, one call of visit: it is inlined once, and no call clobbers the registers
  // holding the ray. The leaves a node's test meets are visited at once (in lane order, each
  // still within reach), and only nodes are stacked: no step of the loop for a leaf.
  for (;;) {
    const Node& n = nodes_[child];
    float entry[kWidth];
    Float8 e;
    const int mask = n.boxes.hits(ray, tMinF, tMaxF, e);
    std::memcpy(entry, &e, sizeof e);
    for (int leaves = mask & n.leafLanes; leaves != 0; leaves &= leaves - 1) {
      const int lane = std::countr_zero(static_cast<unsigned>(leaves));
      if (entry[lane] > tMax) continue;  // a nearer hit has been found since the test
      const uint32_t ref = n.child[lane];
      const double t = visit((ref & ~kItem) >> kCountBits, (ref & kCountMask) + 1);
      if (t < 0) return;
      if (t != tMax) {
        tMax = t;
        tMaxF = floatAbove(t);
      }
    }
    int nodes = mask & n.nodeLanes;
    if (nodes != 0) {
      int lane = std::countr_zero(static_cast<unsigned>(nodes));
      nodes &= nodes - 1;
      if (nodes == 0) {  // one node met: on with it, if still within reach
        if (entry[lane] > tMax) goto resume;
        child = n.child[lane];
        continue;
      }
      // Stack the nodes met, farthest first; the nearest is taken off below.
      const int base = top;
      stack[top++] = {n.child[lane], entry[lane]};
      do {
        lane = std::countr_zero(static_cast<unsigned>(nodes));
        nodes &= nodes - 1;
        const Pending p{n.child[lane], entry[lane]};
        int i = top++;
        if constexpr (nearestFirst) {
          for (; i > base && stack[i - 1].entry < p.entry; --i) stack[i] = stack[i - 1];
        }
        stack[i] = p;
      } while (nodes != 0);
    }
  resume:
    // Resume with the nearest stacked child still within reach.
    do {
      if (top == 0) return;
      --top;
    } while (stack[top].entry > tMax);  // a nearer hit has been found since it was stacked
    child = stack[top].child;
  }
}

}  // namespace prt
