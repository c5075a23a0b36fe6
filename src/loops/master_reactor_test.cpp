#include "loops/master_reactor.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <string>
#include <vector>

#include "balance/strategy.h"

namespace prt {
namespace {

Master twoWorkers(uint64_t pixels = 8) {
  return Master(makeStrategy("self", StrategyOptions{.chunk = 4}), 2, pixels, SceneMsg{"s", 1, 1},
                nullptr);
}

int countOf(const std::vector<Event>& events, EventKind kind) {
  int n = 0;
  for (const Event& e : events) n += e.kind == kind;
  return n;
}

TEST(MasterReactorTest, StartsBySendingTheSceneAndWaitsUntilTheFirstDeadline) {
  Master master = twoWorkers();
  MasterReactorOptions options;
  options.leaseSeconds = 5;
  options.heartbeatSeconds = 1;
  MasterReactor reactor(master, options);
  reactor.start(10);
  const Outbox out = reactor.takeOutbox();
  ASSERT_EQ(out.size(), 2u);
  for (const Envelope& e : out) EXPECT_TRUE(std::holds_alternative<SceneMsg>(e.message));
  EXPECT_TRUE(reactor.takeOutbox().empty()) << "taken once";
  EXPECT_DOUBLE_EQ(reactor.nextDeadline(), 11);  // the first heartbeat round
  EXPECT_EQ(reactor.load().sent, 2u);
}

// Heartbeats go only to workers the master has said nothing to for an interval.
TEST(MasterReactorTest, HeartbeatsGoOnlyToWorkersLeftWithoutAWord) {
  Master master = twoWorkers();
  MasterReactorOptions options;
  options.heartbeatSeconds = 1;
  MasterReactor reactor(master, options);
  reactor.start(0);
  reactor.takeOutbox();
  reactor.onPeerJoined(2, 0.8);  // the joiner gets the scene at 0.8
  EXPECT_FALSE(reactor.takeOutbox().empty());
  reactor.onDeadline(1.0);
  EXPECT_EQ(reactor.takeHeartbeats(), (std::vector<int>{0, 1}));
  EXPECT_EQ(reactor.load().heartbeatsSent, 2u);
  reactor.onDeadline(1.5);  // not yet the next round
  EXPECT_TRUE(reactor.takeHeartbeats().empty());
  reactor.onDeadline(2.0);  // the joiner too, now
  EXPECT_EQ(reactor.takeHeartbeats(), (std::vector<int>{0, 1, 2}));
}

// A silent worker is lost a lease after it was last heard; the loss is logged once and a
// checkpoint follows it. A keep-alive from the transport counts as hearing from it.
TEST(MasterReactorTest, ALeaseRunsOutUnlessTheTransportKeepsTheWorkerAlive) {
  Master master = twoWorkers();
  std::vector<std::string> checkpoints;
  MasterReactorOptions options;
  options.leaseSeconds = 2;
  options.heartbeatSeconds = std::numeric_limits<double>::infinity();
  options.checkpointEverySeconds = 100;
  options.checkpoint = [&](const std::string& why, double now) {
    checkpoints.push_back(why);
    return now + 0.5;
  };
  MasterReactor reactor(master, options);
  reactor.start(0);
  EXPECT_DOUBLE_EQ(reactor.nextDeadline(), 2);  // leases, not heartbeats
  reactor.onKeepAlive(1, 1.5);
  reactor.onDeadline(2.5);
  EXPECT_FALSE(master.isLive(0));
  EXPECT_TRUE(master.isLive(1));
  EXPECT_TRUE(reactor.takeHeartbeats().empty());
  ASSERT_EQ(checkpoints, std::vector<std::string>{"a worker was lost"});
  EXPECT_EQ(countOf(reactor.log().events, EventKind::WorkerLost), 1);
  reactor.onDeadline(3.0);  // nothing new
  EXPECT_EQ(countOf(reactor.log().events, EventKind::WorkerLost), 1);
  EXPECT_DOUBLE_EQ(reactor.nextDeadline(), 3.5);  // worker 1's lease
  // The next periodic checkpoint is due an interval after the last one ended (at 3.0).
  reactor.onKeepAlive(1, 200);
  EXPECT_DOUBLE_EQ(reactor.nextDeadline(), 103);
  reactor.onDeadline(102.9);
  EXPECT_EQ(checkpoints.size(), 1u);
  reactor.onDeadline(103);
  EXPECT_EQ(checkpoints.back(), "periodic");
}

TEST(MasterReactorTest, APeerLostOrMalformedIsALossAndStrangersAreIgnored) {
  Master master = twoWorkers();
  MasterReactorOptions options;
  MasterReactor reactor(master, options);
  reactor.start(0);
  reactor.onMessage(7, RequestMsg{}, 8, 0.1);  // not a worker of this run
  EXPECT_EQ(reactor.load().received, 0u);
  reactor.onPeerLost(0, 0.2);
  reactor.onMalformed(1, "truncated", 0.3);
  EXPECT_TRUE(master.failed());
  reactor.finish("every worker was lost", 0.3);
  ASSERT_EQ(master.ledger().losses().size(), 2u);
  EXPECT_EQ(master.ledger().losses()[0].reason, "connection dropped");
  EXPECT_EQ(master.ledger().losses()[1].reason, "sent a malformed message: truncated");
  EXPECT_EQ(countOf(reactor.log().events, EventKind::WorkerLost), 2);
}

TEST(MasterReactorTest, AJoinerIsAdmittedOnlyInTurn) {
  Master master = twoWorkers();
  MasterReactorOptions options;
  MasterReactor reactor(master, options);
  reactor.start(0);
  reactor.takeOutbox();
  reactor.onPeerJoined(3, 1);  // out of turn
  EXPECT_EQ(master.workerCount(), 2);
  reactor.onPeerJoined(2, 1);
  EXPECT_EQ(master.workerCount(), 3);
  EXPECT_EQ(reactor.summaries().size(), 3u);
  EXPECT_EQ(countOf(reactor.log().events, EventKind::WorkerJoined), 1);
  const Outbox out = reactor.takeOutbox();
  ASSERT_FALSE(out.empty());
  EXPECT_EQ(out[0].to, 2);
  EXPECT_TRUE(std::holds_alternative<SceneMsg>(out[0].message));
}

}  // namespace
}  // namespace prt
