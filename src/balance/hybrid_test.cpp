#include "balance/hybrid.h"

#include <gtest/gtest.h>

#include "balance/fake_master.h"

namespace prt {
namespace {

const std::vector<bool> kAllLive3 = {true, true, true};

TEST(HybridTest, ExcessGoesToDeficitLargestFirst) {
  // Total 12 over 3 workers: target 4. Worker 0 has 6 too many; worker 1 lacks 4, worker 2 2.
  EXPECT_EQ(diffusionTransfers({10, 0, 2}, kAllLive3, {false, true, false}),
            (std::vector<Transfer>{{0, 1, 4}, {0, 2, 2}}));
  // Two senders, one receiver: the larger excess goes first, the total never exceeds the
  // receiver's deficit.
  EXPECT_EQ(diffusionTransfers({9, 7, 0, 8}, {true, true, true, true}, {false, false, true, false}),
            (std::vector<Transfer>{{0, 2, 3}, {3, 2, 2}, {1, 2, 1}}));
}

TEST(HybridTest, TinyQueuesMoveNothing) {
  EXPECT_TRUE(diffusionTransfers({1, 0, 0}, kAllLive3, {false, true, true}).empty());
  EXPECT_TRUE(diffusionTransfers({1, 1, 0}, kAllLive3, {false, false, true}).empty());
  EXPECT_TRUE(diffusionTransfers({0, 0, 0}, kAllLive3, {true, true, true}).empty());
  // Two tasks, three workers: target 1, so one task moves, to a waiting worker first.
  EXPECT_EQ(diffusionTransfers({2, 0, 0}, kAllLive3, {false, false, true}),
            (std::vector<Transfer>{{0, 2, 1}}));
}

TEST(HybridTest, LostWorkersAreLeftOut) {
  // Worker 2 is lost: total 9 over 2 live workers, target 5; it receives nothing.
  EXPECT_EQ(diffusionTransfers({9, 0, 0}, {true, true, false}, {false, true, false}),
            (std::vector<Transfer>{{0, 1, 4}}));
  EXPECT_TRUE(diffusionTransfers({9, 0}, {false, false}, {false, true}).empty());
}

TEST(HybridTest, ScriptedRequestQueryAndAnswer) {
  HybridStrategy s;
  EXPECT_EQ(s.start(StartInfo{12, {1, 1, 1}}),
            (Decisions{Assign{0, TaskSet::strided(0, 4, 3)}, Assign{1, TaskSet::strided(1, 4, 3)},
                       Assign{2, TaskSet::strided(2, 4, 3)}}));
  EXPECT_EQ(s.onRequest(1), (Decisions{QueryQueues{}}));
  EXPECT_TRUE(s.onRequest(2).empty());  // a query is already out: worker 2 waits for it
  // Target ceil(4 / 3) = 2: worker 0 sends its 2 extra to worker 1; worker 2 gets nothing.
  EXPECT_EQ(s.onQueueLengths({4, 0, 0}), (Decisions{Transfer{0, 1, 2}, NoMoreWork{2}}));
  EXPECT_TRUE(s.onQueueLengths({4, 0, 0}).empty());  // unsolicited answers are ignored
  // A new request starts a new query.
  EXPECT_EQ(s.onRequest(2), (Decisions{QueryQueues{}}));
  EXPECT_EQ(s.onQueueLengths({1, 1, 0}), (Decisions{NoMoreWork{2}}));
}

TEST(HybridTest, LostWorkerTasksAreAssignedAndItLeavesTheWaitingList) {
  HybridStrategy s;
  s.start(StartInfo{12, {1, 1, 1}});
  EXPECT_EQ(s.onRequest(1), (Decisions{QueryQueues{}}));
  EXPECT_EQ(s.onWorkerLost(1, TaskSet()), Decisions{});
  EXPECT_TRUE(s.onQueueLengths({4, 0, 3}).empty());  // nobody waits any more
  EXPECT_EQ(s.onWorkerLost(0, TaskSet::strided(6, 2, 3)),
            (Decisions{Assign{2, TaskSet::strided(6, 2, 3)}}));
  EXPECT_EQ(s.onRequest(0), (Decisions{NoMoreWork{0}}));
}

TEST(HybridTest, DiffusionMovesWorkToFastWorkersAndStops) {
  // Worker 0 renders eight times as fast: scatter leaves it idle early, so diffusion must
  // move tasks to it, a bounded number of times.
  HybridStrategy s;
  const testing::FakeRunResult r =
      testing::runFakeMaster(s, {.taskCount = 2000, .speedIndexSeconds = {1, 8}});
  EXPECT_TRUE(r.terminated);
  EXPECT_TRUE(r.errors.empty());
  EXPECT_GT(r.transfers, 0u);
  EXPECT_LE(r.queries, r.requests);
  EXPECT_LT(r.rounds, 2000u / 9 * 2);  // near the balanced ~222 rounds, far from 1000
}

}  // namespace
}  // namespace prt
