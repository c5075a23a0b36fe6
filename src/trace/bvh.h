#pragma once
// Bvh: a bounding volume hierarchy over the bounded objects of a scene (binned SAH build,
// flattened depth-first layout). Beyond the paper, which tests every object's box in turn:
// with it, a scene of thousands of objects costs a few dozen box tests per ray.
// World now traverses the faster QuadBvh, and keeps this tree's visit order (visitOrder) as
// the order that decides equal distances and products of transmissivities, so that images
// stay as they were.
// Built once, then read-only: safe to query from many threads.

#include <cstdint>
#include <vector>

#include "trace/bounds.h"

namespace prt {

class Bvh {
 public:
  Bvh() = default;
  // `bounds[i]` is the box of item i; items are referred to by their index.
  explicit Bvh(const std::vector<Bounds>& bounds);

  // Calls visit(item) for every item whose node boxes the ray meets within (tMin, tMax()).
  // visit returns the new tMax (to shrink the search for the nearest hit) or a negative value
  // to stop the traversal (any-hit queries).
  template <typename Visit>
  void traverse(const RayQuery& q, double tMin, double tMax, Visit&& visit) const;

  size_t nodeCount() const { return nodes_.size(); }

  // The order in which `traverse` visits the items of the leaves it reaches, for a ray whose
  // direction is negative along the axes whose bits (1: x, 2: y, 4: z) are set in `octant`:
  // child order depends on nothing else.
  std::vector<uint32_t> visitOrder(int octant) const;

 private:
  struct Node {
    Bounds box;
    uint32_t firstOrSecondChild = 0;  // leaf: first index into items_; inner: second child
    uint16_t itemCount = 0;           // 0 for inner nodes
    uint16_t axis = 0;                // split axis of inner nodes, for front-to-back order
  };
  uint32_t build(const std::vector<Bounds>& bounds, uint32_t begin, uint32_t end);

  std::vector<Node> nodes_;
  std::vector<uint32_t> items_;
};

template <typename Visit>
void Bvh::traverse(const RayQuery& q, double tMin, double tMax, Visit&& visit) const {
  if (nodes_.empty()) return;
  uint32_t stack[64];
  int top = 0;
  uint32_t node = 0;
  for (;;) {
    const Node& n = nodes_[node];
    if (hitsBounds(n.box, q, tMin, tMax)) {
      if (n.itemCount > 0) {
        for (uint32_t i = 0; i < n.itemCount; ++i) {
          tMax = visit(items_[n.firstOrSecondChild + i]);
          if (tMax < 0) return;
        }
      } else {
        // Visit the child on the ray's side of the split first.
        const bool reversed = q.ray.direction[n.axis] < 0;
        stack[top++] = reversed ? node + 1 : n.firstOrSecondChild;
        node = reversed ? n.firstOrSecondChild : node + 1;
        continue;
      }
    }
    if (top == 0) return;
    node = stack[--top];
  }
}

}  // namespace prt
