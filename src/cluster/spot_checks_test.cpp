#include "cluster/spot_checks.h"

#include <gtest/gtest.h>

#include <cstring>

namespace prt {
namespace {

std::vector<float> colours(const TaskSet& tasks) {  // a "render": pixel p is (p, p/2, 1)
  std::vector<float> rgb;
  tasks.forEach([&](uint64_t p) {
    rgb.insert(rgb.end(), {static_cast<float>(p), static_cast<float>(p) / 2, 1.0f});
  });
  return rgb;
}

TEST(SpotChecksTest, ANewWorkerIsCheckedInEveryBatchThenAtTheRate) {
  SpotChecks checks({1.0, 7}, 3);
  checks.setEligible(0, true);
  checks.setEligible(1, true);
  EXPECT_DOUBLE_EQ(checks.rateFor(0), 0.04);
  // Tiny batches: at 4 % almost none would be drawn, but a new worker's batch gives one.
  for (uint64_t b = 0; b < 3; ++b) {
    const TaskSet batch = TaskSet::range(10 * b, 5);
    EXPECT_GE(checks.sample(0, batch, colours(batch)), 1u);
  }
  ASSERT_EQ(checks.checkersWaiting(), std::vector<int>{1}) << "the other eligible worker";
  const TaskSet sent = checks.take(1);
  EXPECT_GE(sent.size(), 3u);
  EXPECT_TRUE(checks.checkersWaiting().empty());
  EXPECT_TRUE(checks.results(1, sent, colours(sent)).empty());
  EXPECT_TRUE(checks.idle());
  EXPECT_EQ(checks.verifiedPixels(), sent.size());
  EXPECT_GE(checks.passes(0), SpotChecks::kNewPasses);
  EXPECT_DOUBLE_EQ(checks.rateFor(0), 0.01);
  // Regular: about 1 % of a large batch, the same pixels for the same seed.
  const TaskSet big = TaskSet::range(1000, 100000);
  const uint64_t n = checks.sample(0, big, colours(big));
  EXPECT_GT(n, 800u);
  EXPECT_LT(n, 1200u);
  const TaskSet taken = checks.take(1);
  SpotChecks other({1.0, 7}, 3);
  other.setEligible(1, true);
  for (int i = 0; i < SpotChecks::kNewPasses; ++i) {
    other.sample(0, TaskSet::range(static_cast<uint64_t>(i), 1),
                 colours(TaskSet::range(static_cast<uint64_t>(i), 1)));
  }
  const TaskSet first = other.take(1);
  other.results(1, first, colours(first));
  other.sample(0, big, colours(big));
  EXPECT_EQ(other.take(1), taken) << "the sample depends on the seed and the standing only";
  SpotChecks reseeded({1.0, 8}, 3);
  reseeded.setEligible(1, true);
  for (int i = 0; i < SpotChecks::kNewPasses; ++i) {
    const TaskSet px = TaskSet::range(static_cast<uint64_t>(i), 1);
    reseeded.sample(0, px, colours(px));
  }
  const TaskSet seeded = reseeded.take(1);
  reseeded.results(1, seeded, colours(seeded));
  reseeded.sample(0, big, colours(big));
  EXPECT_NE(reseeded.take(1), taken) << "another seed, other pixels";
}

TEST(SpotChecksTest, AMismatchIsReturnedAndAMatchIsAPass) {
  SpotChecks checks({100, 1}, 2);
  checks.setEligible(0, true);
  checks.setEligible(1, true);
  const TaskSet batch = TaskSet::range(0, 4);
  EXPECT_EQ(checks.sample(0, batch, colours(batch)), 4u) << "100 %: every pixel";
  const TaskSet sent = checks.take(1);
  std::vector<float> rendered = colours(sent);
  uint32_t bits;
  std::memcpy(&bits, &rendered[3 * 2], 4);
  bits ^= 1u;  // one bit of pixel 2's red
  std::memcpy(&rendered[3 * 2], &bits, 4);
  const std::vector<Disagreement> d = checks.results(1, sent, rendered);
  ASSERT_EQ(d.size(), 1u);
  EXPECT_EQ(d[0].pixel, 2u);
  EXPECT_EQ(d[0].author, 0);
  EXPECT_EQ(d[0].checker, 1);
  EXPECT_EQ(d[0].authorRgb[0], 2.0f);
  EXPECT_NE(d[0].checkerRgb[0], 2.0f);
  EXPECT_EQ(checks.verifiedPixels(), 3u);
  EXPECT_TRUE(checks.idle());
  // A result nobody asked for is ignored.
  EXPECT_TRUE(checks.results(1, TaskSet::range(0, 1), {9, 9, 9}).empty());
}

TEST(SpotChecksTest, WithNoOtherWorkerTheRefereeChecks) {
  SpotChecks checks({100, 1}, 2);
  checks.setEligible(0, true);
  const TaskSet batch = TaskSet::range(5, 2);
  checks.sample(0, batch, colours(batch));
  ASSERT_EQ(checks.checkersWaiting(), std::vector<int>{SpotChecks::kReferee});
  const TaskSet sent = checks.take(SpotChecks::kReferee);
  EXPECT_TRUE(checks.results(SpotChecks::kReferee, sent, colours(sent)).empty());
  EXPECT_EQ(checks.refereeChecks(), 2u);
}

TEST(SpotChecksTest, AGoneCheckersChecksMoveAndARejectedAuthorsAreDropped) {
  SpotChecks checks({100, 1}, 3);
  for (int w = 0; w < 3; ++w) checks.setEligible(w, true);
  const TaskSet a = TaskSet::range(0, 6), b = TaskSet::range(10, 6);
  checks.sample(0, a, colours(a));
  checks.sample(1, b, colours(b));
  // Each pixel went to one of the others in turn; take every list (all sent).
  TaskSet sentTo2 = checks.take(2);
  checks.take(1);
  checks.take(0);
  ASSERT_FALSE(sentTo2.empty());
  EXPECT_EQ(checks.openChecks(), 12u);
  checks.workerGone(2, false);  // lost: what it was to check goes to someone else
  EXPECT_EQ(checks.openChecks(), 12u);
  EXPECT_TRUE(checks.results(2, sentTo2, colours(sentTo2)).empty()) << "no longer its checks";
  EXPECT_EQ(checks.verifiedPixels(), 0u);
  EXPECT_FALSE(checks.checkersWaiting().empty());
  checks.workerGone(0, true);  // rejected: its own pixels are taken back, their checks dropped
  for (const int c : std::vector<int>(checks.checkersWaiting())) {
    EXPECT_NE(c, 0);
    EXPECT_NE(c, 2);
  }
  uint64_t left = 0;
  for (const int c : std::vector<int>(checks.checkersWaiting())) {
    const TaskSet t = checks.take(c);
    t.forEach([&](uint64_t p) { EXPECT_GE(p, 10u) << "worker 0's pixel " << p; });
    checks.results(c, t, colours(t));
    left += t.size();
  }
  EXPECT_TRUE(checks.idle()) << checks.openChecks() << " open after " << left;
}

TEST(SpotChecksTest, AnUnansweredCheckGoesToTheRefereeAfterItsTime) {
  SpotChecks checks({100, 1}, 2);
  checks.setEligible(0, true);
  checks.setEligible(1, true);
  const TaskSet batch = TaskSet::range(0, 2);
  checks.sample(0, batch, colours(batch));
  const TaskSet sent = checks.take(1, 10.0);
  EXPECT_EQ(checks.expire(14.0, 5.0), 0u) << "not overdue yet";
  EXPECT_EQ(checks.expire(15.5, 5.0), 2u);
  ASSERT_EQ(checks.checkersWaiting(), std::vector<int>{SpotChecks::kReferee});
  EXPECT_TRUE(checks.results(1, sent, colours(sent)).empty()) << "a late answer is ignored";
  EXPECT_EQ(checks.verifiedPixels(), 0u);
  const TaskSet mine = checks.take(SpotChecks::kReferee, 16.0);
  EXPECT_EQ(mine, sent);
  checks.results(SpotChecks::kReferee, mine, colours(mine));
  EXPECT_TRUE(checks.idle());
  EXPECT_EQ(checks.expire(100, 5.0), 0u) << "the referee's own are never overdue";
}

TEST(SpotChecksTest, OffChecksNothing) {
  SpotChecks checks({0, 1}, 2);
  EXPECT_FALSE(checks.enabled());
  checks.setEligible(1, true);
  const TaskSet batch = TaskSet::range(0, 100);
  EXPECT_EQ(checks.sample(0, batch, colours(batch)), 0u);
  EXPECT_TRUE(checks.idle());
}

}  // namespace
}  // namespace prt
