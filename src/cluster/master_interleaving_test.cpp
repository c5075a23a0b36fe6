// The master and worker state machines under random interleavings: each link keeps its
// messages in order (as every transport does), but which link delivers next, and which worker
// finishes a batch next, is drawn at random. Real runs differ from the deterministic
// in-memory network (master_worker_test.cpp) exactly there, and a run must finish, with every
// pixel right, whatever the order.

#include <gtest/gtest.h>

#include <deque>
#include <map>
#include <random>
#include <utility>

#include "balance/registry.h"
#include "cluster/master.h"
#include "cluster/worker.h"

namespace prt {
namespace {

struct Scenario {
  std::string strategy;
  int workers = 4;
  uint64_t pixels = 600;
  std::vector<bool> corrupt;    // per worker: every third pixel of its own wrong
  std::vector<int> corruptAfter;  // per worker: ... once it has rendered this many pixels
  uint64_t batch = 7;
  std::vector<int> crashAfter;  // per worker: lost after that many batches (0: never)
  double verifyPercent = 10;
  std::vector<int> speed;  // per worker: how many turns it gets for one of a speed-1 worker
};

struct Outcome {
  bool complete = false;
  bool failed = false;
  std::vector<float> values;
  std::string state;  // what was left, when the run did not finish
  std::vector<RejectedWorker> rejections;
};

Outcome runShuffled(const Scenario& s, uint32_t seed) {
  std::mt19937 rng(seed);
  Outcome result;
  result.values.assign(s.pixels, -1);
  MasterOptions options;
  options.checks = {s.verifyPercent, seed};
  options.referee = [](const TaskSet& pixels) {
    std::vector<float> rgb;
    pixels.forEach([&](uint64_t p) { rgb.insert(rgb.end(), 3, static_cast<float>(p)); });
    return rgb;
  };
  options.takenBack = [&](int, const TaskSet& tasks) {
    tasks.forEach([&](uint64_t p) { result.values[p] = -1; });
  };
  Master master(makeStrategy(s.strategy, StrategyOptions{80, 5}), s.workers, s.pixels,
                SceneMsg{"scene", 1, 1},
                [&](int, const TaskSet& tasks, const std::vector<float>& rgb) {
                  size_t i = 0;
                  tasks.forEach([&](uint64_t p) {
                    result.values[p] = rgb[i];
                    i += 3;
                  });
                },
                std::move(options));
  std::vector<Worker> ws;
  for (int w = 0; w < s.workers; ++w) ws.emplace_back(w, WorkerOptions{s.batch});
  std::vector<int> batches(static_cast<size_t>(s.workers), 0);
  std::vector<uint64_t> rendered(static_cast<size_t>(s.workers), 0);
  std::vector<bool> gone(static_cast<size_t>(s.workers), false);
  std::map<std::pair<int, int>, std::deque<Message>> links;  // (from, to) -> in order
  auto post = [&](int from, const Outbox& out) {
    for (const Envelope& e : out) links[{from, e.to}].push_back(e.message);
  };
  auto corrupt = [&](int w) { return w < static_cast<int>(s.corrupt.size()) && s.corrupt[w]; };
  auto crashAfter = [&](int w) {
    return w < static_cast<int>(s.crashAfter.size()) ? s.crashAfter[w] : 0;
  };
  double now = 0;
  post(kMaster, master.start(now));
  for (int step = 0; step < 200000 && !master.complete() && !master.failed(); ++step) {
    now += 0.001;
    // The choices: a link with a message, or a worker with work to finish a batch of.
    std::vector<std::pair<int, int>> ready;
    for (const auto& [link, queue] : links) {
      if (!queue.empty()) ready.push_back(link);
    }
    std::vector<int> busy;
    for (int w = 0; w < s.workers; ++w) {
      if (gone[w] || !(ws[w].needsSetup() || ws[w].hasWork())) continue;
      const int turns = w < static_cast<int>(s.speed.size()) ? s.speed[w] : 1;
      for (int i = 0; i < turns; ++i) busy.push_back(w);
    }
    if (ready.empty() && busy.empty()) break;  // nothing can ever happen again
    const size_t pick = std::uniform_int_distribution<size_t>(0, ready.size() + busy.size() - 1)(rng);
    if (pick < ready.size()) {
      const auto [from, to] = ready[pick];
      Message m = std::move(links[{from, to}].front());
      links[{from, to}].pop_front();
      if (to == kMaster) {
        post(kMaster, master.onMessage(from, m, now));
      } else if (!gone[to]) {
        post(to, ws[to].onMessage(from, m));
      }
      continue;
    }
    const int w = busy[pick - ready.size()];
    Worker& worker = ws[w];
    if (worker.needsSetup()) {
      post(w, worker.setupDone(0.1 * (1 + w % 3)));
      continue;
    }
    const TaskSet batch = worker.nextBatch();
    std::vector<float> rgb;
    batch.forEach([&](uint64_t p) {
      const bool late = w < static_cast<int>(s.corruptAfter.size()) &&
                        rendered[w] < static_cast<uint64_t>(s.corruptAfter[w]);
      ++rendered[w];
      const bool wrong = corrupt(w) && !late && p % 3 == 0;
      rgb.insert(rgb.end(), 3, static_cast<float>(p) + (wrong ? 0.5f : 0.0f));
    });
    post(w, worker.batchDone(batch, std::move(rgb), 0.001 * static_cast<double>(batch.size()) * (1 + w % 3)));
    if (crashAfter(w) > 0 && ++batches[w] == crashAfter(w)) {
      gone[w] = true;
      post(kMaster, master.onWorkerLost(w, now, "test"));
    }
  }
  result.complete = master.complete();
  result.failed = master.failed();
  result.rejections = master.rejections();
  if (!result.complete) {
    uint64_t missing = 0;
    for (float v : result.values) missing += v < 0;
    result.state = std::to_string(missing) + " pixels missing;";
    for (int w = 0; w < s.workers; ++w) {
      result.state += " worker " + std::to_string(w) + (gone[w] ? " gone" : "") +
                      (ws[w].stopped() ? " stopped" : "") + " queue " +
                      std::to_string(ws[w].queueLength()) + ";";
    }
  }
  return result;
}

void expectEveryPixelRight(const Scenario& s, uint32_t seeds) {
  for (uint32_t seed = 1; seed <= seeds; ++seed) {
    const Outcome o = runShuffled(s, seed);
    ASSERT_TRUE(o.complete) << s.strategy << ", seed " << seed << ": " << o.state;
    // Only a corrupt worker is rejected: a transfer notice that arrives before the notice of
    // the transfer it passes on is not taken for a lie.
    for (const RejectedWorker& r : o.rejections) {
      const auto w = static_cast<size_t>(r.worker);
      ASSERT_TRUE(w < s.corrupt.size() && s.corrupt[w])
          << s.strategy << ", seed " << seed << ": worker " << r.worker << " rejected: " << r.reason;
    }
    for (uint64_t p = 0; p < s.pixels; ++p) {
      ASSERT_EQ(o.values[p], static_cast<float>(p)) << s.strategy << ", seed " << seed
                                                     << ", pixel " << p;
    }
  }
}

class InterleavingTest : public ::testing::TestWithParam<std::string> {};

TEST_P(InterleavingTest, EveryPixelArrivesWhateverTheOrder) {
  Scenario s;
  s.strategy = GetParam();
  expectEveryPixelRight(s, 40);
}

TEST_P(InterleavingTest, TwoCorruptWorkersAreRejectedWhateverTheOrder) {
  Scenario s;
  s.strategy = GetParam();
  s.corrupt = {true, false, true, false};
  expectEveryPixelRight(s, 60);
  // As the fault test has it: one turns wrong late, after most of its share.
  s.pixels = 3072;
  s.batch = 16;
  s.corruptAfter = {600, 0, 100, 0};
  s.speed = {1, 3, 2, 1};
  expectEveryPixelRight(s, 200);
}

TEST_P(InterleavingTest, CrashesAndACorruptWorkerTogether) {
  Scenario s;
  s.strategy = GetParam();
  s.workers = 5;
  s.corrupt = {false, true, false, false, false};
  s.crashAfter = {0, 0, 3, 0, 6};
  expectEveryPixelRight(s, 40);
}

INSTANTIATE_TEST_SUITE_P(AllStrategies, InterleavingTest, ::testing::ValuesIn(strategyNames()));

}  // namespace
}  // namespace prt
