#include "trace/shadow_shafts.h"

#include <gtest/gtest.h>

#include <algorithm>

#include "core/rng.h"

namespace prt {
namespace {

Bounds box(const Vec3& lo, const Vec3& hi) {
  Bounds b;
  b.lo = lo;
  b.hi = hi;
  return b;
}

Vec3 pointIn(const Bounds& b, Rng& rng) {
  return b.lo + Vec3(rng.uniform(), rng.uniform(), rng.uniform()) * b.diagonal();
}

// Whether the segment from p to q passes through box b (its interior or boundary).
bool segmentMeets(const Vec3& p, const Vec3& q, const Bounds& b) {
  const Vec3 d = q - p;
  const double length = prt::length(d);
  if (length == 0) return hitsBounds(b, RayQuery(Ray{p, {1, 0, 0}}), 0, 0);
  return hitsBounds(b, RayQuery(Ray{p, d / length}), 0, length);
}

Bounds randomBox(Rng& rng, double span, double size) {
  const Vec3 lo(rng.uniform() * span - span / 2, rng.uniform() * span - span / 2,
                rng.uniform() * span - span / 2);
  return box(lo, lo + Vec3(rng.uniform(), rng.uniform(), rng.uniform()) * size);
}

TEST(ShaftTest, MeetsWhatLiesBetweenTheBoxes) {
  const Shaft shaft(box({0, 0, 0}, {1, 1, 1}), box({10, 0, 0}, {11, 1, 1}));
  EXPECT_TRUE(shaft.meets(box({5, 0.4, 0.4}, {5.2, 0.6, 0.6})));  // in the middle
  EXPECT_TRUE(shaft.meets(box({-1, -1, -1}, {0.1, 0.1, 0.1})));   // overlapping an end
  EXPECT_TRUE(shaft.meets(box({5, 1, 0}, {6, 2, 1})));            // touching a side
  EXPECT_FALSE(shaft.meets(box({5, 1.1, 0}, {6, 2, 1})));         // just beside it
  EXPECT_FALSE(shaft.meets(box({12, 0, 0}, {13, 1, 1})));         // beyond the far end
}

TEST(ShaftTest, SeparatesBoxesBesideADiagonalShaft) {
  // A shaft running diagonally: the box sits inside its bounding box, off the shaft.
  const Shaft shaft(box({0, 0, 0}, {1, 1, 1}), box({10, 10, 0}, {11, 11, 1}));
  EXPECT_FALSE(shaft.meets(box({8, 1, 0}, {9, 2, 1})));
  EXPECT_FALSE(shaft.meets(box({1, 8, 0}, {2, 9, 1})));
  EXPECT_TRUE(shaft.meets(box({5, 5, 0}, {6, 6, 1})));
  // Diagonal in all three axes.
  const Shaft steep(box({0, 0, 0}, {1, 1, 1}), box({10, 10, 10}, {11, 11, 11}));
  EXPECT_FALSE(steep.meets(box({8, 1, 4}, {9, 2, 5})));
  EXPECT_TRUE(steep.meets(box({5, 5, 5}, {5.5, 5.5, 5.5})));
}

TEST(ShaftTest, NeverMissesABoxASegmentCrosses) {
  Rng rng(11);
  int separated = 0, met = 0;
  for (int i = 0; i < 3000; ++i) {
    const Bounds from = randomBox(rng, 10, 2), to = randomBox(rng, 10, 3);
    const Shaft shaft(from, to);
    for (int j = 0; j < 20; ++j) {
      const Bounds b = randomBox(rng, 12, 2);
      if (shaft.meets(b)) {
        ++met;
        continue;
      }
      ++separated;
      for (int k = 0; k < 20; ++k) {
        ASSERT_FALSE(segmentMeets(pointIn(from, rng), pointIn(to, rng), b))
            << "shaft " << i << " box " << j;
      }
    }
  }
  EXPECT_GT(separated, 10000);
  EXPECT_GT(met, 1500);
}

TEST(ShaftTest, IsExactForSegmentsBetweenPoints) {
  // With point-sized ends the hull is the segment: boxes near it are separated unless the
  // segment really crosses them.
  Rng rng(5);
  int crossing = 0;
  for (int i = 0; i < 20000; ++i) {
    const Vec3 p = pointIn(box({-5, -5, -5}, {5, 5, 5}), rng);
    const Vec3 q = pointIn(box({-5, -5, -5}, {5, 5, 5}), rng);
    const Bounds b = randomBox(rng, 8, 3);
    const bool crosses = segmentMeets(p, q, b);
    crossing += crosses;
    Bounds from, to;
    from.extend(p);
    to.extend(q);
    EXPECT_EQ(Shaft(from, to).meets(b), crosses) << i;
  }
  EXPECT_GT(crossing, 400);
}

// Items on a lattice, lights of every kind as boxes.
struct Layout {
  std::vector<Bounds> items, lights;
};

Layout layout() {
  Layout l;
  Rng rng(3);
  for (int i = 0; i < 40; ++i) l.items.push_back(randomBox(rng, 8, 1.5));
  l.items.push_back(box({-6, -0.5, -6}, {6, 0, 6}));  // a wide slab under everything
  l.lights.push_back(box({0, 9, 0}, {0, 9, 0}));      // a point
  l.lights.push_back(box({-4, 7, -4}, {-3, 8, -3}));  // a sphere's box
  l.lights.push_back(box({5, 3, -1}, {5, 5, 1}));     // a rectangle beside the items
  return l;
}

TEST(ShadowShaftsTest, ListsEveryItemASegmentToTheLightCrosses) {
  const Layout l = layout();
  const ShadowShafts shafts(l.items, l.lights, 6);
  EXPECT_GT(shafts.cellCount(), 1000u);
  Rng rng(8);
  int listed = 0, empty = 0;
  for (int i = 0; i < 30000; ++i) {
    const size_t light = i % l.lights.size();
    const Vec3 origin = pointIn(box({-5, -1, -5}, {5, 5, 5}), rng);
    const auto candidates = shafts.candidates(light, origin);
    if (!candidates) continue;
    ++listed;
    empty += candidates->empty();
    EXPECT_LE(candidates->size(), 6u);
    for (int k = 0; k < 4; ++k) {
      const Vec3 target = pointIn(l.lights[light], rng);
      for (uint32_t item = 0; item < l.items.size(); ++item) {
        if (segmentMeets(origin, target, l.items[item])) {
          EXPECT_NE(std::find(candidates->begin(), candidates->end(), item), candidates->end())
              << "origin " << i << " item " << item;
        }
      }
    }
  }
  EXPECT_GT(listed, 10000);
  EXPECT_GT(empty, 1000);
}

TEST(ShadowShaftsTest, SendsRaysFromOutsideTheGridToTheBvh) {
  const Layout l = layout();
  const ShadowShafts shafts(l.items, l.lights);
  EXPECT_FALSE(shafts.candidates(0, {100, 0, 0}));
  EXPECT_FALSE(shafts.candidates(0, {0, -50, 0}));
  EXPECT_FALSE(shafts.candidates(1, {0, 0, 1e300}));
  const double nan = std::numeric_limits<double>::quiet_NaN();
  EXPECT_FALSE(shafts.candidates(2, {nan, 0, 0}));
  // No items, no lights: no grid at all.
  EXPECT_FALSE(ShadowShafts({}, l.lights).candidates(0, {0, 0, 0}));
  EXPECT_FALSE(ShadowShafts(l.items, {}).candidates(0, {0, 0, 0}));
  EXPECT_EQ(ShadowShafts({}, l.lights).cellCount(), 0u);
}

TEST(ShadowShaftsTest, LeavesLongListsToTheBvh) {
  // Forty boxes stacked between the floor and the light: every list would be long.
  std::vector<Bounds> items;
  for (int i = 0; i < 40; ++i) items.push_back(box({-1, 0.1 * i, -1}, {1, 0.1 * i + 0.05, 1}));
  const ShadowShafts shafts(items, {box({0, 10, 0}, {0, 10, 0})});
  EXPECT_FALSE(shafts.candidates(0, {0, 0.01, 0}));
  // With a limit above the count, the lists are given.
  const ShadowShafts generous(items, {box({0, 10, 0}, {0, 10, 0})}, 100);
  const auto all = generous.candidates(0, {0, 0.01, 0});
  ASSERT_TRUE(all);
  EXPECT_EQ(all->size(), 40u);
}

TEST(ShadowShaftsTest, ScenesOfManyObjectsKeepTheBvh) {
  // Small boxes scattered over a field: with up to kCrowded of them, most shadow rays get a
  // list; with more, the whole grid is crowded at its root and every ray goes to the BVH.
  auto scattered = [](int count) {
    Rng rng(12);
    std::vector<Bounds> items;
    for (int i = 0; i < count; ++i) {
      const Vec3 lo(rng.uniform() * 20 - 10, rng.uniform() * 4, rng.uniform() * 20 - 10);
      items.push_back(box(lo, lo + Vec3(0.3)));
    }
    return items;
  };
  const std::vector<Bounds> light = {box({0, 20, 0}, {1, 20, 1})};
  const ShadowShafts some(scattered(200), light), many(scattered(300), light);
  Rng rng(13);
  int listed = 0;
  for (int i = 0; i < 1000; ++i) {
    const Vec3 origin(rng.uniform() * 20 - 10, rng.uniform() * 4, rng.uniform() * 20 - 10);
    listed += some.candidates(0, origin).has_value();
    EXPECT_FALSE(many.candidates(0, origin));
  }
  EXPECT_GT(listed, 500);
}

TEST(ShadowShaftsTest, FlatScenesGetAFlatGrid) {
  // Everything in the plane y = 0: the grid is one cell thick and the others share the cells.
  std::vector<Bounds> items;
  for (int i = 0; i < 10; ++i) items.push_back(box({1.0 * i, 0, 0}, {1.0 * i + 0.5, 0, 3}));
  const ShadowShafts shafts(items, {box({5, 0, 5}, {5, 0, 5})});
  EXPECT_GT(shafts.cellCount(), ShadowShafts::kCells / 2);
  EXPECT_LE(shafts.cellCount(), 2 * ShadowShafts::kCells);
  EXPECT_TRUE(shafts.candidates(0, {2.2, 0, 1}));
}

TEST(ShadowShaftsTest, ManyLightsGetFewerCells) {
  // Every cell keeps a list per light: with 64 lights the grid is coarser, its lists as many
  // as with four lights (or fewer), and still answers for each light.
  std::vector<Bounds> items;
  for (int i = 0; i < 10; ++i) items.push_back(box({1.0 * i, 0, 0}, {1.0 * i + 0.5, 1, 3}));
  std::vector<Bounds> four, many;
  for (int l = 0; l < 64; ++l) {
    const Bounds light = box({0.15 * l, 8, -2}, {0.15 * l + 0.1, 8.1, -1.9});
    many.push_back(light);
    if (l < 4) four.push_back(light);
  }
  const ShadowShafts fine(items, four), coarse(items, many);
  EXPECT_GT(fine.cellCount(), ShadowShafts::kCells / 2);
  EXPECT_LE(coarse.cellCount() * many.size(), 2 * fine.cellCount() * four.size());
  EXPECT_GT(coarse.cellCount(), ShadowShafts::kFewestCells / 2);
  for (size_t l = 0; l < many.size(); l += 21) EXPECT_TRUE(coarse.candidates(l, {2.2, 0.5, 1}));
}

}  // namespace
}  // namespace prt
