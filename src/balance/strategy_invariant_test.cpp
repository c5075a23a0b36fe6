// Properties every strategy must have, whatever the image size, worker count and speeds:
// every task is rendered exactly once, nothing is assigned to a lost worker, every request is
// answered, and a run ends in a bounded number of rounds — also when workers join the running
// render, and when some of those are lost.

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <ostream>
#include <string>
#include <vector>

#include "balance/fake_master.h"
#include "balance/strategy.h"
#include "core/input_error.h"
#include "core/rng.h"

namespace prt {
namespace {

struct Variant {
  std::string name;
  StrategyOptions options;
};

void PrintTo(const Variant& v, std::ostream* os) {
  *os << v.name << " (initialPercent " << v.options.initialPercent << ", chunk " << v.options.chunk
      << ", minChunk " << v.options.minChunk << ", firstPercent " << v.options.firstPercent
      << ", reservePercent " << v.options.reservePercent << ")";
}

std::string variantLabel(const ::testing::TestParamInfo<Variant>& info) {
  std::string label = info.param.name;
  if (info.param.name == "reservoir") {
    label += "P";
    label += std::to_string(static_cast<int>(info.param.options.initialPercent));
  } else if (info.param.name == "self") {
    label += "Chunk";
    label += std::to_string(info.param.options.chunk);
  } else if (info.param.options.minChunk != StrategyOptions{}.minChunk) {
    label += "Min" + std::to_string(info.param.options.minChunk) + "First" +
             std::to_string(static_cast<int>(info.param.options.firstPercent)) + "Reserve" +
             std::to_string(static_cast<int>(info.param.options.reservePercent));
  }
  for (char& c : label) {
    if (c == '-') c = '_';  // test names allow only letters, digits and '_'
  }
  return label;
}

std::vector<Variant> allVariants() {
  std::vector<Variant> out;
  for (const std::string& name : strategyNames()) out.push_back({name, StrategyOptions{}});
  out.push_back({"reservoir", StrategyOptions{.initialPercent = 100}});
  out.push_back({"reservoir", StrategyOptions{.initialPercent = 5}});
  out.push_back({"self", StrategyOptions{.chunk = 1}});
  out.push_back({"self", StrategyOptions{.chunk = 5000}});
  out.push_back({"adaptive", StrategyOptions{.minChunk = 1, .firstPercent = 100, .reservePercent = 0}});
  out.push_back({"adaptive", StrategyOptions{.minChunk = 1, .firstPercent = 1, .reservePercent = 90}});
  out.push_back({"stealing", StrategyOptions{.minChunk = 1}});
  out.push_back({"af", StrategyOptions{.minChunk = 1}});
  return out;
}

const std::vector<uint64_t> kTaskCounts = {1, 7, 100, 1000, uint64_t{64} * 48, uint64_t{333} * 77};

std::vector<std::vector<double>> speedLists(int workers) {
  std::vector<double> equal(static_cast<size_t>(workers), 1.0);
  std::vector<double> powers;
  std::vector<double> random;
  Rng rng(static_cast<uint64_t>(workers) * 7919);
  for (int w = 0; w < workers; ++w) {
    powers.push_back(static_cast<double>(1 << (w % 4)));
    random.push_back(0.1 + 9.9 * rng.uniform());
  }
  return {equal, powers, random};
}

std::string describe(const testing::FakeRunConfig& c) {
  std::string s = "tasks " + std::to_string(c.taskCount) + ", speeds {";
  for (double v : c.speedIndexSeconds) s += std::to_string(v) + " ";
  s += "}";
  for (const testing::FakeArrival& a : c.arrivals) {
    s += ", a worker of index " + std::to_string(a.speedIndexSeconds) + " joins at round " +
         std::to_string(a.atRound);
  }
  if (c.lostWorker >= 0) {
    s += ", worker " + std::to_string(c.lostWorker) + " lost after " +
         std::to_string(c.loseAfterRendered);
  }
  return s;
}

// Runs the strategy once and checks the invariants; returns false on the first failure so a
// broken strategy does not flood the log.
bool checkRun(const Variant& variant, const testing::FakeRunConfig& config) {
  SCOPED_TRACE(describe(config));
  auto strategy = makeStrategy(variant.name, variant.options);
  const testing::FakeRunResult r = testing::runFakeMaster(*strategy, config);
  bool ok = true;
  auto fail = [&](const std::string& what) {
    ADD_FAILURE() << what;
    ok = false;
  };
  for (const std::string& e : r.errors) fail("protocol: " + e);
  if (!r.terminated) fail("did not finish within " + std::to_string(r.rounds) + " rounds");
  for (uint64_t t = 0; t < config.taskCount && ok; ++t) {
    const auto i = static_cast<size_t>(t);
    if (r.renderCount[i] != 1) {
      fail("task " + std::to_string(t) + " rendered " + std::to_string(r.renderCount[i]) +
           " times");
    } else if (r.assignCount[i] != 1 + r.recoveredCount[i]) {
      fail("task " + std::to_string(t) + " assigned " + std::to_string(r.assignCount[i]) +
           " times, recovered " + std::to_string(r.recoveredCount[i]) + " times");
    }
  }
  return ok;
}

class StrategyInvariantTest : public ::testing::TestWithParam<Variant> {};

TEST_P(StrategyInvariantTest, EveryTaskRenderedOnceAndRunEnds) {
  for (uint64_t tasks : kTaskCounts) {
    for (int workers = 1; workers <= 16; ++workers) {
      for (const std::vector<double>& speeds : speedLists(workers)) {
        testing::FakeRunConfig config{.taskCount = tasks, .speedIndexSeconds = speeds};
        config.seed = tasks + static_cast<uint64_t>(workers);
        if (!checkRun(GetParam(), config)) return;
      }
    }
  }
}

TEST_P(StrategyInvariantTest, WorkerLostMidwayOrAtOnce) {
  for (uint64_t tasks : kTaskCounts) {
    for (int workers = 2; workers <= 16; ++workers) {
      for (const std::vector<double>& speeds : speedLists(workers)) {
        for (uint64_t loseAfter : {uint64_t{0}, tasks / 3}) {
          testing::FakeRunConfig config{.taskCount = tasks, .speedIndexSeconds = speeds};
          config.lostWorker = workers / 2;
          config.loseAfterRendered = loseAfter;
          config.seed = tasks * 31 + static_cast<uint64_t>(workers);
          if (!checkRun(GetParam(), config)) return;
        }
      }
    }
  }
}

TEST_P(StrategyInvariantTest, WorkersJoiningMidwayKeepEveryInvariant) {
  for (uint64_t tasks : kTaskCounts) {
    for (int workers = 1; workers <= 6; ++workers) {
      for (const std::vector<double>& speeds : speedLists(workers)) {
        testing::FakeRunConfig config{.taskCount = tasks, .speedIndexSeconds = speeds};
        config.arrivals = {{1, 0.5}, {3, 4.0}, {3, 1.0}};
        config.seed = tasks * 17 + static_cast<uint64_t>(workers);
        if (!checkRun(GetParam(), config)) return;
      }
    }
  }
}

TEST_P(StrategyInvariantTest, ArrivalsAndLossesInOneRun) {
  for (uint64_t tasks : kTaskCounts) {
    for (int workers = 1; workers <= 6; ++workers) {
      const std::vector<double> speeds(static_cast<size_t>(workers), 2.0);
      // Lose an initial worker (when there is more than one) or the first joiner.
      for (int lost : {workers > 1 ? 0 : workers, workers}) {
        testing::FakeRunConfig config{.taskCount = tasks, .speedIndexSeconds = speeds};
        config.arrivals = {{2, 1.0}, {2, 0.5}, {5, 2.0}};
        config.lostWorker = lost;
        config.loseAfterRendered = tasks / 4;
        config.seed = tasks * 13 + static_cast<uint64_t>(workers);
        if (!checkRun(GetParam(), config)) return;
      }
    }
  }
}

TEST_P(StrategyInvariantTest, JoinOutOfTurnOrWithoutASpeedIsRefused) {
  auto strategy = makeStrategy(GetParam().name, GetParam().options);
  strategy->start(StartInfo{100, {1.0, 2.0}});
  EXPECT_THROW(strategy->onWorkerJoined(3, 1.0), InputError);
  EXPECT_THROW(strategy->onWorkerJoined(2, 0.0), InputError);
  EXPECT_THROW(strategy->onWorkerJoined(2, std::nan("")), InputError);
  EXPECT_NO_THROW(strategy->onWorkerJoined(2, 1.0));
}

TEST_P(StrategyInvariantTest, AllWorkersLostGivesNothing) {
  auto strategy = makeStrategy(GetParam().name, GetParam().options);
  const Decisions start = strategy->start(StartInfo{100, {1.0, 2.0}});
  TaskSet held0;
  TaskSet held1;
  for (const Decision& d : start) {
    if (const auto* a = std::get_if<Assign>(&d)) (a->worker == 0 ? held0 : held1).append(a->tasks);
  }
  const Decisions afterFirst = strategy->onWorkerLost(0, held0);
  for (const Decision& d : afterFirst) {
    if (const auto* a = std::get_if<Assign>(&d)) {
      EXPECT_EQ(a->worker, 1);
    }
    EXPECT_FALSE(std::holds_alternative<Transfer>(d)) << "transfer after every loss";
  }
  EXPECT_TRUE(strategy->onWorkerLost(1, held1).empty());
  EXPECT_EQ(strategy->onRequest(0), (Decisions{NoMoreWork{0}}));
}

TEST_P(StrategyInvariantTest, TasksReachingALostWorkerLateAreStillRendered) {
  // The master reports a lost worker again when a transfer to it lands after the loss.
  auto strategy = makeStrategy(GetParam().name, GetParam().options);
  strategy->start(StartInfo{50, {1.0, 2.0, 4.0}});
  strategy->onWorkerLost(1, TaskSet());
  Decisions pending = strategy->onWorkerLost(1, TaskSet::range(10, 3));
  TaskSet handedOut;
  std::vector<bool> finished(3, false);
  finished[1] = true;
  for (int round = 0; round < 200 && !(finished[0] && finished[2]); ++round) {
    for (const Decision& d : pending) {
      if (const auto* a = std::get_if<Assign>(&d)) {
        EXPECT_NE(a->worker, 1);
        handedOut.append(a->tasks);
      } else if (const auto* n = std::get_if<NoMoreWork>(&d)) {
        finished[static_cast<size_t>(n->worker)] = true;
      }
    }
    const bool query = std::any_of(pending.begin(), pending.end(), [](const Decision& d) {
      return std::holds_alternative<QueryQueues>(d);
    });
    pending = query ? strategy->onQueueLengths({0, 0, 0}) : strategy->onRequest(round % 2 * 2);
  }
  for (uint64_t t : {10u, 11u, 12u}) {
    const std::vector<uint64_t> v = handedOut.toVector();
    EXPECT_NE(std::find(v.begin(), v.end(), t), v.end()) << "task " << t << " never handed out";
  }
}

INSTANTIATE_TEST_SUITE_P(AllStrategies, StrategyInvariantTest, ::testing::ValuesIn(allVariants()),
                         variantLabel);

}  // namespace
}  // namespace prt
