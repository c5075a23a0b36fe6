#include "trace/quad_bvh.h"

#include <gtest/gtest.h>

#include <algorithm>

#include "core/rng.h"

namespace prt {
namespace {

std::vector<Bounds> randomBoxes(int count, uint64_t seed) {
  Rng rng(seed);
  std::vector<Bounds> boxes;
  for (int i = 0; i < count; ++i) {
    const Vec3 c(rng.uniform() * 20 - 10, rng.uniform() * 20 - 10, rng.uniform() * 20 - 10);
    Bounds b;
    b.extend(c);
    b.extend(c + Vec3(rng.uniform() * 2, rng.uniform() * 2, rng.uniform() * 2));
    if (i % 13 == 0) b.extend(c + Vec3(15, 0.2, 0.1));  // a few long, thin ones
    boxes.push_back(b);
  }
  return boxes;
}

Ray randomQuadRay(Rng& rng) {
  const Vec3 o(rng.uniform() * 30 - 15, rng.uniform() * 30 - 15, rng.uniform() * 30 - 15);
  Vec3 d(rng.uniform() - 0.5, rng.uniform() - 0.5, rng.uniform() - 0.5);
  if (rng.uniform() < 0.1) d.y = 0;  // parallel to the y slabs
  return {o, normalize(d)};
}

// Every item whose box hitsBounds accepts is visited, for each size of tree (including the
// bottom-up built small ones and the top-down built large ones).
TEST(QuadBvhTest, VisitsEveryItemWhoseBoxIsHit) {
  for (int count : {1, 2, 3, 7, 40, 300}) {
    const std::vector<Bounds> boxes = randomBoxes(count, static_cast<uint64_t>(count));
    const QuadBvh bvh(boxes);
    Rng rng(3);
    for (int i = 0; i < 500; ++i) {
      const Ray ray = randomQuadRay(rng);
      const RayQuery q(ray);
      const double tMax = rng.uniform() < 0.5 ? 1e30 : rng.uniform() * 20;
      for (const bool ordered : {false, true}) {
        std::vector<uint32_t> visited;
        auto record = [&](uint32_t item) {
          visited.push_back(item);
          return tMax;
        };
        if (ordered) {
          bvh.traverse<true>(q.ray, 0, tMax, record);
        } else {
          bvh.traverse<false>(q.ray, 0, tMax, record);
        }
        std::sort(visited.begin(), visited.end());
        EXPECT_TRUE(std::adjacent_find(visited.begin(), visited.end()) == visited.end());
        for (uint32_t item = 0; item < boxes.size(); ++item) {
          if (hitsBounds(boxes[item], q, 0, tMax)) {
            EXPECT_TRUE(std::binary_search(visited.begin(), visited.end(), item))
                << count << " items, ray " << i << ", item " << item;
          }
        }
      }
    }
  }
}

// Shrinking tMax as boxes are entered finds the nearest box entry, as brute force does, and
// a negative return stops the traversal at once.
TEST(QuadBvhTest, ShrinkingSearchFindsNearestAndStops) {
  const std::vector<Bounds> boxes = randomBoxes(200, 11);
  const QuadBvh bvh(boxes);
  Rng rng(4);
  for (int i = 0; i < 1000; ++i) {
    const RayQuery q(randomQuadRay(rng));
    double expected = 1e30;
    for (const Bounds& b : boxes) {
      // Entry distance by bisection-free brute force: the smallest t hitsBounds accepts is
      // the slab entry; a box is nearer when it is hit within (0, expected).
      if (hitsBounds(b, q, 0, expected)) {
        double lo = 0, hi = expected;
        for (int k = 0; k < 200 && hi - lo > 1e-12; ++k) {
          const double mid = 0.5 * (lo + hi);
          (hitsBounds(b, q, 0, mid) ? hi : lo) = mid;
        }
        expected = hi;
      }
    }
    double nearest = 1e30;
    bvh.traverse<true>(q.ray, 0, nearest, [&](uint32_t item) {
      double lo = 0, hi = nearest;
      if (!hitsBounds(boxes[item], q, 0, hi)) return nearest;
      for (int k = 0; k < 200 && hi - lo > 1e-12; ++k) {
        const double mid = 0.5 * (lo + hi);
        (hitsBounds(boxes[item], q, 0, mid) ? hi : lo) = mid;
      }
      nearest = hi;
      return nearest;
    });
    EXPECT_NEAR(nearest, expected, 1e-9);
    int visits = 0;
    bvh.traverse<true>(q.ray, 0, 1e30, [&](uint32_t) {
      ++visits;
      return -1.0;
    });
    EXPECT_LE(visits, 1);
  }
}

// Degenerate inputs (all boxes equal, boxes nested in a chain) keep the depth, and so the
// traversal stack, bounded.
TEST(QuadBvhTest, DepthStaysBoundedOnDegenerateInput) {
  const std::vector<Bounds> same(5000, Bounds{{0, 0, 0}, {1, 1, 1}});
  const QuadBvh a(same);
  EXPECT_LE(a.depth(), 128);
  std::vector<Bounds> nested;
  for (int i = 0; i < 3000; ++i) {
    const double s = std::ldexp(1.0, i % 60) * (1 + i * 1e-6);
    nested.push_back(Bounds{{0, 0, 0}, {s, s, s}});
  }
  const QuadBvh b(nested);
  EXPECT_LE(b.depth(), 128);
  int visits = 0;
  b.traverse<true>(Ray{{0.5, 0.5, -1}, {0, 0, 1}}, 0, 1e300, [&](uint32_t) {
    ++visits;
    return 1e300;
  });
  EXPECT_EQ(visits, 3000);
}

TEST(QuadBvhTest, EmptyAndSingle) {
  const QuadBvh empty(std::vector<Bounds>{});
  int visits = 0;
  empty.traverse<false>(Ray{{0, 0, 0}, {0, 0, 1}}, 0, 1e30, [&](uint32_t) {
    ++visits;
    return 1e30;
  });
  EXPECT_EQ(visits, 0);
  const QuadBvh one(std::vector<Bounds>{Bounds{{-1, -1, 2}, {1, 1, 3}}});
  one.traverse<true>(Ray{{0, 0, 0}, {0, 0, 1}}, 0, 1e30, [&](uint32_t item) {
    EXPECT_EQ(item, 0u);
    ++visits;
    return 1e30;
  });
  EXPECT_EQ(visits, 1);
}

// A tree of blocks holds every item once, in blocks of one to four used lanes (used first),
// and visits every block holding an item whose box is hit, each once.
TEST(QuadBvhTest, BlocksHoldEveryItemOnceAndAreVisitedWhenHit) {
  for (int count : {1, 2, 3, 4, 5, 9, 40, 300, 3000}) {
    const std::vector<Bounds> boxes = randomBoxes(count, static_cast<uint64_t>(count) + 100);
    std::vector<uint32_t> items;
    const QuadBvh bvh(boxes, items);
    ASSERT_EQ(items.size() % QuadBvh::kBlockItems, 0u);
    std::vector<int> seen(boxes.size(), 0);
    std::vector<uint32_t> blockOf(boxes.size());
    std::vector<uint32_t> used(items.size() / QuadBvh::kBlockItems, 0);
    for (size_t k = 0; k < items.size(); ++k) {
      const uint32_t block = static_cast<uint32_t>(k / QuadBvh::kBlockItems);
      if (items[k] == ~0u) continue;
      ASSERT_LT(items[k], boxes.size());
      EXPECT_EQ(used[block], k % QuadBvh::kBlockItems) << "used lanes come first";
      ++used[block];
      ++seen[items[k]];
      blockOf[items[k]] = block;
    }
    for (uint32_t n : used) EXPECT_GT(n, 0u);
    for (int n : seen) EXPECT_EQ(n, 1);
    Rng rng(9);
    for (int i = 0; i < 300; ++i) {
      const Ray ray = randomQuadRay(rng);
      const RayQuery q(ray);
      const double tMax = rng.uniform() < 0.5 ? 1e30 : rng.uniform() * 20;
      for (const bool ordered : {false, true}) {
        std::vector<uint32_t> visited;
        auto record = [&](uint32_t block, uint32_t lanes) {
          EXPECT_EQ(lanes, used[block]);
          visited.push_back(block);
          return tMax;
        };
        if (ordered) {
          bvh.traverseBlocks<true>(ray, 0, tMax, record);
        } else {
          bvh.traverseBlocks<false>(ray, 0, tMax, record);
        }
        std::sort(visited.begin(), visited.end());
        EXPECT_TRUE(std::adjacent_find(visited.begin(), visited.end()) == visited.end());
        for (uint32_t item = 0; item < boxes.size(); ++item) {
          if (hitsBounds(boxes[item], q, 0, tMax)) {
            EXPECT_TRUE(std::binary_search(visited.begin(), visited.end(), blockOf[item]))
                << count << " items, ray " << i << ", item " << item;
          }
        }
      }
    }
  }
}

}  // namespace
}  // namespace prt
