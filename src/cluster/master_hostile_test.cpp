// The master against a worker that lies in ways a message's own bytes cannot show: a transfer
// notice no order asked for, or of tasks it does not hold; tasks kept for ever behind
// heartbeats. Honest Worker state machines render the rest; the run must finish with every
// pixel right, and only the liar be rejected or lost.

#include <gtest/gtest.h>

#include <deque>
#include <functional>
#include <set>

#include "balance/registry.h"
#include "cluster/master.h"
#include "cluster/worker.h"

namespace prt {
namespace {

// What the hostile worker does with each message it gets; `gone` set: it disconnects.
using Script = std::function<void(const Message& in, Outbox& out, bool& gone)>;

struct HostileOutcome {
  bool complete = false;
  std::vector<float> values;  // per pixel: the red channel in the image (-1: none)
  std::vector<RejectedWorker> rejections;
  std::vector<LostWorker> losses;
};

// `honest` workers 0.., and the hostile one numbered after them. Every step is 10 ms: the
// messages in flight are delivered, each honest worker with work renders a batch of 7, the
// hostile one heartbeats, and leases (`leaseSeconds`) are judged.
HostileOutcome runWithHostile(const std::string& strategy, int honest, uint64_t pixels,
                              const Script& script, MasterOptions options = {},
                              double leaseSeconds = 1e9,
                              std::pair<double, double> honestPause = {-1, -1}) {
  HostileOutcome result;
  result.values.assign(pixels, -1);
  const int hostile = honest;
  Master master(makeStrategy(strategy, StrategyOptions{50, 5}), honest + 1, pixels,
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
  for (int w = 0; w < honest; ++w) ws.emplace_back(w, WorkerOptions{7});
  bool gone = false;
  std::deque<std::pair<int, Envelope>> network;
  const auto post = [&](int from, const Outbox& out) {
    for (const Envelope& e : out) network.push_back({from, e});
  };
  double now = 0;
  post(kMaster, master.start(now));
  for (int step = 0; step < 20000 && !master.complete() && !master.failed(); ++step) {
    now += 0.01;
    for (size_t n = network.size(); n > 0 && !network.empty(); --n) {
      auto [from, e] = std::move(network.front());
      network.pop_front();
      if (e.to == kMaster && from == hostile && std::holds_alternative<StopMsg>(e.message)) {
        // The hostile worker's connection drops, after what it sent before.
        post(kMaster, master.onWorkerLost(hostile, now, "connection dropped"));
      } else if (e.to == kMaster) {
        post(kMaster, master.onMessage(from, e.message, now));
      } else if (e.to == hostile) {
        if (gone) continue;
        Outbox out;
        script(e.message, out, gone);
        if (gone) out.push_back({kMaster, StopMsg{}});  // the drop, marked in its link
        post(hostile, out);
      } else {
        post(e.to, ws[static_cast<size_t>(e.to)].onMessage(from, e.message));
      }
    }
    const bool paused = now >= honestPause.first && now < honestPause.second;
    for (int w = 0; w < honest && !paused; ++w) {
      Worker& worker = ws[static_cast<size_t>(w)];
      if (worker.needsSetup()) {
        post(w, worker.setupDone(0.1));
      } else if (worker.hasWork()) {
        const TaskSet batch = worker.nextBatch();
        std::vector<float> rgb;
        batch.forEach([&](uint64_t p) { rgb.insert(rgb.end(), 3, static_cast<float>(p)); });
        post(w, worker.batchDone(batch, std::move(rgb), 0.01));
      }
    }
    if (!gone) {
      // Time passes for it too (a heartbeat of the master's), and it says it is there.
      Outbox out;
      script(HeartbeatMsg{}, out, gone);
      out.push_back({kMaster, HeartbeatMsg{}});
      post(hostile, out);
    }
    post(kMaster, master.expireLeases(now, leaseSeconds));
  }
  result.complete = master.complete();
  result.rejections = master.rejections();
  result.losses = master.ledger().losses();
  return result;
}

void expectEveryPixel(const HostileOutcome& o, const std::string& what) {
  ASSERT_TRUE(o.complete) << what << ": the run did not finish";
  for (size_t p = 0; p < o.values.size(); ++p) {
    ASSERT_EQ(o.values[p], static_cast<float>(p)) << what << ", pixel " << p;
  }
}

// Takes part as a fast worker; `onTasks` hears each task message, `onOrder` each order.
Script participant(std::function<void(const TaskSet&, Outbox&, bool&)> onTasks,
                   std::function<void(const TransferOrderMsg&, Outbox&)> onOrder = {}) {
  return [onTasks, onOrder](const Message& in, Outbox& out, bool& gone) {
    if (std::holds_alternative<SceneMsg>(in)) {
      out.push_back({kMaster, SpeedIndexMsg{0.01}});
    } else if (const auto* t = std::get_if<TasksMsg>(&in)) {
      onTasks(t->tasks, out, gone);
    } else if (const auto* o = std::get_if<TransferOrderMsg>(&in)) {
      if (onOrder) onOrder(*o, out);
    } else if (std::holds_alternative<QueryQueueMsg>(in)) {
      out.push_back({kMaster, QueueLengthMsg{1000}});
    }
  };
}

// One notice claiming every pixel moved to worker 0, then the connection drops: the notice
// answers no order, so its sender is rejected and what it held goes back.
TEST(MasterHostile, ANoticeNoOrderAskedForRejectsItsSender) {
  for (const std::string strategy : {"adaptive", "stealing", "self", "hybrid"}) {
    const uint64_t pixels = 400;
    const HostileOutcome o = runWithHostile(
        strategy, 2, pixels,
        participant([&](const TaskSet&, Outbox& out, bool& gone) {
          out.push_back({kMaster, TransferNoticeMsg{0, TaskSet::range(0, pixels)}});
          gone = true;
        }));
    expectEveryPixel(o, strategy);
    ASSERT_EQ(o.rejections.size(), 1u) << strategy;
    EXPECT_EQ(o.rejections[0].worker, 2) << strategy;
    EXPECT_NE(o.rejections[0].reason.find("no order asked for"), std::string::npos)
        << o.rejections[0].reason;
  }
}

// A real order, answered with tasks the sender was never given (another worker's): rejected.
TEST(MasterHostile, ANoticeOfTasksItDoesNotHoldRejectsItsSender) {
  std::set<uint64_t> mine;
  const HostileOutcome o = runWithHostile(
      "stealing", 2, 600,
      participant([&](const TaskSet& tasks, Outbox&,
                      bool&) { tasks.forEach([&](uint64_t t) { mine.insert(t); }); },
                  [&](const TransferOrderMsg& order, Outbox& out) {
                    TaskSet foreign;
                    for (uint64_t t = 0; t < 600 && foreign.size() < order.count; ++t) {
                      if (!mine.count(t)) foreign.append(TaskRun{t, 1, 1});
                    }
                    out.push_back({order.to, TasksMsg{foreign}});
                    out.push_back({kMaster, TransferNoticeMsg{order.to, foreign}});
                  }));
  expectEveryPixel(o, "stealing");
  ASSERT_EQ(o.rejections.size(), 1u);
  EXPECT_EQ(o.rejections[0].worker, 2);
  EXPECT_NE(o.rejections[0].reason.find("does not hold"), std::string::npos)
      << o.rejections[0].reason;
}

// An order answered for another receiver, or with more tasks than ordered: rejected.
TEST(MasterHostile, ANoticeThatDoesNotAnswerItsOrderRejectsItsSender) {
  for (const bool more : {false, true}) {
    std::vector<uint64_t> queue;
    const HostileOutcome o = runWithHostile(
        "stealing", 2, 600,
        participant([&](const TaskSet& tasks, Outbox&,
                        bool&) { tasks.forEach([&](uint64_t t) { queue.push_back(t); }); },
                    [&](const TransferOrderMsg& order, Outbox& out) {
                      const uint64_t count = more ? order.count + 1 : order.count;
                      TaskSet moved;
                      for (uint64_t i = 0; i < count && !queue.empty(); ++i) {
                        moved.append(TaskRun{queue.back(), 1, 1});
                        queue.pop_back();
                      }
                      const int to = more ? order.to : 1 - order.to;
                      out.push_back({to, TasksMsg{moved}});
                      out.push_back({kMaster, TransferNoticeMsg{to, moved}});
                    }));
    expectEveryPixel(o, more ? "more than ordered" : "another receiver");
    ASSERT_EQ(o.rejections.size(), 1u);
    EXPECT_EQ(o.rejections[0].worker, 2);
    EXPECT_NE(o.rejections[0].reason.find("for an order of at most"), std::string::npos)
        << o.rejections[0].reason;
  }
}

// Tasks taken and kept behind heartbeats: its task lease runs out, it is lost (not rejected:
// it said nothing untrue) and what it held is rendered by the others.
TEST(MasterHostile, TasksKeptBehindHeartbeatsAreReissuedWhenTheTaskLeaseRunsOut) {
  for (const std::string strategy : {"adaptive", "stealing", "self", "hybrid", "scatter"}) {
    MasterOptions options;
    options.taskLease = {kTaskLeaseBatches, 0.5};
    const HostileOutcome o = runWithHostile(
        strategy, 2, 600, participant([](const TaskSet&, Outbox&, bool&) {}), options, 1.0);
    expectEveryPixel(o, strategy);
    EXPECT_TRUE(o.rejections.empty()) << strategy;
    ASSERT_EQ(o.losses.size(), 1u) << strategy;
    EXPECT_EQ(o.losses[0].worker, 2) << strategy;
    EXPECT_NE(o.losses[0].reason.find("task lease"), std::string::npos) << o.losses[0].reason;
    EXPECT_GT(o.losses[0].unfinished, 0u) << strategy;
  }
}

// A machine too busy for every honest worker at once (a pause of 2 s, heartbeats going on,
// far past their task leases) loses none of them: no other worker shows the time was there
// to work. Only the one that keeps its tasks is lost, once the others work again.
TEST(MasterHostile, APauseOfEveryWorkerAtOnceLosesNone) {
  for (const std::string strategy : {"adaptive", "stealing", "self"}) {
    MasterOptions options;
    options.taskLease = {kTaskLeaseBatches, 0.2};
    const HostileOutcome o = runWithHostile(
        strategy, 2, 3000, participant([](const TaskSet&, Outbox&, bool&) {}), options, 1e9,
        {0.3, 2.3});
    expectEveryPixel(o, strategy);
    for (const LostWorker& l : o.losses) {
      EXPECT_EQ(l.worker, 2) << strategy << ": worker " << l.worker << " at " << l.atSeconds << " " << l.reason;
    }
    ASSERT_EQ(o.losses.size(), 1u) << strategy;
    EXPECT_EQ(o.losses[0].worker, 2) << strategy;
  }
}

// Honest workers under task leases, fast and slow, every strategy, with the endgame's copies:
// none is lost.
TEST(MasterHostile, HonestWorkersKeepTheirTaskLeases) {
  for (const std::string& strategy : strategyNames()) {
    for (const bool endgame : {false, true}) {
      MasterOptions options;
      options.taskLease = {kTaskLeaseBatches, 0.05};
      options.endgame = endgame;
      // The last worker here is honest but slow: a batch of two every fifth step.
      Worker slow(3, WorkerOptions{2});
      int ticks = 0;
      const HostileOutcome o = runWithHostile(
          strategy, 3, 700,
          [&](const Message& in, Outbox& out, bool&) {
            if (!std::holds_alternative<HeartbeatMsg>(in)) {
              out = slow.onMessage(kMaster, in);
            } else if (slow.needsSetup()) {
              out = slow.setupDone(0.3);
            } else if (slow.hasWork() && ++ticks % 5 == 0) {
              const TaskSet batch = slow.nextBatch();
              std::vector<float> rgb;
              batch.forEach([&](uint64_t p) { rgb.insert(rgb.end(), 3, static_cast<float>(p)); });
              out = slow.batchDone(batch, std::move(rgb), 0.05);
            }
          },
          options, 1e9);
      expectEveryPixel(o, strategy);
      EXPECT_TRUE(o.losses.empty()) << strategy << (endgame ? " with the endgame" : "") << ": "
                                    << (o.losses.empty() ? "" : o.losses[0].reason);
      EXPECT_TRUE(o.rejections.empty()) << strategy << ": "
                                        << (o.rejections.empty() ? "" : o.rejections[0].reason);
    }
  }
}

// A joiner that arrives before the start and never reports its speed index holds the start
// up for a lease at most: the strategy then starts with the starting workers (and would hear
// of the joiner once it reported, as of any joiner).
TEST(MasterHostile, AJoinerThatNeverMeasuresHoldsUpTheStartForALeaseAtMost) {
  const auto tasksGiven = [](const Outbox& out, uint64_t& given) {
    for (const Envelope& e : out) {
      if (const auto* t = std::get_if<TasksMsg>(&e.message)) {
        EXPECT_NE(e.to, 2);
        given += t->tasks.size();
      }
    }
  };
  for (const std::string strategy : {"adaptive", "scatter", "stealing", "hybrid"}) {
    Master master(makeStrategy(strategy, StrategyOptions{50, 5}), 2, 100, SceneMsg{}, nullptr);
    master.start(0);
    master.onWorkerJoined(2, 0.1);
    uint64_t given = 0;
    tasksGiven(master.onMessage(0, SpeedIndexMsg{0.1}, 0.2), given);
    tasksGiven(master.onMessage(1, SpeedIndexMsg{0.1}, 0.3), given);
    EXPECT_EQ(given, 0u) << strategy << ": a joiner there before the start is waited for";
    EXPECT_LE(master.nextExpiry(2.0), 2.3) << strategy;
    for (int w = 0; w < 3; ++w) master.onMessage(w, HeartbeatMsg{}, 2.2);  // all there
    tasksGiven(master.expireLeases(2.2, 2.0), given);
    EXPECT_EQ(given, 0u) << strategy;
    tasksGiven(master.expireLeases(2.4, 2.0), given);
    EXPECT_GT(given, 0u) << strategy << ": the start waits for the joiner for ever";
    EXPECT_TRUE(master.isLive(2)) << "it is not lost for it: it may yet report";
  }
}

}  // namespace
}  // namespace prt
