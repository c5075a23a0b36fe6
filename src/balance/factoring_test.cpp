#include "balance/factoring.h"

#include <gtest/gtest.h>

#include "balance/assign_testing.h"

namespace prt {
namespace {

using testing_support::assignRange;

TEST(FactoringTest, ChunksFollowTheWeights) {
  EXPECT_EQ(factoringChunks(50, {0.5, 0.5}), (std::vector<uint64_t>{25, 25}));
  EXPECT_EQ(factoringChunks(50, {0.75, 0.25}), (std::vector<uint64_t>{38, 13}));
  EXPECT_EQ(factoringChunks(1, {0.9, 0.1, 0.0}), (std::vector<uint64_t>{1, 1, 0}));
}

TEST(FactoringTest, EqualWorkersHalveTheRemainderEachBatch) {
  FactoringStrategy s;
  EXPECT_EQ(s.start(StartInfo{100, {1, 1}}),
            (Decisions{assignRange(0, 0, 25), assignRange(1, 25, 25)}));
  // Batch 2 is ceil(50 / 2) = 25, chunks ceil(12.5) = 13: 13 then the 12 left.
  EXPECT_EQ(s.onRequest(0), (Decisions{assignRange(0, 50, 13)}));
  EXPECT_EQ(s.onRequest(1), (Decisions{assignRange(1, 63, 12)}));
  for (int i = 0;; ++i) {
    if (s.onRequest(i % 2) == Decisions{NoMoreWork{i % 2}}) break;
  }
  EXPECT_EQ(s.batchSizes(), (std::vector<uint64_t>{50, 25, 13, 6, 3, 2, 1}));
}

TEST(FactoringTest, WeightedChunksAndAFastWorkerAskingTwice) {
  // Speeds (1, 3): weights 0.75, 0.25.
  FactoringStrategy s;
  // Batch 50: chunks 38 and 13, the second clamped to the 12 left in the batch.
  EXPECT_EQ(s.start(StartInfo{100, {1, 3}}),
            (Decisions{assignRange(0, 0, 38), assignRange(1, 38, 12)}));
  // Batch 25: chunks ceil(18.75) = 19 and ceil(6.25) = 7.
  EXPECT_EQ(s.onRequest(0), (Decisions{assignRange(0, 50, 19)}));
  EXPECT_EQ(s.onRequest(0), (Decisions{assignRange(0, 69, 6)}));  // the rest of the batch
  // Batch 13: chunks 10 and 4.
  EXPECT_EQ(s.onRequest(1), (Decisions{assignRange(1, 75, 4)}));
  EXPECT_EQ(s.batchSizes(), (std::vector<uint64_t>{50, 25, 13}));
}

TEST(FactoringTest, LostWorkerOpensANewBatch) {
  FactoringStrategy s;
  s.start(StartInfo{100, {1, 1}});  // 0..24, 25..49
  EXPECT_TRUE(s.onWorkerLost(1, TaskSet::range(40, 10)).empty());
  // Pool {40..99}, 60 tasks; one live worker: batch 30, all of it to worker 0.
  TaskSet expected = TaskSet::range(40, 10);
  expected.append(TaskSet::range(50, 20));
  EXPECT_EQ(s.onRequest(0), (Decisions{Assign{0, expected}}));
  EXPECT_EQ(s.batchSizes(), (std::vector<uint64_t>{50, 30}));
}

}  // namespace
}  // namespace prt
