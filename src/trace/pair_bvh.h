#pragma once
// PairBvh: a binary bounding volume hierarchy whose nodes hold the boxes of both their
// children, tested together with one BoxPair (SIMD) slab test; a child is another node or a
// single item. Built by a full-sweep surface-area heuristic over the three axes, so large
// objects (floors, walls, pedestals) end up near the root instead of deep under boxes that
// overlap them. Traversal is nearest-child-first and skips a stacked child once the search
// distance has shrunk below its entry distance.
// Built once, then read-only: safe to query from many threads.

#include <cstdint>
#include <vector>

#include "trace/box_pair.h"

namespace prt {

class PairBvh {
 public:
  PairBvh() = default;
  // `bounds[i]` is the box of item i; items are referred to by their index.
  explicit PairBvh(const std::vector<Bounds>& bounds);

  // Calls visit(item) for (a superset of) the items whose boxes hitsBounds says the ray meets
  // within (tMin, tMax()), nearer boxes first as far as the tree tells. visit returns the new
  // tMax (to shrink the search for the nearest hit) or a negative value to stop the traversal.
  // A box whose entry equals tMax() is still visited, so equal distances can be compared.
  template <typename Visit>
  void traverse(const SlabRay& ray, double tMin, double tMax, Visit&& visit) const;

  size_t nodeCount() const { return nodes_.size(); }
  int depth() const { return depth_; }

 private:
  static constexpr uint32_t kItem = 1u << 31;  // child reference: set for an item index
  static constexpr int kMaxDepth = 128;        // the build guarantees it; sizes the stack

  struct alignas(128) Node {  // a power of two: cheap indexing, two cache lines
    BoxPair boxes;
    uint32_t child[2] = {0, 0};
  };
  uint32_t build(const std::vector<Bounds>& bounds, std::vector<uint32_t>& items, uint32_t begin,
                 uint32_t end, int depth, Bounds& box);
  uint32_t cluster(const std::vector<Bounds>& bounds, const std::vector<uint32_t>& items,
                   uint32_t begin, uint32_t end, int depth, Bounds& box);

  std::vector<Node> nodes_;
  int depth_ = 0;
};

template <typename Visit>
void PairBvh::traverse(const SlabRay& ray, double tMin, double tMax, Visit&& visit) const {
  if (nodes_.empty()) return;
  struct Pending {
    uint32_t child;
    double entry;
  };
  Pending stack[kMaxDepth + 1];
  int top = 0;
  uint32_t child = 0;  // the root node
  // One loop, one call of visit: it is inlined once, and no call clobbers the registers
  // holding the ray.
  for (;;) {
    if (!(child & kItem)) {
      const Node& n = nodes_[child];
      Double2 entry;
      const int mask = n.boxes.hits(ray, tMin, tMax, entry);
      if (mask == 3) {  // the nearer first, the other stacked with its entry distance
        const int near = entry[1] < entry[0] ? 1 : 0;
        stack[top++] = {n.child[1 - near], entry[1 - near]};
        child = n.child[near];
        continue;
      }
      if (mask != 0) {
        child = n.child[mask >> 1];
        continue;
      }
    } else {
      tMax = visit(child & ~kItem);
      if (tMax < 0) return;
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
