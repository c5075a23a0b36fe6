// Each item kind of World's loops against its shape's own intersect(): the first crossing, its
// normal and the crossings a shadow ray counts, bit for bit, for rays from everywhere; and the
// dispatch finds each kind by its index.

#include "trace/world_items.h"

#include <gtest/gtest.h>

#include <cmath>

#include "core/rng.h"

namespace prt {
namespace {

Ray randomItemsRay(Rng& rng) {
  auto coordinate = [&] { return 8 * rng.uniform() - 4; };
  const Vec3 origin(coordinate(), coordinate(), coordinate());
  const Vec3 towards(rng.uniform() - 0.5, rng.uniform() - 0.5, rng.uniform() - 0.5);
  return {origin, normalize(Vec3(coordinate(), coordinate(), coordinate()) * 0.5 + towards -
                            origin * 0.25)};
}

template <typename Kind, typename ShapeT>
void expectAgreesWithIntersect(const WorldItem& item, const ShapeT& shape) {
  Rng rng(7);
  int hits = 0;
  for (int i = 0; i < 20000; ++i) {
    const Ray ray = randomItemsRay(rng);
    const double tMin = rng.uniform() < 0.5 ? 0.0 : rng.uniform();
    const Crossings all = intersect(shape, ray, tMin, INFINITY);
    uint32_t triangle = 0;
    const double t = Kind::firstAfter(item, ray, tMin, INFINITY, triangle);
    if (all.count == 0) {
      EXPECT_TRUE(std::isnan(t)) << i;
      continue;
    }
    ++hits;
    ASSERT_EQ(t, all.t[0]) << i;
    const Vec3 n = Kind::normal(item, ray, t, triangle);
    EXPECT_EQ(n.x, all.normal[0].x) << i;
    EXPECT_EQ(n.y, all.normal[0].y) << i;
    EXPECT_EQ(n.z, all.normal[0].z) << i;
    const double distance = 6 * rng.uniform();
    EXPECT_EQ(Kind::crossings(item, ray, tMin, distance),
              intersect(shape, ray, tMin, distance).count)
        << i;
  }
  EXPECT_GT(hits, 1000);  // the rays do meet the shape
}

TEST(WorldItems, ASphereItemCrossesAsTheSphereDoes) {
  const SphereShape s{{0.3, -0.2, 0.5}, 1.7};
  const WorldItem item{s.center, Vec3(s.radius, 1.0 / s.radius, 0), boundsOf(s), 0, 0,
                       itemKind<SphereItem>()};
  expectAgreesWithIntersect<SphereItem>(item, s);
}

TEST(WorldItems, ABoxItemCrossesAsTheBoxDoes) {
  const BoxShape b{{-1, -0.5, -2}, {1.5, 2, 0.5}};
  const WorldItem item{b.min, b.max, boundsOf(b), 0, 0, itemKind<BoxItem>()};
  expectAgreesWithIntersect<BoxItem>(item, b);
}

TEST(WorldItems, TheDispatchFindsEachKindByItsIndex) {
  auto name = [](uint8_t kind) {
    return visitItemKind(kind, []<typename Kind>(Kind) -> int {
      if constexpr (std::is_same_v<Kind, SphereItem>) return 1;
      if constexpr (std::is_same_v<Kind, BoxItem>) return 2;
      if constexpr (std::is_same_v<Kind, MeshItem>) return 3;
      return 0;
    });
  };
  EXPECT_EQ(name(itemKind<SphereItem>()), 1);
  EXPECT_EQ(name(itemKind<BoxItem>()), 2);
  EXPECT_EQ(name(itemKind<MeshItem>()), 3);
  EXPECT_EQ(name(std::tuple_size_v<ItemKinds>), 0);  // none: the result's default
}

}  // namespace
}  // namespace prt
