// FinishOrder against a plain list of the same entries, over random inserts, updates and
// removals; and the indexed adaptive reservoir against the walk over all workers it replaced
// (kept here as the reference), decision for decision under the scripted master.

#include <gtest/gtest.h>

#include <algorithm>
#include <map>
#include <random>

#include "balance/adaptive_reservoir.h"
#include "balance/fake_master.h"
#include "balance/finish_order.h"
#include "balance/interleaved_order.h"
#include "balance/reservoir_math.h"
#include "core/check.h"

namespace prt {
namespace {

struct Plain {
  std::map<int, FinishOrder::Entry> entries;
  // In the order's order: key ascending, ties by worker descending.
  std::vector<std::pair<int, FinishOrder::Entry>> sorted() const {
    std::vector<std::pair<int, FinishOrder::Entry>> out(entries.begin(), entries.end());
    std::sort(out.begin(), out.end(), [](const auto& x, const auto& y) {
      return x.second.key < y.second.key || (x.second.key == y.second.key && x.first > y.first);
    });
    return out;
  }
};

TEST(FinishOrderTest, AgreesWithAPlainListOverRandomChanges) {
  std::mt19937_64 random(7);
  FinishOrder order;
  Plain plain;
  for (int step = 0; step < 4000; ++step) {
    const int worker = static_cast<int>(random() % 64);
    if (random() % 4 == 0) {
      order.erase(worker);
      plain.entries.erase(worker);
    } else {
      // Few distinct keys, so that ties are common.
      const FinishOrder::Entry e{static_cast<double>(random() % 16),
                                 static_cast<double>(random() % 100), static_cast<double>(random() % 7),
                                 static_cast<double>(random() % 3), random() % 3 != 0};
      order.set(worker, e);
      plain.entries[worker] = e;
    }
    const auto sorted = plain.sorted();
    const FinishOrder::Sums total = order.total();
    ASSERT_EQ(total.count, static_cast<int>(sorted.size()));
    double a = 0;
    for (const auto& [w, e] : sorted) a += e.a;
    EXPECT_EQ(total.a, a);  // integers: exact in any order
    // below(): entries of key < k.
    const double k = static_cast<double>(random() % 17);
    double b = 0;
    int count = 0;
    for (const auto& [w, e] : sorted) {
      if (e.key < k) {
        b += e.b;
        ++count;
      }
    }
    const FinishOrder::Sums below = order.below(k);
    EXPECT_EQ(below.b, b);
    EXPECT_EQ(below.count, count);
    // prefixWhile(): the longest prefix whose running sum of a before each entry stays below
    // a limit (true, then false: monotone).
    const double limit = static_cast<double>(random() % 2000);
    int prefix = 0;
    double running = 0;
    for (const auto& [w, e] : sorted) {
      if (!(running < limit)) break;
      running += e.a;
      ++prefix;
    }
    const FinishOrder::Sums taken =
        order.prefixWhile([&](const FinishOrder::Sums& before, double) { return before.a < limit; });
    EXPECT_EQ(taken.count, prefix);
    // lastEligible(): the last eligible entry in the order.
    int last = -1;
    for (const auto& [w, e] : sorted) {
      if (e.eligible) last = w;
    }
    EXPECT_EQ(order.lastEligible(), last);
    for (const auto& [w, e] : plain.entries) {
      ASSERT_TRUE(order.contains(w));
      EXPECT_EQ(order.entry(w).key, e.key);
    }
  }
}

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
  std::vector<double> rates() const {
    std::vector<double> out(static_cast<size_t>(workers().workerCount()), 0.0);
    const std::vector<double>& index = speedIndexSeconds();
    double rateTimesIndex = 0;
    int measured = 0;
    for (int w : workers().liveList()) {
      if (throughput().measured(w)) {
        out[static_cast<size_t>(w)] = throughput().rate(w);
        rateTimesIndex += out[static_cast<size_t>(w)] * index[static_cast<size_t>(w)];
        ++measured;
      }
    }
    if (measured == 0) return out;
    for (int w : workers().liveList()) {
      if (!throughput().measured(w)) {
        out[static_cast<size_t>(w)] = rateTimesIndex / measured / index[static_cast<size_t>(w)];
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

TEST(FinishOrderTest, TheIndexedAdaptiveReservoirDecidesAsTheWalkOverAllWorkersDid) {
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
// losses and joins; both strategies see the same events as long as they decide alike.
TEST(FinishOrderTest, TheIndexedAdaptiveReservoirStealsAsTheWalkDidUnderRandomEvents) {
  uint64_t steals = 0;
  uint64_t decisions = 0;
  for (uint64_t seed = 1; seed <= 60; ++seed) {
    std::mt19937_64 random(seed);
    const int workers = 3 + static_cast<int>(seed % 13);
    std::vector<double> speeds;
    for (int w = 0; w < workers; ++w) speeds.push_back(1.0 + static_cast<double>(random() % 4));
    WalkingAdaptive walking(2);
    AdaptiveReservoirStrategy indexed(10, 50, 2);
    std::vector<TaskSet> queue(static_cast<size_t>(workers));
    std::vector<bool> lost(static_cast<size_t>(workers), false);
    auto both = [&](auto&& call) {
      const Decisions a = call(static_cast<Strategy&>(walking));
      const Decisions b = call(static_cast<Strategy&>(indexed));
      EXPECT_EQ(a, b) << "seed " << seed;
      for (const Decision& d : a) {
        ++decisions;
        if (const auto* as = std::get_if<Assign>(&d)) {
          queue[static_cast<size_t>(as->worker)].append(as->tasks);
        } else if (const auto* t = std::get_if<Transfer>(&d)) {
          ++steals;
          TaskSet& from = queue[static_cast<size_t>(t->from)];
          const TaskSet moved = from.takeBack(std::min(t->count, from.size()));
          queue[static_cast<size_t>(t->to)].append(moved);
        }
      }
      return a == b;
    };
    const StartInfo info{3000, speeds};
    ASSERT_TRUE(both([&](Strategy& s) { return s.start(info); }));
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
        ASSERT_TRUE(both([&](Strategy& s) { return s.onWorkerLost(w, unfinished); }));
        continue;
      }
      if (random() % 500 == 0) {  // a newcomer
        const int joiner = static_cast<int>(queue.size());
        queue.emplace_back();
        lost.push_back(false);
        const double index = 1.0 + static_cast<double>(random() % 4);
        ASSERT_TRUE(both([&](Strategy& s) { return s.onWorkerJoined(joiner, index); }));
        ASSERT_TRUE(both([&](Strategy& s) { return s.onRequest(joiner); }));
      }
      const uint64_t n = std::min<uint64_t>(1 + random() % 16, queue[i].size());
      const TaskSet done = queue[i].takeFront(n);
      const double seconds = static_cast<double>(n) * speeds[i % speeds.size()] *
                             (0.5 + static_cast<double>(random() % 1000) / 1000.0);
      ASSERT_TRUE(both([&](Strategy& s) { return s.onResults(w, done, seconds); }));
      if (queue[i].empty()) {
        ASSERT_TRUE(both([&](Strategy& s) { return s.onRequest(w); }));
      }
    }
  }
  EXPECT_GT(decisions, 4000u);
  EXPECT_GT(steals, 200u);  // the end game was compared, not only the hand-outs
}

}  // namespace
}  // namespace prt
