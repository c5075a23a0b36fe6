#include "cluster/task_leases.h"

#include <gtest/gtest.h>

#include <cmath>

namespace prt {
namespace {

TEST(TaskLeases, OffByDefault) {
  TaskLeases leases({}, 2);
  EXPECT_FALSE(leases.enabled());
  leases.given(0, 0, true);
  EXPECT_TRUE(leases.expired(1e9).empty());
  EXPECT_TRUE(std::isinf(leases.nextExpiry()));
}

// Until some batch has been measured there is no estimate: a lease never runs out, but is
// looked at again every least lease.
TEST(TaskLeases, NothingMeasuredNothingRunsOut) {
  TaskLeases leases({10, 1}, 2);
  leases.setSpeedIndex(0, 0.1);
  leases.given(0, 0, true);
  EXPECT_DOUBLE_EQ(leases.nextExpiry(), 1.0);
  EXPECT_TRUE(leases.expired(50).empty());
  EXPECT_DOUBLE_EQ(leases.nextExpiry(), 51.0);
}

// Ten of its expected batches, never less than the least lease: a worker whose batches take
// 0.5 s has 5 s; a fresh result renews it, a result of pixels done already does not.
TEST(TaskLeases, TenExpectedBatchesFromTheLastFreshResult) {
  TaskLeases leases({10, 1}, 2);
  leases.setSpeedIndex(0, 1);
  leases.setSpeedIndex(1, 1);
  leases.given(0, 0, true);
  leases.given(1, 0, true);
  leases.returned(0, 0.5, 0.5, true);
  EXPECT_DOUBLE_EQ(leases.leaseOf(0), 5.0);
  EXPECT_DOUBLE_EQ(leases.leaseOf(1), 5.0) << "the same speed index, the same estimate";
  leases.returned(0, 1.0, 0.5, false);  // duplicates only: measured, but no renewal
  EXPECT_TRUE(leases.expired(4.9).empty());
  EXPECT_EQ(leases.expired(5.6), std::vector<int>({0, 1})) << "0 from 0.5 s, 1 from 0 s";
  EXPECT_TRUE(std::isinf(leases.nextExpiry())) << "taken off until given tasks again";
  // Given tasks while holding nothing: the lease starts again then.
  leases.given(0, 7, true);
  EXPECT_DOUBLE_EQ(leases.nextExpiry(), 12.0);
  leases.given(0, 9, false);  // more while busy: no renewal
  EXPECT_DOUBLE_EQ(leases.nextExpiry(), 12.0);
  leases.renew(0, 10);        // spot checks returned
  EXPECT_DOUBLE_EQ(leases.nextExpiry(), 15.0);
  leases.drop(0);
  EXPECT_TRUE(leases.expired(100).empty());
}

// A slower batch anywhere lengthens everyone's lease, scaled by speed index; the leases armed
// before are looked at again, not found out early.
TEST(TaskLeases, EstimatesGrowAndAreAppliedWhenALeaseRunsOut) {
  TaskLeases leases({10, 1}, 3);
  leases.setSpeedIndex(0, 1);
  leases.setSpeedIndex(1, 1);
  leases.setSpeedIndex(2, 4);  // four times slower by its speed index
  for (int w = 0; w < 3; ++w) leases.given(w, 0, true);
  leases.returned(0, 0.2, 0.2, true);
  EXPECT_DOUBLE_EQ(leases.leaseOf(2), 8.0) << "0.2 s per speed second, times 4, times 10";
  EXPECT_DOUBLE_EQ(leases.leaseOf(1), 2.0);
  leases.returned(0, 3.2, 3.0, true);  // a costly part of the image: 3 s
  EXPECT_DOUBLE_EQ(leases.leaseOf(1), 30.0);
  EXPECT_TRUE(leases.expired(20).empty()) << "armed with no estimate, found to be 30 s when looked at";
  EXPECT_EQ(leases.expired(30.5), std::vector<int>({1}));
}

// What a worker says its batch took is capped by how long the master waited for it: it
// cannot lengthen its lease, or anyone's, by its word alone.
TEST(TaskLeases, AClaimedBatchTimeIsCappedByTheWait) {
  TaskLeases leases({10, 1}, 2);
  leases.setSpeedIndex(0, 1);
  leases.setSpeedIndex(1, 1);
  leases.given(0, 0, true);
  leases.given(1, 0, true);
  leases.returned(0, 0.1, 1e300, true);
  EXPECT_DOUBLE_EQ(leases.leaseOf(0), 1.0) << "0.1 s measured, ten of them: the least lease";
  leases.returned(0, 0.2, std::nan(""), true);
  EXPECT_DOUBLE_EQ(leases.leaseOf(1), 1.0);
}

// A speed index is the worker's word: one that claims to be a million times slower gets no
// lease without end, nor does a claim of great speed followed by a slow batch lengthen the
// others' leases past kSpeedSpread times the longest batch returned.
TEST(TaskLeases, AClaimedSpeedIndexBuysAtMostTenTimesTheLongestBatch) {
  TaskLeases leases({10, 1}, 3);
  leases.setSpeedIndex(0, 1);
  leases.setSpeedIndex(1, 1e6);   // claims to be very slow
  leases.setSpeedIndex(2, 1e-6);  // claims to be very fast
  for (int w = 0; w < 3; ++w) leases.given(w, 0, true);
  leases.returned(0, 0.5, 0.5, true);
  EXPECT_DOUBLE_EQ(leases.leaseOf(1), 50.0) << "10 batches of at most 10 x 0.5 s";
  leases.returned(2, 1.0, 1.0, true);  // 1 s for a worker of speed index 1e-6
  EXPECT_DOUBLE_EQ(leases.leaseOf(0), 100.0) << "10 batches of at most 10 x 1 s, not 10^7 s";
  EXPECT_DOUBLE_EQ(leases.leaseOf(2), 10.0) << "its own batch counts in full";
  EXPECT_EQ(leases.expired(1.0 + 100.0), std::vector<int>({0, 1, 2}));
}

// A lease the master does not act on is looked at again when it says, from the same start;
// a fresh result is remembered for the master to compare.
TEST(TaskLeases, APostponedLeaseIsLookedAtAgainFromTheSameStart) {
  TaskLeases leases({10, 1}, 1);
  leases.setSpeedIndex(0, 1);
  leases.given(0, 0, true);
  EXPECT_EQ(leases.lastFresh(0), -std::numeric_limits<double>::infinity());
  leases.returned(0, 0.1, 0.1, true);
  EXPECT_DOUBLE_EQ(leases.lastFresh(0), 0.1);
  EXPECT_EQ(leases.expired(1.2), std::vector<int>({0}));
  leases.postpone(0, 1.2, 1.0);
  EXPECT_DOUBLE_EQ(leases.nextExpiry(), 2.2);
  EXPECT_DOUBLE_EQ(leases.since(0), 0.1);
  EXPECT_EQ(leases.expired(2.2), std::vector<int>({0}));
}

}  // namespace
}  // namespace prt
