// The master and worker state machines driven together by a deterministic in-memory network:
// no threads, no clock. Every strategy must get every pixel rendered, exactly once when no
// worker fails, and recover a lost worker's tasks.

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <deque>
#include <memory>

#include "cluster/master.h"
#include "cluster/worker.h"

namespace prt {
namespace {

struct InMemoryRun {
  std::vector<int> deliveries;  // per pixel: how many times results arrived
  std::vector<float> values;    // per pixel: the red channel in the image (-1: none)
  bool complete = false;
  uint64_t steps = 0;
  uint64_t messages = 0;
  int joined = 0;
};

// Worker w renders one batch every (1 + w % 3) rounds, so workers have different speeds.
// `loseAfterBatches[w]` > 0 makes worker w vanish after that many batches. Each entry of
// `joinRounds` makes one more worker join at the start of that round (workers, workers+1, ...).
InMemoryRun runInMemory(const std::string& strategy, int workers, uint64_t pixels,
                        std::vector<int> loseAfterBatches = {}, MasterOptions options = {},
                        StrategyOptions strategyOptions = StrategyOptions{80, 5},
                        const std::vector<uint64_t>& joinRounds = {},
                        std::vector<bool> corrupt = {}) {
  InMemoryRun run;
  run.deliveries.assign(pixels, 0);
  run.values.assign(pixels, -1);
  loseAfterBatches.resize(static_cast<size_t>(workers) + joinRounds.size(), 0);
  corrupt.resize(loseAfterBatches.size(), false);
  const bool anyCorrupt = std::find(corrupt.begin(), corrupt.end(), true) != corrupt.end();
  options.takenBack = [&](int, const TaskSet& tasks) {
    tasks.forEach([&](uint64_t p) { run.values[p] = -1; });
  };
  Master master(makeStrategy(strategy, strategyOptions), workers, pixels,
                SceneMsg{"scene", 1, 1}, [&](int, const TaskSet& tasks, const std::vector<float>& rgb) {
                  size_t i = 0;
                  tasks.forEach([&](uint64_t p) {
                    // Colours travel with positions.
                    if (!anyCorrupt) {
                      EXPECT_EQ(rgb[i], static_cast<float>(p));
                    }
                    ++run.deliveries[p];
                    run.values[p] = rgb[i];
                    i += 3;
                  });
                }, std::move(options));
  std::vector<Worker> ws;
  for (int w = 0; w < workers; ++w) ws.emplace_back(w, WorkerOptions{7});
  std::vector<int> batches(static_cast<size_t>(workers), 0);
  std::vector<bool> gone(static_cast<size_t>(workers), false);
  struct InFlight { int from; Envelope envelope; };
  std::deque<InFlight> network;
  auto post = [&](int from, const Outbox& out) {
    for (const Envelope& e : out) network.push_back({from, e});
  };
  post(kMaster, master.start(0));
  for (uint64_t round = 0; round < 1000000 && !master.complete() && !master.failed(); ++round) {
    for (uint64_t at : joinRounds) {
      if (at != round) continue;
      const int id = static_cast<int>(ws.size());
      ws.emplace_back(id, WorkerOptions{7});
      batches.push_back(0);
      gone.push_back(false);
      post(kMaster, master.onWorkerJoined(id, static_cast<double>(round)));
      ++run.joined;
    }
    while (!network.empty()) {
      InFlight m = std::move(network.front());
      network.pop_front();
      ++run.messages;
      if (m.envelope.to == kMaster) {
        post(kMaster, master.onMessage(m.from, m.envelope.message, static_cast<double>(round)));
      } else if (!gone[static_cast<size_t>(m.envelope.to)]) {
        post(m.envelope.to, ws[static_cast<size_t>(m.envelope.to)].onMessage(m.from, m.envelope.message));
      }
    }
    for (int w = 0; w < static_cast<int>(ws.size()); ++w) {
      Worker& worker = ws[static_cast<size_t>(w)];
      if (gone[static_cast<size_t>(w)]) continue;
      if (worker.needsSetup()) {
        post(w, worker.setupDone(0.1 * (1 + w % 3)));
      } else if (worker.hasWork() && round % static_cast<uint64_t>(1 + w % 3) == 0) {
        const TaskSet batch = worker.nextBatch();
        std::vector<float> rgb;
        batch.forEach([&](uint64_t p) {
          // A corrupt worker gets every third pixel wrong (by a little: a bit of it).
          const bool wrong = corrupt[static_cast<size_t>(w)] && p % 3 == 0;
          rgb.insert(rgb.end(), 3, static_cast<float>(p) + (wrong ? 0.5f : 0.0f));
        });
        post(w, worker.batchDone(batch, std::move(rgb)));
        const int limit = loseAfterBatches[static_cast<size_t>(w)];
        if (limit > 0 && ++batches[static_cast<size_t>(w)] == limit) {
          gone[static_cast<size_t>(w)] = true;
          post(kMaster, master.onWorkerLost(w, static_cast<double>(round), "test"));
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
    for (uint64_t p = 0; p < 500; ++p) ASSERT_EQ(run.deliveries[p], 1) << "pixel " << p;
  }
}

// The lost worker held every task and the others had been given nothing: the tasks must still
// reach them (they never asked, so the master enters their request at the start).
TEST_P(MasterWorkerTest, LostWorkerHoldingEverythingIsReplaced) {
  for (int workers : {2, 3}) {
    std::vector<int> lose(static_cast<size_t>(workers), 0);
    lose[0] = 1;
    // 16 pixels and a chunk of 64: self-scheduling and the reservoir give worker 0 everything.
    const InMemoryRun run =
        runInMemory(GetParam(), workers, 16, lose, {}, StrategyOptions{80, 64});
    ASSERT_TRUE(run.complete) << workers << " workers";
    for (uint64_t p = 0; p < 16; ++p) ASSERT_EQ(run.deliveries[p], 1) << "pixel " << p;
  }
}

// An initial share that rounds to nothing: the workers ask, nobody waits forever.
TEST_P(MasterWorkerTest, TinyInitialShareStillFinishes) {
  const InMemoryRun run = runInMemory(GetParam(), 3, 200, {}, {}, StrategyOptions{1e-14, 5});
  ASSERT_TRUE(run.complete);
  for (uint64_t p = 0; p < 200; ++p) ASSERT_EQ(run.deliveries[p], 1) << "pixel " << p;
}

// Endgame copies never deliver a pixel twice, with or without losses.
TEST_P(MasterWorkerTest, EndgameCopiesAreAcceptedOnce) {
  MasterOptions endgame;
  endgame.endgame = true;
  for (int workers : {2, 3, 5}) {
    const InMemoryRun run = runInMemory(GetParam(), workers, 300, {}, endgame);
    ASSERT_TRUE(run.complete) << workers << " workers";
    for (uint64_t p = 0; p < 300; ++p) ASSERT_EQ(run.deliveries[p], 1) << "pixel " << p;
    std::vector<int> lose(static_cast<size_t>(workers), 0);
    lose[1] = 2;
    const InMemoryRun lossy = runInMemory(GetParam(), workers, 300, lose, endgame);
    ASSERT_TRUE(lossy.complete) << workers << " workers";
    for (uint64_t p = 0; p < 300; ++p) ASSERT_EQ(lossy.deliveries[p], 1) << "pixel " << p;
  }
}

// Resuming: the pixels done before are never handed out, the rest exactly once.
TEST_P(MasterWorkerTest, ResumedPixelsAreNotRenderedAgain) {
  MasterOptions resumed;
  resumed.resumedDone = TaskSet::range(0, 50);
  resumed.resumedDone.append(TaskSet::strided(101, 40, 7));
  const TaskSet done = resumed.resumedDone;
  for (int workers : {1, 3, 4}) {
    const InMemoryRun run = runInMemory(GetParam(), workers, 400, {}, resumed);
    ASSERT_TRUE(run.complete) << workers << " workers";
    std::vector<bool> wasDone(400, false);
    done.forEach([&](uint64_t p) { wasDone[p] = true; });
    for (uint64_t p = 0; p < 400; ++p) {
      ASSERT_EQ(run.deliveries[p], wasDone[p] ? 0 : 1) << "pixel " << p;
    }
  }
}

// Workers join before the start, early and late; every pixel arrives once.
TEST_P(MasterWorkerTest, JoinersAreServedAndEveryPixelArrivesOnce) {
  for (int workers : {1, 2}) {
    const InMemoryRun run =
        runInMemory(GetParam(), workers, 600, {}, {}, StrategyOptions{80, 5}, {0, 3, 3});
    ASSERT_TRUE(run.complete) << workers << " workers";
    EXPECT_EQ(run.joined, 3) << "the run ended before round 40";
    for (uint64_t p = 0; p < 600; ++p) ASSERT_EQ(run.deliveries[p], 1) << "pixel " << p;
  }
}

// Arrivals and losses in one run: a starting worker and a joiner vanish.
TEST_P(MasterWorkerTest, ArrivalsAndLossesTogether) {
  for (bool endgame : {false, true}) {
    MasterOptions options;
    options.endgame = endgame;
    // Workers 0, 1 start; 2, 3, 4 join at rounds 2, 5, 5; 0 and 3 are lost.
    const InMemoryRun run = runInMemory(GetParam(), 2, 500, {2, 0, 0, 1}, options,
                                        StrategyOptions{80, 5}, {2, 5, 5});
    ASSERT_TRUE(run.complete) << (endgame ? "endgame" : "");
    for (uint64_t p = 0; p < 500; ++p) ASSERT_EQ(run.deliveries[p], 1) << "pixel " << p;
  }
}

// The last starting worker is lost while a joiner is still measuring its speed index: the
// joiner is the only live worker, and once measured it gets everything left, for every
// strategy (the image is finished, not left waiting for ever).
TEST_P(MasterWorkerTest, AJoinerTakesOverWhenTheLastStartingWorkerIsLostBeforeItIsMeasured) {
  const uint64_t pixels = 60;
  Master master(makeStrategy(GetParam(), StrategyOptions{8, 2}), 1, pixels, SceneMsg{"s", 1, 1},
                nullptr);
  master.start(0);
  master.onMessage(0, SpeedIndexMsg{0.1}, 0.1);
  Worker joiner(1, WorkerOptions{7});
  std::deque<Envelope> toJoiner;
  auto post = [&](const Outbox& out) {
    for (const Envelope& e : out) {
      if (e.to == 1) toJoiner.push_back(e);
    }
  };
  post(master.onWorkerJoined(1, 0.5));
  post(master.onWorkerLost(0, 0.6, "gone"));
  ASSERT_FALSE(master.failed());
  bool measured = false;
  double now = 1;
  for (int step = 0; step < 10000 && !master.complete(); ++step, now += 0.01) {
    if (!toJoiner.empty()) {
      const Envelope e = toJoiner.front();
      toJoiner.pop_front();
      for (const Envelope& reply : joiner.onMessage(kMaster, e.message)) {
        post(master.onMessage(1, reply.message, now));
      }
    } else if (joiner.needsSetup()) {
      ASSERT_FALSE(measured);
      measured = true;
      for (const Envelope& reply : joiner.setupDone(0.1)) post(master.onMessage(1, reply.message, now));
    } else if (joiner.hasWork()) {
      const TaskSet batch = joiner.nextBatch();
      for (const Envelope& reply : joiner.batchDone(batch, std::vector<float>(3 * batch.size()), 0.01)) {
        post(master.onMessage(1, reply.message, now));
      }
    } else {
      break;  // nothing in flight and nothing to do: stuck
    }
  }
  EXPECT_TRUE(master.complete()) << master.doneCount() << " of " << pixels << " pixels done";
}

INSTANTIATE_TEST_SUITE_P(AllStrategies, MasterWorkerTest, ::testing::ValuesIn(strategyNames()));

TEST(MasterTest, WorkerLostBeforeTheStartGetsNothing) {
  for (const std::string& name : strategyNames()) {
    Master master(makeStrategy(name, {}), 3, 30, SceneMsg{}, nullptr);
    master.start(0);
    master.onMessage(0, SpeedIndexMsg{0.1}, 0);
    master.onWorkerLost(1, 0, "test");
    const Outbox out = master.onMessage(2, SpeedIndexMsg{0.2}, 0);
    uint64_t assigned = 0;
    for (const Envelope& e : out) {
      if (std::holds_alternative<TasksMsg>(e.message)) {
        EXPECT_NE(e.to, 1) << name;
      }
      if (const auto* t = std::get_if<TasksMsg>(&e.message)) assigned += t->tasks.size();
    }
    EXPECT_EQ(assigned > 0, true) << name;
    EXPECT_TRUE(master.isLive(0));
    EXPECT_FALSE(master.isLive(1));
  }
}

TEST(MasterTest, AJoinerGetsTheSceneThenTasksAndOneAfterTheEndIsStopped) {
  Master master(makeStrategy("self", StrategyOptions{.chunk = 10}), 1, 100, SceneMsg{"s", 1, 1},
                nullptr);
  master.start(0);
  master.onMessage(0, SpeedIndexMsg{0.1}, 0.1);  // the strategy starts: worker 0 gets 10
  Outbox joined = master.onWorkerJoined(1, 1.0);
  ASSERT_EQ(joined.size(), 1u);
  EXPECT_EQ(joined[0].to, 1);
  EXPECT_TRUE(std::holds_alternative<SceneMsg>(joined[0].message));
  EXPECT_EQ(master.workerCount(), 2);
  EXPECT_EQ(master.ledger().joinedAt(1), 1.0);
  // Out of turn: a driver numbers joiners in arrival order.
  EXPECT_DEATH(master.onWorkerJoined(3, 1.0), "");
  const Outbox served = master.onMessage(1, SpeedIndexMsg{0.1}, 1.5);
  ASSERT_EQ(served.size(), 1u);
  EXPECT_EQ(served[0].to, 1);
  ASSERT_TRUE(std::holds_alternative<TasksMsg>(served[0].message));
  EXPECT_EQ(std::get<TasksMsg>(served[0].message).tasks, TaskSet::range(10, 10));
  // A speed index that is no number: the joiner is lost, its tasks go back to the pool.
  master.onWorkerJoined(2, 2.0);
  master.onMessage(2, SpeedIndexMsg{std::nan("")}, 2.1);
  EXPECT_FALSE(master.isLive(2));
  // Finish, then another arrives: it is told to stop.
  Master small(makeStrategy("blocks", {}), 1, 4, SceneMsg{}, nullptr);
  small.start(0);
  small.onMessage(0, SpeedIndexMsg{0.1}, 0);
  small.onMessage(0, ResultsMsg{TaskSet::range(0, 4), std::vector<float>(12, 0.f)}, 1);
  ASSERT_TRUE(small.complete());
  const Outbox late = small.onWorkerJoined(1, 2);
  ASSERT_EQ(late.size(), 1u);
  EXPECT_TRUE(std::holds_alternative<StopMsg>(late[0].message));
}

// Spot checks find corrupt workers, whatever the strategy: each is rejected (and no correct
// worker ever is), what it delivered is taken back and rendered again, and the image ends up
// right in every pixel.
TEST_P(MasterWorkerTest, CorruptWorkersAreCaughtAndTheirPixelsRenderedAgain) {
  for (const std::vector<bool>& corrupt :
       {std::vector<bool>{false, true, false, false}, std::vector<bool>{true, false, true, false},
        std::vector<bool>{false, true}}) {
    MasterOptions options;
    options.checks = {10, 7};
    int refereed = 0;
    options.referee = [&](const TaskSet& pixels) {
      std::vector<float> rgb;
      pixels.forEach([&](uint64_t p) { rgb.insert(rgb.end(), 3, static_cast<float>(p)); });
      refereed += static_cast<int>(pixels.size());
      return rgb;
    };
    const int workers = static_cast<int>(corrupt.size());
    auto run = runInMemory(GetParam(), workers, 999, {}, options, StrategyOptions{80, 5}, {},
                           corrupt);
    ASSERT_TRUE(run.complete) << workers << " workers";
    for (uint64_t p = 0; p < 999; ++p) {
      ASSERT_EQ(run.values[p], static_cast<float>(p)) << "pixel " << p << ", " << workers;
    }
    EXPECT_GT(refereed, 0);
  }
}

TEST(MasterTest, ARejectedWorkerIsStoppedAndListedWithWhatWasTakenBack) {
  MasterOptions options;
  options.checks = {100, 1};
  options.referee = [](const TaskSet& pixels) {
    return std::vector<float>(3 * pixels.size(), 1.0f);  // the truth: every pixel is 1
  };
  TaskSet back;
  options.takenBack = [&](int w, const TaskSet& t) {
    EXPECT_EQ(w, 1);
    back.append(t);
  };
  Master master(makeStrategy("blocks", {}), 3, 30, SceneMsg{"s", 1, 1},
                [](int, const TaskSet&, const std::vector<float>&) {}, options);
  master.start(0);
  for (int w = 0; w < 3; ++w) master.onMessage(w, SpeedIndexMsg{0.1}, 0);  // 10 pixels each
  // Worker 1 delivers its block wrong; every pixel is checked (100 %) by worker 0 or 2.
  Outbox out = master.onMessage(1, ResultsMsg{TaskSet::range(10, 10), std::vector<float>(30, 2.f)}, 1);
  const auto checksIn = [](const Outbox& o) {
    std::vector<Envelope> checks;
    for (const Envelope& e : o) {
      if (std::holds_alternative<CheckMsg>(e.message)) checks.push_back(e);
    }
    return checks;
  };
  EXPECT_TRUE(checksIn(out).empty()) << "busy checkers get theirs when next heard from";
  out = master.onMessage(0, HeartbeatMsg{}, 1.5);
  const std::vector<Envelope> checks = checksIn(out);
  ASSERT_EQ(checks.size(), 1u);
  EXPECT_EQ(checks[0].to, 0);
  // The first checker answers right: the referee agrees with it, worker 1 is rejected.
  const auto& first = std::get<CheckMsg>(checks[0].message);
  out = master.onMessage(checks[0].to,
                         CheckResultsMsg{first.tasks, std::vector<float>(3 * first.tasks.size(), 1.f)}, 2);
  ASSERT_EQ(master.rejections().size(), 1u);
  const RejectedWorker& r = master.rejections()[0];
  EXPECT_EQ(r.worker, 1);
  EXPECT_EQ(r.pixelsTakenBack, 10u);
  EXPECT_NE(r.reason.find("spot check"), std::string::npos) << r.reason;
  EXPECT_EQ(back, TaskSet::range(10, 10));
  EXPECT_FALSE(master.isLive(1));
  EXPECT_EQ(master.ledger().doneCount(), 0u);
  bool stopped = false, reissued = false;
  for (const Envelope& e : out) {
    stopped = stopped || (e.to == 1 && std::holds_alternative<StopMsg>(e.message));
    if (const auto* t = std::get_if<TasksMsg>(&e.message)) reissued = reissued || (e.to != 1 && !t->tasks.empty());
  }
  EXPECT_TRUE(stopped) << "the rejected worker is told to stop";
  EXPECT_TRUE(reissued) << "its pixels go to the others";
  // Nothing from it counts any more.
  master.onMessage(1, ResultsMsg{TaskSet::range(10, 10), std::vector<float>(30, 1.f)}, 3);
  EXPECT_EQ(master.ledger().doneCount(), 0u);
}

TEST(MasterTest, AMessageThatCannotBeTrueLosesItsWorkerAndCrashesNothing) {
  auto master = [] {
    auto m = std::make_unique<Master>(makeStrategy("blocks", {}), 2, 10, SceneMsg{},
                                      [](int, const TaskSet&, const std::vector<float>&) {});
    m->start(0);
    m->onMessage(0, SpeedIndexMsg{0.1}, 0);
    m->onMessage(1, SpeedIndexMsg{0.1}, 0);
    return m;
  };
  const std::vector<Message> bad = {
      ResultsMsg{TaskSet::range(8, 5), std::vector<float>(15, 0.f)},          // past the image
      ResultsMsg{TaskSet::range(0, 2), std::vector<float>(3, 0.f)},           // too few colours
      ResultsMsg{TaskSet::range(0, 2), {}},                                   // none at all
      ResultsMsg{TaskSet::strided(9, 3, ~uint64_t{0} / 2), std::vector<float>(9, 0.f)},
      TransferNoticeMsg{7, TaskSet::range(0, 1)},                             // to no worker
      TransferNoticeMsg{1, TaskSet::range(20, 1)},
      SpeedIndexMsg{-1.0},
      ResultsMsg{TaskSet::range(0, 2), {0.f, 0.f, 0.f, 0.f, std::nanf(""), 0.f}},  // not colours
      ResultsMsg{TaskSet::range(0, 1), {0.f, INFINITY, 0.f}}};
  for (const Message& m : bad) {
    auto run = master();
    run->onMessage(0, m, 1.0);
    EXPECT_FALSE(run->isLive(0)) << messageName(m);
    EXPECT_TRUE(run->isLive(1));
    ASSERT_EQ(run->ledger().losses().size(), 1u);
    EXPECT_NE(run->ledger().losses()[0].reason.find("invalid"), std::string::npos);
    ASSERT_EQ(run->rejections().size(), 1u) << "what it sent before is as doubtful";
    // Once it has lied, nothing from it counts: a lost worker's late results otherwise do.
    run->onMessage(0, ResultsMsg{TaskSet::range(0, 1), std::vector<float>(3, 0.f)}, 2.0);
    EXPECT_FALSE(run->ledger().isDone(0)) << messageName(m);
  }
}

// A worker of another build is rejected when it says so, with its speed index; the others go
// on, and the machine it named is passed on for the blocklist.
TEST(MasterTest, AWorkerOfAnotherVersionIsRejectedAtItsSpeedIndex) {
  MasterOptions options;
  options.admit = [](const WorkerIdentity& id) {
    return id.build == "prt 1" ? std::string() : "it runs '" + id.build + "'";
  };
  std::vector<std::string> blocked;
  options.rejected = [&](const RejectedWorker& r) { blocked.push_back(r.host); };
  Master master(makeStrategy("blocks", {}), 2, 10, SceneMsg{"s", 1, 1}, nullptr, options);
  master.start(0);
  master.onMessage(0, SpeedIndexMsg{0.1, {"prt 1", "a"}}, 0);
  const Outbox out = master.onMessage(1, SpeedIndexMsg{0.1, {"prt 2", "b"}}, 0);
  EXPECT_FALSE(master.isLive(1));
  ASSERT_EQ(master.rejections().size(), 1u);
  EXPECT_EQ(master.rejections()[0].reason, "it runs 'prt 2'");
  EXPECT_EQ(blocked, std::vector<std::string>{"b"});
  bool started = false;
  for (const Envelope& e : out) started = started || (e.to == 0 && std::holds_alternative<TasksMsg>(e.message));
  EXPECT_TRUE(started) << "the run starts without it";
  EXPECT_EQ(master.identity(0).host, "a");
}

// Results for pixels nobody was given yet (a process that joined only to paint the image, or a
// correct worker another process sent those tasks to) are dropped; the rest of the batch, and
// the sender, count.
TEST(MasterTest, ResultsForPixelsNeverHandedOutAreDropped) {
  StrategyOptions options;
  options.chunk = 10;
  Master master(makeStrategy("self", options), 2, 1000, SceneMsg{"s", 1, 1},
                [](int, const TaskSet&, const std::vector<float>&) {});
  master.start(0);
  master.onMessage(0, SpeedIndexMsg{0.1}, 0);
  master.onMessage(1, SpeedIndexMsg{0.1}, 0);  // 10 pixels each, the rest in the pool
  ASSERT_FALSE(master.ledger().allHandedOut(TaskSet::range(900, 1)));
  master.onMessage(1, ResultsMsg{TaskSet::range(900, 100), std::vector<float>(300, 1.f)}, 1);
  EXPECT_EQ(master.ledger().doneCount(), 0u);
  EXPECT_TRUE(master.isLive(1));
  EXPECT_TRUE(master.rejections().empty());
  // Its own pixels with others: the own ones count.
  const TaskSet own = master.ledger().unfinished(1);
  ASSERT_FALSE(own.empty());
  TaskSet mixed = own;
  mixed.append(TaskSet::range(950, 3));
  master.onMessage(1, ResultsMsg{mixed, std::vector<float>(3 * mixed.size(), 1.f)}, 2);
  EXPECT_EQ(master.ledger().doneCount(), own.size());
  EXPECT_FALSE(master.ledger().holdsWork(1));
}

// A joiner still measuring its speed index is unknown to the strategy: a diffusion round does
// not ask it for its queue (it would answer only once measured, holding the round up that long).
TEST(MasterTest, ADiffusionRoundDoesNotWaitForAJoinerStillMeasuring) {
  Master master(makeStrategy("hybrid", {}), 2, 100, SceneMsg{"s", 1, 1}, nullptr);
  master.start(0);
  master.onMessage(0, SpeedIndexMsg{0.1}, 0.1);
  master.onMessage(1, SpeedIndexMsg{0.1}, 0.1);  // scatter: 50 pixels each
  master.onWorkerJoined(2, 0.5);                  // measuring from now on
  master.onMessage(0, ResultsMsg{TaskSet::range(0, 50), {}}, 1.0);
  ASSERT_FALSE(master.ledger().holdsWork(0));
  const Outbox query = master.onMessage(0, RequestMsg{}, 1.0);
  int asked = 0;
  for (const Envelope& e : query) {
    if (!std::holds_alternative<QueryQueueMsg>(e.message)) continue;
    EXPECT_NE(e.to, 2) << "the joiner was asked for its queue before the strategy knew of it";
    ++asked;
  }
  EXPECT_EQ(asked, 2);
  master.onMessage(0, QueueLengthMsg{0}, 1.1);
  const Outbox moves = master.onMessage(1, QueueLengthMsg{50}, 1.1);
  bool transfer = false;
  for (const Envelope& e : moves) {
    if (const auto* t = std::get_if<TransferOrderMsg>(&e.message)) {
      transfer = e.to == 1 && t->to == 0;
    }
  }
  EXPECT_TRUE(transfer) << "the round waited for the joiner";
}

TEST(MasterTest, EveryWorkerLostIsAFailureNotAHang) {
  Master master(makeStrategy("scatter", {}), 2, 10, SceneMsg{}, nullptr);
  master.start(0);
  master.onWorkerLost(0, 0, "test");
  EXPECT_FALSE(master.failed());
  master.onWorkerLost(1, 0, "test");
  EXPECT_TRUE(master.failed());
}

TEST(MasterTest, SilentWorkersLoseTheirLeaseAndTheirTasksMove) {
  Master master(makeStrategy("blocks", {}), 2, 10, SceneMsg{}, nullptr);
  master.start(0);
  master.onMessage(0, SpeedIndexMsg{0.1}, 0.5);
  master.onMessage(1, SpeedIndexMsg{0.1}, 0.5);
  EXPECT_TRUE(master.holdsWork(0));
  master.onMessage(0, ResultsMsg{TaskSet::range(0, 5), std::vector<float>(15, 0.f)}, 1.0);
  EXPECT_FALSE(master.holdsWork(0));
  EXPECT_TRUE(master.holdsWork(1));
  EXPECT_TRUE(master.expireLeases(2.4, 2.0).empty());  // worker 1 silent 1.9 s, 0 for 1.4 s
  master.onMessage(0, HeartbeatMsg{}, 2.9);
  const Outbox out = master.expireLeases(3.0, 2.0);
  EXPECT_FALSE(master.isLive(1));
  EXPECT_TRUE(master.isLive(0));
  ASSERT_EQ(master.ledger().losses().size(), 1u);
  EXPECT_EQ(master.ledger().losses()[0].worker, 1);
  EXPECT_EQ(master.ledger().losses()[0].unfinished, 5u);
  EXPECT_EQ(master.ledger().reissuedTasks(), 5u);
  bool reissued = false;
  for (const Envelope& e : out) {
    if (const auto* t = std::get_if<TasksMsg>(&e.message)) {
      EXPECT_EQ(e.to, 0);
      EXPECT_EQ(t->tasks.toVector(), TaskSet::range(5, 5).toVector());
      reissued = true;
    }
  }
  EXPECT_TRUE(reissued);
}

TEST(MasterTest, LateAndDuplicateResultsAreDroppedOnce) {
  std::vector<int> delivered(10, 0);
  Master master(makeStrategy("blocks", {}), 2, 10, SceneMsg{},
                [&](int, const TaskSet& tasks, const std::vector<float>& rgb) {
                  ASSERT_EQ(rgb.size(), 3 * tasks.size());
                  size_t i = 0;
                  tasks.forEach([&](uint64_t p) {
                    EXPECT_EQ(rgb[i], static_cast<float>(p));
                    ++delivered[p];
                    i += 3;
                  });
                });
  auto results = [](uint64_t first, uint64_t count) {
    std::vector<float> rgb;
    for (uint64_t p = first; p < first + count; ++p) rgb.insert(rgb.end(), 3, static_cast<float>(p));
    return ResultsMsg{TaskSet::range(first, count), rgb};
  };
  master.start(0);
  master.onMessage(0, SpeedIndexMsg{0.1}, 0);
  master.onMessage(1, SpeedIndexMsg{0.1}, 0);
  master.onMessage(1, results(5, 2), 1);           // worker 1 returns part of its block
  master.onWorkerLost(1, 2, "test");               // then is presumed lost: 7..9 move to 0
  master.onMessage(0, results(0, 5), 3);
  master.onMessage(1, results(7, 2), 4);           // late, but first: accepted
  master.onMessage(0, results(5, 5), 5);           // 5..8 are copies: only 9 is new
  EXPECT_TRUE(master.complete());
  for (int p = 0; p < 10; ++p) EXPECT_EQ(delivered[static_cast<size_t>(p)], 1) << p;
  EXPECT_EQ(master.ledger().duplicates(), 4u);
}

}  // namespace
}  // namespace prt
