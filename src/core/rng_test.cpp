#include "core/rng.h"

#include <gtest/gtest.h>

#include <set>

namespace prt {
namespace {

TEST(RngTest, SameKeySameSequence) {
  Rng a = Rng::forSample(1234, 7);
  Rng b = Rng::forSample(1234, 7);
  for (int i = 0; i < 100; ++i) EXPECT_EQ(a.uniform(), b.uniform());
}

TEST(RngTest, DifferentPixelsSamplesAndChildrenDiffer) {
  std::set<double> firsts;
  for (uint64_t pixel = 0; pixel < 50; ++pixel) {
    for (uint32_t sample = 0; sample < 4; ++sample) {
      Rng r = Rng::forSample(pixel, sample);
      firsts.insert(r.uniform());
      firsts.insert(r.child(0).uniform());
      firsts.insert(r.child(1).uniform());
    }
  }
  EXPECT_EQ(firsts.size(), 50u * 4u * 3u);
}

TEST(RngTest, UniformInUnitIntervalWithPlausibleMean) {
  Rng r(42);
  double sum = 0;
  const int n = 100000;
  for (int i = 0; i < n; ++i) {
    const double u = r.uniform();
    ASSERT_GE(u, 0.0);
    ASSERT_LT(u, 1.0);
    sum += u;
  }
  EXPECT_NEAR(sum / n, 0.5, 0.01);
}

TEST(RngTest, ChildDoesNotDependOnDrawsFromParent) {
  Rng a(9);
  Rng b(9);
  b.uniform();
  b.uniform();
  EXPECT_EQ(a.child(3).uniform(), b.child(3).uniform());
}

TEST(RngTest, SkipMovesPastAsManyDraws) {
  Rng drawn(21);
  Rng skipped(21);
  for (int i = 0; i < 5; ++i) drawn.uniform();
  skipped.skip(5);
  EXPECT_EQ(drawn.uniform(), skipped.uniform());
  skipped.skip(0);
  EXPECT_EQ(drawn.uniform(), skipped.uniform());
}

}  // namespace
}  // namespace prt
