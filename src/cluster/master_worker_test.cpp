// The master and worker state machines driven together by a deterministic in-memory network:
// no threads, no clock. Every strategy must get every pixel rendered, exactly once when no
// worker fails, and recover a lost worker's tasks.

#include <gtest/gtest.h>

#include <deque>

#include "cluster/master.h"
#include "cluster/worker.h"

namespace prt {
namespace {

struct InMemoryRun {
  std::vector<int> deliveries;  // per pixel: how many times results arrived
  bool complete = false;
  uint64_t steps = 0;
  uint64_t messages = 0;
};

// Worker w renders one batch every (1 + w % 3) rounds, so workers have different speeds.
// `loseAfterBatches[w]` > 0 makes worker w vanish after that many batches.
InMemoryRun runInMemory(const std::string& strategy, int workers, uint64_t pixels,
                        std::vector<int> loseAfterBatches = {}) {
  InMemoryRun run;
  run.deliveries.assign(pixels, 0);
  loseAfterBatches.resize(static_cast<size_t>(workers), 0);
  Master master(makeStrategy(strategy, StrategyOptions{80, 5}), workers, pixels,
                SceneMsg{"scene", 1, 1}, [&](int, const TaskSet& tasks, const std::vector<float>& rgb) {
                  size_t i = 0;
                  tasks.forEach([&](uint64_t p) {
                    EXPECT_EQ(rgb[i], static_cast<float>(p));  // colours travel with positions
                    ++run.deliveries[p];
                    i += 3;
                  });
                });
  std::vector<Worker> ws;
  for (int w = 0; w < workers; ++w) ws.emplace_back(w, WorkerOptions{7});
  std::vector<int> batches(static_cast<size_t>(workers), 0);
  std::vector<bool> gone(static_cast<size_t>(workers), false);
  struct InFlight { int from; Envelope envelope; };
  std::deque<InFlight> network;
  auto post = [&](int from, const Outbox& out) {
    for (const Envelope& e : out) network.push_back({from, e});
  };
  post(kMaster, master.start());
  for (uint64_t round = 0; round < 1000000 && !master.complete() && !master.failed(); ++round) {
    while (!network.empty()) {
      InFlight m = std::move(network.front());
      network.pop_front();
      ++run.messages;
      if (m.envelope.to == kMaster) {
        post(kMaster, master.onMessage(m.from, m.envelope.message));
      } else if (!gone[static_cast<size_t>(m.envelope.to)]) {
        post(m.envelope.to, ws[static_cast<size_t>(m.envelope.to)].onMessage(m.from, m.envelope.message));
      }
    }
    for (int w = 0; w < workers; ++w) {
      Worker& worker = ws[static_cast<size_t>(w)];
      if (gone[static_cast<size_t>(w)]) continue;
      if (worker.needsSetup()) {
        post(w, worker.setupDone(0.1 * (1 + w % 3)));
      } else if (worker.hasWork() && round % static_cast<uint64_t>(1 + w % 3) == 0) {
        const TaskSet batch = worker.nextBatch();
        std::vector<float> rgb;
        batch.forEach([&](uint64_t p) { rgb.insert(rgb.end(), 3, static_cast<float>(p)); });
        post(w, worker.batchDone(batch, std::move(rgb)));
        const int limit = loseAfterBatches[static_cast<size_t>(w)];
        if (limit > 0 && ++batches[static_cast<size_t>(w)] == limit) {
          gone[static_cast<size_t>(w)] = true;
          post(kMaster, master.onWorkerLost(w));
        }
      }
    }
    ++run.steps;
  }
  run.complete = master.complete();
  return run;
}

class MasterWorkerTest : public ::testing::TestWithParam<std::string> {};

TEST_P(MasterWorkerTest, EveryPixelExactlyOnce) {
  for (int workers : {1, 2, 3, 4, 7, 16}) {
    for (uint64_t pixels : {16ull, 100ull, 999ull}) {
      if (static_cast<uint64_t>(workers) > pixels) continue;
      const InMemoryRun run = runInMemory(GetParam(), workers, pixels);
      ASSERT_TRUE(run.complete) << workers << " workers, " << pixels << " pixels";
      for (uint64_t p = 0; p < pixels; ++p) {
        ASSERT_EQ(run.deliveries[p], 1) << "pixel " << p << ", " << workers << " workers";
      }
    }
  }
}

TEST_P(MasterWorkerTest, LostWorkersTasksAreRecovered) {
  for (int workers : {2, 3, 5}) {
    std::vector<int> lose(static_cast<size_t>(workers), 0);
    lose[0] = 2;                  // the first worker vanishes after two batches
    if (workers > 2) lose[2] = 1;  // and another after one
    const InMemoryRun run = runInMemory(GetParam(), workers, 500, lose);
    ASSERT_TRUE(run.complete) << workers << " workers";
    for (uint64_t p = 0; p < 500; ++p) ASSERT_GE(run.deliveries[p], 1) << "pixel " << p;
  }
}

INSTANTIATE_TEST_SUITE_P(AllStrategies, MasterWorkerTest, ::testing::ValuesIn(strategyNames()));

TEST(MasterTest, WorkerLostBeforeTheStartGetsNothing) {
  for (const std::string& name : strategyNames()) {
    Master master(makeStrategy(name, {}), 3, 30, SceneMsg{}, nullptr);
    master.start();
    master.onMessage(0, SpeedIndexMsg{0.1});
    master.onWorkerLost(1);
    const Outbox out = master.onMessage(2, SpeedIndexMsg{0.2});
    uint64_t assigned = 0;
    for (const Envelope& e : out) {
      EXPECT_NE(e.to, 1) << name;
      if (const auto* t = std::get_if<TasksMsg>(&e.message)) assigned += t->tasks.size();
    }
    EXPECT_EQ(assigned > 0, true) << name;
    EXPECT_TRUE(master.isLive(0));
    EXPECT_FALSE(master.isLive(1));
  }
}

TEST(MasterTest, EveryWorkerLostIsAFailureNotAHang) {
  Master master(makeStrategy("scatter", {}), 2, 10, SceneMsg{}, nullptr);
  master.start();
  master.onWorkerLost(0);
  EXPECT_FALSE(master.failed());
  master.onWorkerLost(1);
  EXPECT_TRUE(master.failed());
}

TEST(MasterTest, OwesAnswerTracksSpeedIndexAndHeldWork) {
  Master master(makeStrategy("blocks", {}), 2, 10, SceneMsg{}, nullptr);
  master.start();
  EXPECT_TRUE(master.owesAnswer(0));
  master.onMessage(0, SpeedIndexMsg{0.1});
  EXPECT_FALSE(master.owesAnswer(0));
  master.onMessage(1, SpeedIndexMsg{0.1});
  EXPECT_TRUE(master.owesAnswer(0));  // now holds its block
  master.onMessage(0, ResultsMsg{TaskSet::range(0, 5), std::vector<float>(15, 0.f)});
  EXPECT_FALSE(master.owesAnswer(0));
  EXPECT_TRUE(master.owesAnswer(1));
}

}  // namespace
}  // namespace prt
