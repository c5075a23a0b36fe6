// The strategies whose decisions no longer walk all workers (adaptive, stealing, AF, AWF)
// against the walking versions they replaced, kept here as references: decision for decision,
// under the scripted master and under random events with losses and joins.

#include <gtest/gtest.h>

#include <algorithm>
#include <random>

#include "balance/adaptive_factoring.h"
#include "balance/adaptive_reservoir.h"
#include "balance/awf.h"
#include "balance/fake_master.h"
#include "balance/interleaved_order.h"
#include "balance/reservoir_math.h"
#include "balance/stealing.h"

namespace prt {
namespace {

// The adaptive reservoir as it was before its workers were indexed: every decision walks all
// live workers. Kept as the reference the indexed one must agree with.
class WalkingAdaptive final : public PooledStrategy {
 public:
  explicit WalkingAdaptive(uint64_t minChunk) : kMinChunk(minChunk) {}
  std::string name() const override { return "adaptive-walking"; }

 protected:
  TaskSet initialPool(const StartInfo& info) override {
    return interleavedOrder(info.taskCount, info.frameTasks);
  }
  void prepare(const StartInfo& info) override {
    const std::vector<double>& speeds = info.speedIndexSeconds;
    const bool indexRun = std::any_of(speeds.begin(), speeds.end(),
                                      [&](double s) { return s != speeds.front(); });
    const std::vector<double> division =
        indexRun ? divisionOfLabor(speeds)
                 : std::vector<double>(speeds.size(), 1.0 / static_cast<double>(speeds.size()));
    firstBlocks_ = initialBlockSizes(division, initialLimit(10, info.taskCount));
  }
  uint64_t initialSize(int worker) override { return firstBlocks_[static_cast<size_t>(worker)]; }
  bool waitsForSteals() const override { return true; }

  uint64_t handOutSize(int worker) override {
    const std::vector<double> rate = rates();
    const double mine = rate[static_cast<size_t>(worker)];
    if (mine <= 0) return kMinChunk;
    std::vector<uint64_t> held(rate.size(), 0);
    for (int w : workers().liveList()) held[static_cast<size_t>(w)] = throughput().held(w);
    const double t = commonFinishSeconds(rate, held, remaining());
    const double share = mine * t - static_cast<double>(held[static_cast<size_t>(worker)]);
    return std::max(kMinChunk, ceilCount(share * 0.5));
  }

  std::optional<Transfer> stealFor(int worker) override {
    const std::vector<double> rate = rates();
    const double mine = rate[static_cast<size_t>(worker)];
    if (mine <= 0) return std::nullopt;
    int victim = -1;
    double latest = 0;
    for (int w : workers().liveList()) {
      if (w == worker || rate[static_cast<size_t>(w)] <= 0 || awaitingSteal(w)) continue;
      const double finish = static_cast<double>(throughput().held(w)) / rate[static_cast<size_t>(w)];
      if (finish > latest) {
        latest = finish;
        victim = w;
      }
    }
    if (victim < 0) return std::nullopt;
    const double theirs = rate[static_cast<size_t>(victim)];
    const double held = static_cast<double>(throughput().held(victim));
    double heldSum = 0;
    double rateSum = 0;
    for (int w : workers().liveList()) {
      heldSum += static_cast<double>(throughput().held(w));
      rateSum += rate[static_cast<size_t>(w)];
    }
    const double fair = mine * heldSum / rateSum;
    const auto count = static_cast<uint64_t>(std::min(held * mine / (theirs + mine), fair));
    if (count < kMinChunk) return std::nullopt;
    return Transfer{victim, worker, count};
  }

 private:
  uint64_t kMinChunk;
  bool isMeasured(int w) const {
    return throughput().measured(w) &&
           throughput().measuredTasks(w) >=
               static_cast<double>(AdaptiveReservoirStrategy::kMeasuredTasks);
  }
  std::vector<double> rates() const {
    std::vector<double> out(static_cast<size_t>(workers().workerCount()), 0.0);
    const std::vector<double>& index = speedIndexSeconds();
    double least = 0;  // of rate x index over the measured: the unmeasured are that slow
    int measured = 0;
    for (int w : workers().liveList()) {
      if (isMeasured(w) && throughput().rate(w) > 0) {
        out[static_cast<size_t>(w)] = throughput().rate(w);
        const double factor = out[static_cast<size_t>(w)] * index[static_cast<size_t>(w)];
        least = measured == 0 ? factor : std::min(least, factor);
        ++measured;
      }
    }
    if (measured == 0) return out;
    for (int w : workers().liveList()) {
      if (!isMeasured(w)) {
        out[static_cast<size_t>(w)] = least / index[static_cast<size_t>(w)];
      }
    }
    return out;
  }
  std::vector<uint64_t> firstBlocks_;
};

// Forwards to a strategy and writes down every decision it returns.
class Recording final : public Strategy {
 public:
  explicit Recording(Strategy& inner) : inner_(inner) {}
  std::string name() const override { return inner_.name(); }
  Decisions start(const StartInfo& info) override { return log(inner_.start(info)); }
  Decisions onRequest(int w) override { return log(inner_.onRequest(w)); }
  Decisions onQueueLengths(const std::vector<uint64_t>& l) override {
    return log(inner_.onQueueLengths(l));
  }
  Decisions onResults(int w, const TaskSet& t, double s) override {
    return log(inner_.onResults(w, t, s));
  }
  Decisions onWorkerLost(int w, const TaskSet& t) override { return log(inner_.onWorkerLost(w, t)); }
  Decisions onWorkerJoined(int w, double s) override { return log(inner_.onWorkerJoined(w, s)); }
  Decisions decisions;

 private:
  Decisions log(Decisions d) {
    decisions.insert(decisions.end(), d.begin(), d.end());
    return d;
  }
  Strategy& inner_;
};

TEST(IndexedStrategiesTest, TheIndexedAdaptiveReservoirDecidesAsTheWalkOverAllWorkersDid) {
  struct Case {
    std::vector<double> speeds;
    int lost = -1;
    std::vector<testing::FakeArrival> arrivals = {};
    int slowed = -1;
    uint64_t slowedFrom = 10;
    bool hide = false;
    uint64_t tasks = 20000;
  };
  const std::vector<Case> cases = {
      {{1, 1, 1, 1}},
      {{1, 2, 3, 4, 1, 2, 3, 4}},
      {{1, 4, 1, 4, 1, 4}, 2},
      {{1, 1, 4, 4}, -1, {{3, 2.0}, {9, 0.5}}},
      {{1, 2, 1, 2, 1, 2, 1, 2, 1, 2, 1, 2}, 5, {{4, 1.0}}, 3},
      // Speeds hidden, one worker slowing down after its last hand-out: the end game steals.
      {{1, 1, 4, 4}, -1, {}, 0, 150, true, 4000},
      {{1, 1, 4, 4, 2, 2}, -1, {{20, 1.0}}, 1, 120, true, 4000},
      {{1, 1, 4, 4, 1, 1, 4, 4}, 6, {}, 0, 100, true, 6000},
  };
  int checked = 0;
  uint64_t steals = 0;
  for (const Case& c : cases) {
    for (uint64_t seed : {1, 2, 3}) {
      testing::FakeRunConfig config;
      config.taskCount = c.tasks;
      config.hideSpeedIndex = c.hide;
      config.speedIndexSeconds = c.speeds;
      config.seed = seed;
      config.lostWorker = c.lost;
      config.loseAfterRendered = 7000;
      config.arrivals = c.arrivals;
      config.slowedWorker = c.slowed;
      config.slowedFromRound = c.slowedFrom;
      WalkingAdaptive walking(4);
      AdaptiveReservoirStrategy indexed(10, 50, 4);
      Recording a(walking);
      Recording b(indexed);
      const testing::FakeRunResult ra = testing::runFakeMaster(a, config);
      const testing::FakeRunResult rb = testing::runFakeMaster(b, config);
      ASSERT_TRUE(ra.errors.empty());
      ASSERT_TRUE(rb.errors.empty());
      EXPECT_TRUE(rb.terminated);
      EXPECT_EQ(ra.transfers, rb.transfers);
      ASSERT_EQ(a.decisions.size(), b.decisions.size()) << "seed " << seed;
      for (size_t i = 0; i < a.decisions.size(); ++i) {
        ASSERT_EQ(a.decisions[i], b.decisions[i]) << "decision " << i << ", seed " << seed;
      }
      checked += static_cast<int>(a.decisions.size());
      steals += ra.transfers;
    }
  }
  EXPECT_GT(checked, 1000);
  EXPECT_GT(steals, 0u);
}

// Random workers with random batch times (so queues drift apart and the end game steals),
// losses and joins, fed to two strategies in lock step: both see the same events as long as
// they decide alike. Returns the decisions and transfers compared.
struct Lockstep {
  uint64_t decisions = 0;
  uint64_t steals = 0;
};
Lockstep runInLockstep(Strategy& reference, Strategy& indexed, uint64_t seed) {
  Lockstep out;
  std::mt19937_64 random(seed);
  const int workers = 3 + static_cast<int>(seed % 13);
  std::vector<double> speeds;
  for (int w = 0; w < workers; ++w) speeds.push_back(1.0 + static_cast<double>(random() % 4));
  std::vector<TaskSet> queue(static_cast<size_t>(workers));
  std::vector<bool> lost(static_cast<size_t>(workers), false);
  auto both = [&](auto&& call) {
    const Decisions a = call(reference);
    const Decisions b = call(indexed);
    EXPECT_EQ(a, b) << reference.name() << ", seed " << seed;
    for (const Decision& d : a) {
      ++out.decisions;
      if (const auto* as = std::get_if<Assign>(&d)) {
        queue[static_cast<size_t>(as->worker)].append(as->tasks);
      } else if (const auto* t = std::get_if<Transfer>(&d)) {
        ++out.steals;
        TaskSet& from = queue[static_cast<size_t>(t->from)];
        const TaskSet moved = from.takeBack(std::min(t->count, from.size()));
        queue[static_cast<size_t>(t->to)].append(moved);
      }
    }
    return a == b;
  };
  const StartInfo info{3000, speeds};
  if (!both([&](Strategy& s) { return s.start(info); })) return out;
  for (int step = 0; step < 20000; ++step) {
    std::vector<int> busy;
    for (int w = 0; w < static_cast<int>(queue.size()); ++w) {
      if (!lost[static_cast<size_t>(w)] && !queue[static_cast<size_t>(w)].empty()) busy.push_back(w);
    }
    if (busy.empty()) break;
    const int w = busy[random() % busy.size()];
    const auto i = static_cast<size_t>(w);
    if (random() % 400 == 0 && busy.size() > 1) {  // lost, with what it holds
      lost[i] = true;
      const TaskSet unfinished = std::move(queue[i]);
      queue[i] = TaskSet();
      if (!both([&](Strategy& s) { return s.onWorkerLost(w, unfinished); })) return out;
      continue;
    }
    if (random() % 500 == 0) {  // a newcomer
      const int joiner = static_cast<int>(queue.size());
      queue.emplace_back();
      lost.push_back(false);
      const double index = 1.0 + static_cast<double>(random() % 4);
      if (!both([&](Strategy& s) { return s.onWorkerJoined(joiner, index); })) return out;
      if (!both([&](Strategy& s) { return s.onRequest(joiner); })) return out;
    }
    const uint64_t n = std::min<uint64_t>(1 + random() % 16, queue[i].size());
    const TaskSet done = queue[i].takeFront(n);
    const double seconds = static_cast<double>(n) * speeds[i % speeds.size()] *
                           (0.5 + static_cast<double>(random() % 1000) / 1000.0);
    if (!both([&](Strategy& s) { return s.onResults(w, done, seconds); })) return out;
    if (queue[i].empty() && !both([&](Strategy& s) { return s.onRequest(w); })) return out;
  }
  return out;
}

TEST(IndexedStrategiesTest, TheIndexedAdaptiveReservoirStealsAsTheWalkDidUnderRandomEvents) {
  Lockstep total;
  for (uint64_t seed = 1; seed <= 60; ++seed) {
    WalkingAdaptive walking(2);
    AdaptiveReservoirStrategy indexed(10, 50, 2);
    const Lockstep run = runInLockstep(walking, indexed, seed);
    total.decisions += run.decisions;
    total.steals += run.steals;
  }
  EXPECT_GT(total.decisions, 4000u);
  EXPECT_GT(total.steals, 200u);  // the end game was compared, not only the hand-outs
}

// Work stealing as it was: the victim found by a walk over all live workers.
class WalkingStealing final : public PooledStrategy {
 public:
  std::string name() const override { return "stealing-walking"; }

 protected:
  TaskSet initialPool(const StartInfo& info) override {
    return interleavedOrder(info.taskCount, info.frameTasks);
  }
  void prepare(const StartInfo& info) override {
    taskCount_ = info.taskCount;
    workerCount_ = info.speedIndexSeconds.size();
  }
  uint64_t initialSize(int worker) override {
    const auto w = static_cast<uint64_t>(worker);
    return taskCount_ / workerCount_ + (w < taskCount_ % workerCount_ ? 1 : 0);
  }
  uint64_t handOutSize(int) override {
    const auto p = static_cast<uint64_t>(workers().liveCount());
    return (remaining() + p - 1) / p;
  }
  bool waitsForSteals() const override { return true; }
  std::optional<Transfer> stealFor(int worker) override {
    int victim = -1;
    for (int w : workers().liveList()) {
      if (w == worker || awaitingSteal(w)) continue;
      if (victim < 0 || throughput().held(w) > throughput().held(victim)) victim = w;
    }
    if (victim < 0) return std::nullopt;
    const uint64_t half = throughput().held(victim) / 2;
    if (half < 2) return std::nullopt;
    return Transfer{victim, worker, half};
  }

 private:
  uint64_t taskCount_ = 0;
  uint64_t workerCount_ = 1;
};

TEST(IndexedStrategiesTest, IndexedWorkStealingRobsAsTheWalkDid) {
  Lockstep total;
  for (uint64_t seed = 1; seed <= 40; ++seed) {
    WalkingStealing walking;
    StealingStrategy indexed(2);
    const Lockstep run = runInLockstep(walking, indexed, seed);
    total.decisions += run.decisions;
    total.steals += run.steals;
  }
  EXPECT_GT(total.steals, 200u);
}

// AF and AWF as they were: every hand-out gathers every live worker's times.
class WalkingAf final : public PooledStrategy {
 public:
  std::string name() const override { return "af-walking"; }

 protected:
  TaskSet initialPool(const StartInfo& info) override {
    return interleavedOrder(info.taskCount, info.frameTasks);
  }
  void prepare(const StartInfo& info) override { taskCount_ = info.taskCount; }
  uint64_t initialSize(int) override { return 2; }
  uint64_t handOutSize(int worker) override {
    const std::vector<int> live = workers().liveList();
    int fastest = -1;
    for (int w : live) {
      const double mu = throughput().meanTaskSeconds(w);
      if (mu > 0 && (fastest < 0 || mu < throughput().meanTaskSeconds(fastest))) fastest = w;
    }
    if (fastest < 0) return 2;
    std::vector<double> mu;
    std::vector<double> variance;
    size_t index = 0;
    for (int w : live) {
      const int from = throughput().meanTaskSeconds(w) > 0 ? w : fastest;
      if (w == worker) index = mu.size();
      mu.push_back(throughput().meanTaskSeconds(from));
      variance.push_back(throughput().taskSecondsVariance(from));
    }
    const double chunk =
        adaptiveFactoringChunk(mu, variance, index, static_cast<double>(remaining())) + 0.5;
    const auto p = static_cast<uint64_t>(live.size());
    const uint64_t maxChunk = std::max<uint64_t>(1, (taskCount_ + 2 * p - 1) / (2 * p));
    const auto rounded = chunk >= static_cast<double>(maxChunk) ? maxChunk
                                                                 : static_cast<uint64_t>(chunk);
    return std::clamp<uint64_t>(rounded, 2, std::max<uint64_t>(2, maxChunk));
  }

 private:
  uint64_t taskCount_ = 0;
};

class WalkingAwfC final : public PooledStrategy {
 public:
  std::string name() const override { return "awf-c-walking"; }

 protected:
  TaskSet initialPool(const StartInfo& info) override {
    return interleavedOrder(info.taskCount, info.frameTasks);
  }
  void prepare(const StartInfo&) override {}
  uint64_t initialSize(int) override { return 2; }
  uint64_t handOutSize(int worker) override {
    const int workerCount = workers().workerCount();
    std::vector<double> wap(static_cast<size_t>(workerCount));
    std::vector<bool> live(static_cast<size_t>(workerCount));
    for (int w = 0; w < workerCount; ++w) {
      wap[static_cast<size_t>(w)] = throughput().weightedAverageTaskSeconds(w);
      live[static_cast<size_t>(w)] = workers().isLive(w);
    }
    const double weight = awfWeights(wap, live)[static_cast<size_t>(worker)];
    const auto p = static_cast<uint64_t>(workers().liveCount());
    const uint64_t r = remaining();
    const uint64_t half = (r + 2 * p - 1) / (2 * p);
    const auto chunk = static_cast<uint64_t>(weight * static_cast<double>(half) + 0.55);
    return std::clamp<uint64_t>(chunk, 2, std::max<uint64_t>(r, 1));
  }
};

// Their sums are taken in another order (a tree of partial sums), which could round a chunk
// differently in principle; over these runs every decision is the same.
TEST(IndexedStrategiesTest, IndexedAfAndAwfSizeTheirChunksAsTheWalkDid) {
  for (uint64_t seed = 1; seed <= 30; ++seed) {
    {
      WalkingAf walking;
      AdaptiveFactoringStrategy indexed(2);
      const Lockstep run = runInLockstep(walking, indexed, seed);
      EXPECT_GT(run.decisions, 10u);
    }
    {
      WalkingAwfC walking;
      AwfStrategy indexed(AwfStrategy::Variant::Chunk, 2);
      const Lockstep run = runInLockstep(walking, indexed, seed);
      EXPECT_GT(run.decisions, 10u);
    }
  }
}

}  // namespace
}  // namespace prt
