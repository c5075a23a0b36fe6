// The adaptive and speed-weighted strategies: their arithmetic against hand-worked cases and
// their behaviour under the scripted master (fake_master.h).

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "balance/adaptive_factoring.h"
#include "balance/adaptive_reservoir.h"
#include "balance/awf.h"
#include "balance/fake_master.h"
#include "balance/hybrid.h"
#include "balance/registry.h"
#include "balance/stealing.h"
#include "balance/weighted_scatter.h"

namespace prt {
namespace {

TEST(AwfTest, WeightsAreInverseTimesNormalisedToTheWorkerCount) {
  // Times per task 1, 2, 4: inverse 1, 1/2, 1/4 sum 7/4; weights P * inv / sum.
  const std::vector<double> w = awfWeights({1, 2, 4}, {true, true, true});
  EXPECT_DOUBLE_EQ(w[0], 3 * 1.0 / 1.75);
  EXPECT_DOUBLE_EQ(w[1], 3 * 0.5 / 1.75);
  EXPECT_DOUBLE_EQ(w[2], 3 * 0.25 / 1.75);
  // Unmeasured (0) takes the fastest measured; lost workers weigh nothing.
  const std::vector<double> v = awfWeights({0, 2, 4}, {true, true, false});
  EXPECT_DOUBLE_EQ(v[0], 1.0);
  EXPECT_DOUBLE_EQ(v[1], 1.0);
  EXPECT_DOUBLE_EQ(v[2], 0.0);
  EXPECT_EQ(awfWeights({0, 0}, {true, true}), (std::vector<double>{1, 1}));
}

TEST(AwfTest, ChunksFollowMeasuredSpeeds) {
  // Two workers, worker 1 four times slower. After the first measurements AWF-C gives the
  // fast worker four times the slow one's chunk of ceil(R / 2P).
  AwfStrategy awf(AwfStrategy::Variant::Chunk, 1);
  const Decisions start = awf.start(StartInfo{1000, {1, 1}});
  ASSERT_EQ(start.size(), 2u);  // one task each
  awf.onResults(0, TaskSet::range(0, 1), 1.0);
  awf.onResults(1, TaskSet::range(1, 1), 4.0);
  // R = 998, ceil(R / 4) = 250; weights 2 * 1 / 1.25 = 1.6 and 0.4.
  const Decisions fast = awf.onRequest(0);
  ASSERT_EQ(fast.size(), 1u);
  EXPECT_EQ(std::get<Assign>(fast[0]).tasks.size(), 400u);
  const Decisions slow = awf.onRequest(1);
  // R = 598, ceil(598 / 4) = 150; worker 1's wap now weighs its chunk twice: still 4 s.
  EXPECT_EQ(std::get<Assign>(slow[0]).tasks.size(), 60u);
}

TEST(AwfTest, BatchVariantSplitsOneBatch) {
  AwfStrategy awf(AwfStrategy::Variant::Batch, 1);
  awf.start(StartInfo{1002, {1, 1}});
  awf.onResults(0, TaskSet::range(0, 1), 1.0);
  awf.onResults(1, TaskSet::range(1, 1), 4.0);
  // R = 1000: batch 2 * ceil(1000 / 4) = 500; chunks 1.6 * 250 = 400 and 0.4 * 250 = 100.
  EXPECT_EQ(std::get<Assign>(awf.onRequest(0)[0]).tasks.size(), 400u);
  EXPECT_EQ(std::get<Assign>(awf.onRequest(1)[0]).tasks.size(), 100u);
}

TEST(AdaptiveFactoringTest, FormulaMatchesHandWorkedCases) {
  // No variance: chunk_i = T R / mu_i, worker i's proportional share of all that is left.
  EXPECT_DOUBLE_EQ(adaptiveFactoringChunk({1, 1}, {0, 0}, 0, 100), 50);
  EXPECT_DOUBLE_EQ(adaptiveFactoringChunk({1, 3}, {0, 0}, 1, 100), 25);
  // D = 1 + 1 = 2, T = 1/2, R = 12: (2 + 12 - sqrt(4 + 48)) / 2.
  EXPECT_NEAR(adaptiveFactoringChunk({1, 1}, {1, 1}, 0, 12), (14 - std::sqrt(52.0)) / 2, 1e-12);
  // More spread, smaller chunks.
  EXPECT_LT(adaptiveFactoringChunk({1, 1}, {4, 4}, 0, 12), adaptiveFactoringChunk({1, 1}, {1, 1}, 0, 12));
}

TEST(AdaptiveFactoringTest, ChunksAreBoundedByHalfAnEvenShare) {
  AdaptiveFactoringStrategy af(2);
  af.start(StartInfo{1000, {1, 1}});
  for (int w = 0; w < 2; ++w) af.onResults(w, TaskSet::range(2 * static_cast<uint64_t>(w), 2), 2.0);
  // No variance: the formula asks for 498, the bound is ceil(1000 / 4) = 250.
  EXPECT_EQ(std::get<Assign>(af.onRequest(0)[0]).tasks.size(), 250u);
}

TEST(AdaptiveReservoirTest, CommonFinishTimeFillsTheIdleFirst) {
  // Rates 10 and 10, nobody holding anything: 200 tasks take 10 s.
  EXPECT_DOUBLE_EQ(commonFinishSeconds({10, 10}, {0, 0}, 200), 10);
  // Worker 1 holds 100 (10 s of work): 100 left for worker 0 alone... until 10 s, then both.
  EXPECT_DOUBLE_EQ(commonFinishSeconds({10, 10}, {0, 100}, 100), 10);
  EXPECT_DOUBLE_EQ(commonFinishSeconds({10, 10}, {0, 100}, 300), 20);
  // A queue that lasts past T gets no part of the pool.
  EXPECT_DOUBLE_EQ(commonFinishSeconds({10, 10}, {0, 1000}, 50), 5);
  EXPECT_EQ(commonFinishSeconds({0, 0}, {0, 0}, 50), 0);
}

TEST(AdaptiveReservoirTest, HandOutsFollowMeasuredSpeedsAndKeepAReserve) {
  AdaptiveReservoirStrategy adaptive(/*firstPercent=*/10, /*reservePercent=*/50, /*minChunk=*/1);
  const Decisions start = adaptive.start(StartInfo{1000, {1, 1}});  // no speed index run
  ASSERT_EQ(start.size(), 2u);
  EXPECT_EQ(std::get<Assign>(start[0]).tasks.size(), 50u);
  EXPECT_EQ(std::get<Assign>(start[1]).tasks.size(), 50u);
  adaptive.onResults(0, std::get<Assign>(start[0]).tasks, 5.0);  // 10 tasks/s
  adaptive.onResults(1, TaskSet::range(50, 40), 16.0);          // 2.5 tasks/s, holds 10
  // Pool 900, worker 1 holds 10 (4 s). T: (900 + 10) / 12.5 = 72.8 s; worker 0's part
  // 728, half of it handed out.
  EXPECT_EQ(std::get<Assign>(adaptive.onRequest(0)[0]).tasks.size(), 364u);
}

TEST(AdaptiveReservoirTest, ARateFromFewerTasksThanAStratumDoesNotCountYet) {
  AdaptiveReservoirStrategy adaptive(10, 50, 1);
  const Decisions start = adaptive.start(StartInfo{1000, {1, 1}});
  adaptive.onResults(0, std::get<Assign>(start[0]).tasks, 5.0);  // 50 tasks, 10 tasks/s
  // Ten cheap pixels in 0.1 s: 100 tasks/s, but ten pixels have not seen the image. Worker 1
  // asks once its queue is empty, and is sized as the slowest measured worker, 10 tasks/s:
  // T = 900 / 20 = 45 s, its part 450, half handed out (at 100 tasks/s it would be 409).
  adaptive.onResults(1, TaskSet::range(50, 10), 0.1);
  static_assert(AdaptiveReservoirStrategy::kMeasuredTasks > 10);
  EXPECT_EQ(std::get<Assign>(adaptive.onRequest(1)[0]).tasks.size(), 225u);
}

TEST(AdaptiveReservoirTest, StealsFromTheWorkerExpectedToFinishLast) {
  AdaptiveReservoirStrategy adaptive(100, 50, 1);
  const Decisions start = adaptive.start(StartInfo{300, {1, 1, 1}});  // 100 each, pool empty
  adaptive.onResults(0, std::get<Assign>(start[0]).tasks, 10.0);  // 10 tasks/s, done
  adaptive.onResults(1, TaskSet::range(100, 40), 4.0);            // 10 tasks/s, 60 left (6 s)
  adaptive.onResults(2, TaskSet::range(200, 40), 16.0);           // 2.5 tasks/s, 60 left (24 s)
  // Worker 0 takes 60 * 10 / (2.5 + 10) = 48 of worker 2's, so that both finish at 4.8 s
  // (below its fair part, 10 * 120 / 22.5 = 53).
  EXPECT_EQ(adaptive.onRequest(0), (Decisions{Transfer{2, 0, 48}}));
}

TEST(AdaptiveReservoirTest, SlowWorkersFinishWithTheFast) {
  // Under the scripted master (a round a second), workers of rates 4, 4, 1, 1 end within a
  // few rounds of each other, and stay so when one slows down from 4 to 1 part-way.
  for (int slowed : {-1, 0}) {
    SCOPED_TRACE(slowed);
    auto strategy = makeStrategy("adaptive", StrategyOptions{.minChunk = 4});
    // True rates 4, 4, 1, 1 tasks a round; the strategy is told nothing of them.
    testing::FakeRunConfig config{.taskCount = 4000, .speedIndexSeconds = {1, 1, 4, 4}};
    config.hideSpeedIndex = true;
    config.slowedWorker = slowed;
    config.slowedFromRound = 150;
    config.slowedRate = 1;
    const testing::FakeRunResult r = testing::runFakeMaster(*strategy, config);
    ASSERT_TRUE(r.terminated);
    ASSERT_TRUE(r.errors.empty()) << r.errors.front();
    const auto [first, last] = std::minmax_element(r.lastBusyRound.begin(), r.lastBusyRound.end());
    EXPECT_LE(*last - *first, 12u) << "rounds " << *first << " to " << *last;
  }
}

TEST(StealingTest, IdleWorkerTakesHalfOfTheFullestQueue) {
  StealingStrategy stealing(1);
  const Decisions start = stealing.start(StartInfo{90, {1, 1, 1}});  // 30 each
  stealing.onResults(0, std::get<Assign>(start[0]).tasks, 1.0);
  stealing.onResults(1, TaskSet::range(0, 20), 1.0);  // holds 10
  stealing.onResults(2, TaskSet::range(0, 4), 1.0);   // holds 26: the fullest
  EXPECT_EQ(stealing.onRequest(0), (Decisions{Transfer{2, 0, 13}}));
  // Workers 0 and 2 now count 13 each, but worker 0's may still be on their way to it: it is
  // no victim until it has rendered some of them.
  stealing.onResults(1, TaskSet::range(20, 10), 1.0);
  EXPECT_EQ(stealing.onRequest(1), (Decisions{Transfer{2, 1, 6}}));
  stealing.onResults(0, TaskSet::range(0, 1), 1.0);  // 12 left at worker 0, 7 at worker 2
  stealing.onResults(2, TaskSet::range(0, 7), 1.0);  // worker 2 done: 0 left
  EXPECT_EQ(stealing.onRequest(2), (Decisions{Transfer{0, 2, 6}}));
}

TEST(StealingTest, NoStealBelowTheMinimumTheThiefWaitsForTheEnd) {
  StealingStrategy stealing(8);
  const Decisions start = stealing.start(StartInfo{30, {1, 1}});  // 15 each
  stealing.onResults(0, std::get<Assign>(start[0]).tasks, 1.0);
  EXPECT_EQ(stealing.onRequest(0), Decisions{});  // half of 15 is 7 < 8: it waits
  EXPECT_EQ(stealing.onResults(1, TaskSet::range(15, 10), 1.0), Decisions{});
  // The last results: nothing will ever be worth stealing, the waiting thief is let go.
  EXPECT_EQ(stealing.onResults(1, TaskSet::range(25, 5), 1.0), (Decisions{NoMoreWork{0}}));
}

TEST(WeightedScatterTest, SharesFollowTheDivisionOfLabourAndCoverEveryTask) {
  const std::vector<TaskSet> shares = weightedScatterShares(1000, {1, 1, 2, 4});
  // Division 4/11, 4/11, 2/11, 1/11 of 1000: ceil 364, 364, 182, then 90 left.
  ASSERT_EQ(shares.size(), 4u);
  EXPECT_EQ(shares[0].size(), 364u);
  EXPECT_EQ(shares[1].size(), 364u);
  EXPECT_EQ(shares[2].size(), 182u);
  EXPECT_EQ(shares[3].size(), 90u);
  std::vector<int> seen(1000, 0);
  for (const TaskSet& s : shares) s.forEach([&](uint64_t t) { ++seen[t]; });
  EXPECT_TRUE(std::all_of(seen.begin(), seen.end(), [](int n) { return n == 1; }));
  // Each share samples the whole image: it has tasks in the first and last tenth.
  for (const TaskSet& s : shares) {
    const std::vector<uint64_t> v = s.toVector();
    EXPECT_LT(*std::min_element(v.begin(), v.end()), 100u);
    EXPECT_GE(*std::max_element(v.begin(), v.end()), 900u);
  }
}

TEST(HybridWeightedTest, DiffusionBalancesTowardsSpeedWeightedShares) {
  HybridStrategy hybrid(/*speedWeighted=*/true);
  hybrid.start(StartInfo{300, {1, 2}});  // division 2/3, 1/3
  EXPECT_EQ(hybrid.onRequest(0), (Decisions{QueryQueues{}}));
  // 90 tasks queued, all at worker 1: targets 60 and 30, so 60 move.
  EXPECT_EQ(hybrid.onQueueLengths({0, 90}), (Decisions{Transfer{1, 0, 60}}));
  HybridStrategy plain;
  plain.start(StartInfo{300, {1, 2}});
  plain.onRequest(0);
  EXPECT_EQ(plain.onQueueLengths({0, 90}), (Decisions{Transfer{1, 0, 45}}));
}

TEST(RegistryRowsTest, EveryRowDeclaresItsKindAndOptions) {
  for (const StrategyRow& row : strategyRows()) {
    for (const StrategyOption& option : row.options) {
      EXPECT_TRUE(option.accepts(option.defaultValue())) << row.name << " --" << option.flag;
      EXPECT_FALSE(option.help.empty());
    }
  }
  EXPECT_EQ(strategyRow("adaptive").kind, StrategyKind::Adaptive);
  EXPECT_FALSE(strategyRow("adaptive").readsSpeedIndex);
  EXPECT_TRUE(strategyRow("reservoir").readsSpeedIndex);
  EXPECT_EQ(strategiesTaking("initial-percent"),
            (std::vector<std::string>{"reservoir", "reservoir-scatter"}));
  EXPECT_NO_THROW(strategyRow(kDefaultStrategy));
}

}  // namespace
}  // namespace prt

namespace prt {
namespace {

// The victim of a steal is lost before it sends anything: the thief must still get the
// victim's tasks (it used to wait for a transfer that never comes).
TEST(StealingTest, AThiefWhoseVictimIsLostIsServedItsTasks) {
  std::unique_ptr<Strategy> s = makeStrategy("stealing", StrategyOptions{});
  const Decisions start = s->start(StartInfo{100, {1.0, 1.0}});
  ASSERT_EQ(start.size(), 2u);
  const TaskSet mine = std::get<Assign>(start[1]).tasks;
  const TaskSet theirs = std::get<Assign>(start[0]).tasks;
  s->onResults(1, mine, 0.5);
  const Decisions steal = s->onRequest(1);
  ASSERT_EQ(steal.size(), 1u);
  const auto* transfer = std::get_if<Transfer>(&steal[0]);
  ASSERT_NE(transfer, nullptr);
  EXPECT_EQ(transfer->from, 0);
  const Decisions after = s->onWorkerLost(0, theirs);
  uint64_t given = 0;
  for (const Decision& d : after) {
    if (const auto* a = std::get_if<Assign>(&d)) {
      EXPECT_EQ(a->worker, 1);
      given += a->tasks.size();
    }
  }
  EXPECT_GT(given, 0u);
}

}  // namespace
}  // namespace prt
