// What each kind of strategy gives a worker that joins the running render (Strategy::
// onWorkerJoined), scripted without a transport.

#include <gtest/gtest.h>

#include <numeric>

#include "balance/fake_master.h"
#include "balance/hybrid.h"
#include "balance/registry.h"
#include "balance/reservoir.h"
#include "balance/reservoir_math.h"
#include "balance/scatter.h"

namespace prt {
namespace {

TaskSet assignedTo(const Decisions& decisions, int worker) {
  TaskSet out;
  for (const Decision& d : decisions) {
    if (const auto* a = std::get_if<Assign>(&d); a != nullptr && a->worker == worker) {
      out.append(a->tasks);
    }
  }
  return out;
}

TEST(JoinTest, ReservoirGivesANewcomerItsShareOfTheReservoirBySpeedIndex) {
  // 1000 tasks, 50 % out at the start to two equal workers; 500 stay in the reservoir.
  ReservoirStrategy s(50);
  s.start(StartInfo{1000, {2.0, 2.0}});
  EXPECT_TRUE(s.onWorkerJoined(2, 1.0).empty());
  // Speeds (2, 2, 1): division 1/4, 1/4, 1/2, so the newcomer asks for half of 500.
  EXPECT_NEAR(s.division()[2], 0.5, 1e-12);
  EXPECT_EQ(assignedTo(s.onRequest(2), 2).size(), 250u);
  // The others' shares shrink accordingly: a quarter of the 250 left.
  EXPECT_EQ(assignedTo(s.onRequest(0), 0).size(), 63u);
}

TEST(JoinTest, ScatterGivesANewcomerOnlyTheTasksOfWorkersLostLater) {
  ScatterStrategy s;
  s.start(StartInfo{90, {1.0, 1.0}});
  EXPECT_TRUE(s.onWorkerJoined(2, 1.0).empty());
  EXPECT_EQ(s.onRequest(2), (Decisions{NoMoreWork{2}}));
  // Worker 0 is lost holding 40 tasks: they are spread over workers 1 and 2.
  const Decisions after = s.onWorkerLost(0, TaskSet::range(0, 40));
  EXPECT_EQ(assignedTo(after, 1).size(), 20u);
  EXPECT_EQ(assignedTo(after, 2).size(), 20u);
}

TEST(JoinTest, HybridMovesTasksToANewcomerByDiffusion) {
  HybridStrategy s(false);
  s.start(StartInfo{600, {1.0, 1.0}});
  EXPECT_TRUE(s.onWorkerJoined(2, 1.0).empty());
  EXPECT_EQ(s.onRequest(2), (Decisions{QueryQueues{}}));
  // Queues of 300 and 300 and the newcomer's 0: each sends it 100.
  EXPECT_EQ(s.onQueueLengths({300, 300, 0}),
            (Decisions{Transfer{0, 2, 100}, Transfer{1, 2, 100}}));
}

TEST(JoinTest, AdaptiveSizesANewcomerByItsSpeedIndexBeforeMeasuringIt) {
  // Two workers of index 1 measured at 100 tasks/s, holding nothing, 90 000 tasks in the pool.
  // A newcomer of index 0.5 is taken to run at 200 tasks/s: all would finish together at
  // T = 90000 / 400 = 225 s, its part is 200 T = 45 000 and it gets half (the reserve), 22 500.
  // One of index 1 runs at 100: T = 300 s, part 30 000, hand-out 15 000.
  const StrategyOptions options{.minChunk = 1, .firstPercent = 10, .reservePercent = 50};
  auto measuredRun = [&](double joinerIndex) {
    auto s = makeStrategy("adaptive", options);
    const Decisions start = s->start(StartInfo{100000, {1.0, 1.0}});
    for (int w = 0; w < 2; ++w) {
      const TaskSet mine = assignedTo(start, w);
      s->onResults(w, mine, static_cast<double>(mine.size()) / 100.0);
    }
    s->onWorkerJoined(2, joinerIndex);
    return assignedTo(s->onRequest(2), 2).size();
  };
  EXPECT_EQ(measuredRun(0.5), 22500u);
  EXPECT_EQ(measuredRun(1.0), 15000u);
}

// A render that starts on one slow worker and gains two workers four times as fast at round 20:
// which strategies let the newcomers help.
testing::FakeRunResult slowStartThenTwoFastJoin(const std::string& name) {
  auto strategy = makeStrategy(name, StrategyOptions{});
  testing::FakeRunConfig config{.taskCount = 4000, .speedIndexSeconds = {4.0}};
  config.arrivals = {{20, 1.0}, {20, 1.0}};
  return testing::runFakeMaster(*strategy, config);
}

TEST(JoinTest, StrategiesThatHandOutAsTheyGoLetNewcomersHelp) {
  // The slow worker renders 1 task a round, each newcomer 4: from round 20 on, an ideal split
  // gives the newcomers 8/9 of the 3980 tasks left.
  for (const StrategyRow& row : strategyRows()) {
    if (row.kind == StrategyKind::Static) continue;
    if (row.name == "frames") continue;  // a still is one frame: the first worker's whole
    SCOPED_TRACE(row.name);
    const testing::FakeRunResult r = slowStartThenTwoFastJoin(row.name);
    ASSERT_TRUE(r.errors.empty()) << r.errors.front();
    ASSERT_TRUE(r.terminated);
    ASSERT_EQ(r.joined, 2u);
    const uint64_t newcomers = r.renderedBy[1] + r.renderedBy[2];
    if (row.name == "guided") {
      // Guided's first hand-out is the pool over the live workers: with one, everything.
      EXPECT_EQ(newcomers, 0u);
    } else if (row.name == "adaptive" || row.name == "stealing" || row.name == "self") {
      EXPECT_GT(newcomers, 3300u) << "of 4000";  // they take tasks from the slow one's queue
    } else {
      // The rest keep what they gave the first worker (80 % for the reservoir, half or more
      // for factoring, AWF and AF): the newcomers render what remained.
      EXPECT_GE(newcomers, 700u) << "of 4000";
    }
  }
}

TEST(JoinTest, StaticStrategiesGiveNewcomersNothingWhenNoneIsLost) {
  for (const std::string name : {"scatter", "scatter-weighted", "blocks"}) {
    SCOPED_TRACE(name);
    const testing::FakeRunResult r = slowStartThenTwoFastJoin(name);
    ASSERT_TRUE(r.errors.empty()) << r.errors.front();
    EXPECT_EQ(r.renderedBy[1] + r.renderedBy[2], 0u);
  }
}

}  // namespace
}  // namespace prt
