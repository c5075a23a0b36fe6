// The ledger alone, with scripted holdings, losses, lease expiries and duplicates: no
// transport, no clock.

#include "cluster/ledger.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <random>
#include <vector>

namespace prt {
namespace {

TEST(LedgerTest, ResultsAreAcceptedOnceAndDuplicatesCounted) {
  Ledger ledger(2, 10);
  ledger.gave(0, TaskSet::range(0, 6));
  ledger.gave(1, TaskSet::range(4, 6));  // 4 and 5 held twice (an endgame copy)
  EXPECT_EQ(ledger.accept(1, TaskSet::range(4, 3)), TaskSet::range(4, 3));
  EXPECT_EQ(ledger.accept(0, TaskSet::range(0, 6)), TaskSet::range(0, 4));
  EXPECT_EQ(ledger.duplicates(), 2u);
  EXPECT_EQ(ledger.doneCount(), 7u);
  EXPECT_FALSE(ledger.holdsWork(0));
  EXPECT_TRUE(ledger.holdsWork(1));
  EXPECT_EQ(ledger.unfinished(1), TaskSet::range(7, 3));
  EXPECT_FALSE(ledger.complete());
  ledger.accept(1, TaskSet::range(7, 3));
  EXPECT_TRUE(ledger.complete());
  EXPECT_EQ(ledger.doneSet(), TaskSet::range(0, 10));
}

TEST(LedgerTest, AWorkersAcceptedTasksAreTakenBackAndNothingElse) {
  Ledger ledger(3, 12);
  ledger.seedDone(TaskSet::range(0, 2));  // resumed: never taken back
  ledger.gave(0, TaskSet::range(2, 10));
  ledger.gave(1, TaskSet::range(6, 6));  // copies of 6..11
  ledger.accept(0, TaskSet::range(2, 5));  // 2..6
  ledger.accept(1, TaskSet::range(6, 3));  // 6 a duplicate; 7, 8 its own
  ledger.accept(0, TaskSet::range(9, 2));  // 9, 10
  EXPECT_EQ(ledger.ownerOf(0), Ledger::kResumed);
  EXPECT_EQ(ledger.ownerOf(6), 0);
  EXPECT_EQ(ledger.ownerOf(7), 1);
  EXPECT_EQ(ledger.doneCount(), 11u);
  TaskSet expected = TaskSet::range(2, 5);
  expected.append(TaskSet::range(9, 2));
  EXPECT_EQ(ledger.takeBack(0), expected);
  EXPECT_EQ(ledger.doneCount(), 4u);
  EXPECT_EQ(ledger.acceptedFrom(0), 0u);
  EXPECT_EQ(ledger.acceptedFrom(1), 2u);
  EXPECT_EQ(ledger.takenBackTasks(), 7u);
  EXPECT_FALSE(ledger.isDone(6));
  EXPECT_TRUE(ledger.isDone(0));
  // Worker 1 still holds 6, 9, 10 and 11 unfinished: they count as its own again.
  EXPECT_EQ(ledger.unfinished(1).toVector(), (std::vector<uint64_t>{6, 9, 10, 11}));
  EXPECT_TRUE(ledger.takeBack(0).empty());
  // A result for a taken-back task is accepted again, from anyone.
  EXPECT_EQ(ledger.accept(2, TaskSet::range(2, 1)), TaskSet::range(2, 1));
}

TEST(LedgerTest, ALostWorkersUnfinishedTasksLeaveOutWhatItMovedAndWhatIsDone) {
  Ledger ledger(3, 20);
  ledger.gave(0, TaskSet::range(0, 10));
  ledger.movedOut(0, TaskSet::range(7, 3));  // diffusion: 7..9 went to worker 2
  ledger.gave(2, TaskSet::range(7, 3));
  ledger.accept(0, TaskSet::range(0, 2));
  ledger.accept(1, TaskSet::range(3, 1));  // someone else finished 3 (a reissue raced)
  const TaskSet left = ledger.markLost(0, 4.5, "connection dropped");
  EXPECT_EQ(left.toVector(), (std::vector<uint64_t>{2, 4, 5, 6}));
  EXPECT_FALSE(ledger.isLive(0));
  EXPECT_EQ(ledger.liveCount(), 2);
  ASSERT_EQ(ledger.losses().size(), 1u);
  EXPECT_EQ(ledger.losses()[0].reason, "connection dropped");
  EXPECT_EQ(ledger.losses()[0].atSeconds, 4.5);
  EXPECT_EQ(ledger.losses()[0].unfinished, 4u);
  EXPECT_EQ(ledger.reissuedTasks(), 4u);
  // A late result from the lost worker still counts where it is the first.
  EXPECT_EQ(ledger.accept(0, TaskSet::range(2, 2)), TaskSet::range(2, 1));
}

// Stolen, then back: worker 0's tasks 7..9 went to worker 2, worker 2 was lost before it
// rendered them, and the strategy handed them to worker 0 again. Worker 0 owes them once more
// (a loss of worker 0 that left them out would leave them undone for ever), and once each,
// however often they reached it.
TEST(LedgerTest, TasksThatCameBackToAWorkerTheyLeftAreOwedByItOnce) {
  Ledger ledger(3, 20);
  ledger.gave(0, TaskSet::range(0, 10));
  ledger.movedOut(0, TaskSet::range(7, 3));
  ledger.gave(2, TaskSet::range(7, 3));
  EXPECT_EQ(ledger.markLost(2, 1.0, "lost").toVector(), (std::vector<uint64_t>{7, 8, 9}));
  ledger.gave(0, TaskSet::range(8, 2));
  ledger.accept(0, TaskSet::range(0, 7));
  EXPECT_EQ(ledger.unfinishedCount(0), 2u);
  EXPECT_EQ(ledger.unfinishedTail(0, 1).toVector(), (std::vector<uint64_t>{9}));
  EXPECT_EQ(ledger.markLost(0, 2.0, "lost").toVector(), (std::vector<uint64_t>{8, 9}));
}

// A task given twice without a move between (a copy, or one undone again when the worker that
// first rendered it was rejected) is listed once among what is owed.
TEST(LedgerTest, ATaskGivenTwiceIsOwedOnce) {
  Ledger ledger(2, 10);
  ledger.gave(0, TaskSet::range(0, 4));
  ledger.gave(1, TaskSet::range(3, 1));  // an end-game copy of task 3
  ledger.accept(1, TaskSet::range(3, 1));
  ledger.takeBack(1);  // worker 1 rejected: task 3 undone again
  ledger.gave(0, TaskSet::range(3, 1));
  EXPECT_EQ(ledger.unfinished(0).toVector(), (std::vector<uint64_t>{0, 1, 2, 3}));
  EXPECT_EQ(ledger.unfinishedCount(0), 4u);
  EXPECT_EQ(ledger.unfinishedTail(0, 2).toVector(), (std::vector<uint64_t>{2, 3}));
}

TEST(LedgerTest, LeasesExpireOnlyForLiveSilentWorkers) {
  Ledger ledger(3, 5);
  ledger.startLeases(10.0);
  EXPECT_TRUE(ledger.expired(12.0, 2.0).empty());  // exactly the lease: not yet
  ledger.heard(1, 11.5);
  EXPECT_EQ(ledger.expired(12.5, 2.0), (std::vector<int>{0, 2}));
  EXPECT_DOUBLE_EQ(ledger.nextExpiry(2.0), 12.0);
  ledger.markLost(0, 12.5, "silent");
  EXPECT_EQ(ledger.expired(12.5, 2.0), (std::vector<int>{2}));
  ledger.heard(2, 11.0);  // an old message delivered late never moves the lease back
  ledger.heard(2, 12.6);
  EXPECT_DOUBLE_EQ(ledger.silentSeconds(2, 13.0), 13.0 - 12.6);
  ledger.markLost(1, 14, "silent");
  ledger.markLost(2, 14, "silent");
  EXPECT_TRUE(std::isinf(ledger.nextExpiry(2.0)));
}

TEST(LedgerTest, SeededTasksAreDoneAndTheTailIsTakenFromTheBack) {
  Ledger ledger(1, 12);
  ledger.seedDone(TaskSet::range(0, 4));
  EXPECT_EQ(ledger.doneCount(), 4u);
  EXPECT_EQ(ledger.accept(0, TaskSet::range(2, 4)), TaskSet::range(4, 2));
  ledger.gave(0, TaskSet::range(6, 6));
  ledger.accept(0, TaskSet::range(11, 1));
  EXPECT_EQ(ledger.unfinishedTail(0, 2), TaskSet::range(9, 2));
  EXPECT_EQ(ledger.unfinishedTail(0, 100), TaskSet::range(6, 5));
}

TEST(LedgerTest, AWorkerThatJoinsIsLiveWithItsOwnLeaseAndCanBeLost) {
  Ledger ledger(1, 10);
  ledger.startLeases(0);
  EXPECT_FALSE(ledger.joinedAt(0).has_value());
  EXPECT_EQ(ledger.addWorker(4.0), 1);
  EXPECT_EQ(ledger.workerCount(), 2);
  EXPECT_EQ(ledger.liveCount(), 2);
  EXPECT_EQ(ledger.joinedAt(1), 4.0);
  // Its lease starts when it joins: at 6 s only worker 0, silent since 0, has run out.
  EXPECT_EQ(ledger.expired(6.0, 5.0), (std::vector<int>{0}));
  EXPECT_EQ(ledger.nextExpiry(5.0), 5.0);
  ledger.gave(1, TaskSet::range(0, 5));
  ledger.accept(1, TaskSet::range(0, 2));
  EXPECT_EQ(ledger.markLost(1, 7.0, "silent"), TaskSet::range(2, 3));
  EXPECT_EQ(ledger.liveCount(), 1);
}

// The lease index against a walk of every worker, under random renewals (some out of time
// order), losses and joins.
TEST(LedgerTest, IndexedLeasesAgreeWithAWalkOfEveryWorker) {
  std::mt19937_64 random(7);
  Ledger ledger(50, 100);
  ledger.startLeases(1.0);
  std::vector<double> heard(50, 1.0);
  std::vector<bool> live(50, true);
  double now = 1.0;
  for (int step = 0; step < 5000; ++step) {
    now += std::uniform_real_distribution<double>(0, 0.01)(random);
    const int w = static_cast<int>(random() % static_cast<uint64_t>(ledger.workerCount()));
    const uint64_t what = random() % 100;
    if (what < 85) {
      const double at = now - (what < 10 ? 0.5 : 0.0);  // a late message is no renewal
      ledger.heard(w, at);
      heard[static_cast<size_t>(w)] = std::max(heard[static_cast<size_t>(w)], at);
    } else if (what < 95 && ledger.isLive(w) && ledger.liveCount() > 1) {
      ledger.markLost(w, now, "test");
      live[static_cast<size_t>(w)] = false;
    } else if (what < 97) {
      ledger.addWorker(now);
      heard.push_back(now);
      live.push_back(true);
    }
    const double lease = 0.3;
    std::vector<int> expected;
    double next = std::numeric_limits<double>::infinity();
    for (size_t i = 0; i < heard.size(); ++i) {
      if (!live[i]) continue;
      if (now - heard[i] > lease) expected.push_back(static_cast<int>(i));
      next = std::min(next, heard[i] + lease);
    }
    ASSERT_EQ(ledger.expired(now, lease), expected) << "step " << step;
    ASSERT_EQ(ledger.nextExpiry(lease), next) << "step " << step;
  }
}

}  // namespace
}  // namespace prt
