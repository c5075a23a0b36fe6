#pragma once
// QuadBvh: a bounding volume hierarchy of four-way nodes, each holding its children's boxes in
// one BoxQuad tested at once in single precision (conservatively: see box_quad.h); a child is
// another node or a single item. The tree is built binary — top-down by a full-sweep surface
// area heuristic over the three axes, bottom-up by greedy merging for small sets, so large
// objects (floors, walls, pedestals) end up near the root instead of deep under boxes that
// overlap them — then collapsed to four children per node. Traversal is nearest-child-first
// and skips a stacked child once the search distance has shrunk below its entry distance.
// Built once, then read-only: safe to query from many threads.

#include <bit>
#include <cstdint>
#include <vector>

#include "trace/box_quad.h"

namespace prt {

// How the binary tree is split. `careful` sweeps every split along the three axes and merges
// small sets bottom-up: the best trees for the few hundred objects of a scene, but time and
// memory grow faster than the count. `binned` evaluates the surface area heuristic at 16
// planes per axis (Wald 2007; for sets of 4096 items or more, along the longest axis only),
// linear per level: a million triangles of a mesh in about a second (bench/mesh_bench.cpp).
enum class BvhBuild { careful, binned };

class QuadBvh {
 public:
  QuadBvh() = default;
  // `bounds[i]` is the box of item i; items are referred to by their index.
  explicit QuadBvh(const std::vector<Bounds>& bounds, BvhBuild build = BvhBuild::careful);

  // Calls visit(item) for (a superset of) the items whose boxes hitsBounds says the ray meets
  // within (tMin, tMax()). visit returns the new tMax (to shrink the search for the nearest
  // hit) or a negative value to stop the traversal. A box whose entry equals tMax() is still
  // visited, so equal distances can be compared. With `nearestFirst`, children are visited in
  // order of entry distance, so that the search shrinks early; without, in any order (for
  // queries that need every item, or any).
  template <bool nearestFirst, typename Visit>
  void traverse(const Ray& ray, double tMin, double tMax, Visit&& visit) const;

  size_t nodeCount() const { return nodes_.size(); }
  int depth() const { return depth_; }
  size_t bytes() const { return nodes_.capacity() * sizeof(Node); }

  // The items in the order a traversal that enters every child, first lane first, meets them;
  // and the same tree with item i renamed newIndex[i] (a permutation). Together they let a
  // caller store its items in the tree's order, so that the items a ray meets lie close in
  // memory.
  std::vector<uint32_t> itemOrder() const;
  void renameItems(const std::vector<uint32_t>& newIndex);

 private:
  static constexpr uint32_t kItem = 1u << 31;  // child reference: set for an item index
  static constexpr uint32_t kEmpty = ~0u;      // child reference: an unused lane
  static constexpr int kMaxDepth = 128;        // of the binary tree; the build guarantees it

  struct alignas(128) Node {  // a power of two: cheap indexing, two cache lines
    BoxQuad boxes;
    uint32_t child[4] = {kEmpty, kEmpty, kEmpty, kEmpty};
  };

  std::vector<Node> nodes_;
  float maxCoordinate_ = 0;  // of any box, rounded up: QuadRay's error bound needs it
  int depth_ = 0;
};

template <bool nearestFirst, typename Visit>
void QuadBvh::traverse(const Ray& r, double tMin, double tMax, Visit&& visit) const {
  if (nodes_.empty()) return;
  const QuadRay ray(r, maxCoordinate_);
  const float tMinF = floatBelow(tMin);
  float tMaxF = floatAbove(tMax);
  struct Pending {
    uint32_t child;
    float entry;  // a lower bound of the distance at which the child's box is entered
  };
  // Each node stacks at most three children, and the tree is no deeper than its binary form.
  Pending stack[3 * kMaxDepth + 4];
  int top = 0;
  uint32_t child = 0;  // the root node
  // One loop, one call of visit: it is inlined once, and no call clobbers the registers
  // holding the ray.
  for (;;) {
    if (!(child & kItem)) {
      const Node& n = nodes_[child];
      Float4 entry;
      int mask = n.boxes.hits(ray, tMinF, tMaxF, entry);
      if (mask != 0) {
        // Stack the children met, farthest first, and go on with the nearest.
        int lane = std::countr_zero(static_cast<unsigned>(mask));
        mask &= mask - 1;
        if (mask == 0) {
          child = n.child[lane];
          continue;
        }
        const int base = top;
        stack[top++] = {n.child[lane], entry[lane]};
        do {
          lane = std::countr_zero(static_cast<unsigned>(mask));
          mask &= mask - 1;
          const Pending p{n.child[lane], entry[lane]};
          int i = top++;
          if constexpr (nearestFirst) {
            for (; i > base && stack[i - 1].entry < p.entry; --i) stack[i] = stack[i - 1];
          }
          stack[i] = p;
        } while (mask != 0);
        child = stack[--top].child;
        continue;
      }
    } else if (child != kEmpty) {
      const double t = visit(child & ~kItem);
      if (t < 0) return;
      if (t != tMax) {
        tMax = t;
        tMaxF = floatAbove(t);
      }
    }
    // Resume with the nearest stacked child still within reach.
    do {
      if (top == 0) return;
      --top;
    } while (stack[top].entry > tMax);  // a nearer hit has been found since it was stacked
    child = stack[top].child;
  }
}

}  // namespace prt
