#include "drive/master_loop.h"

#include <gtest/gtest.h>

#include <thread>

#include "balance/strategy.h"
#include "cluster/messages.h"
#include "drive/local_transport.h"

namespace prt {
namespace {

// The next protocol message for `self`, skipping heartbeats; fails the test after 10 s.
Message nextMessage(LocalTransport& self) {
  for (;;) {
    const Incoming in = self.poll(self.now() + 10);
    EXPECT_NE(in.kind, Incoming::Kind::Timeout);
    if (in.kind == Incoming::Kind::Timeout) return HeartbeatMsg{};
    if (in.kind != Incoming::Kind::Packet || in.channel != Channel::Protocol) continue;
    Message m = decode(in.bytes);
    if (!std::holds_alternative<HeartbeatMsg>(m)) return m;
  }
}

// A worker that joins once the image is complete (while the master collects summaries) is told
// to stop; its summary, sent at once, is taken as any other's: it is not reported missing.
TEST(MasterLoopTest, AWorkerJoiningWhileSummariesAreCollectedIsStoppedNotMissing) {
  LocalNetwork net(2);
  LocalTransport masterSide(net, kMaster);
  Master master(makeStrategy("self", StrategyOptions{.chunk = 4}), 1, 4, SceneMsg{"s", 1, 1},
                nullptr);
  MasterLoopOptions options;
  options.leaseSeconds = 5;
  MasterLoopResult result;
  std::thread loop([&] { result = runMasterLoop(masterSide, master, options); });

  LocalTransport first(net, 0);
  EXPECT_TRUE(std::holds_alternative<SceneMsg>(nextMessage(first)));
  first.send(kMaster, Channel::Protocol, encode(SpeedIndexMsg{0.1}));
  const Message tasks = nextMessage(first);
  ASSERT_TRUE(std::holds_alternative<TasksMsg>(tasks));
  first.send(kMaster, Channel::Protocol,
             encode(ResultsMsg{std::get<TasksMsg>(tasks).tasks, std::vector<float>(12, 0.f)}));
  EXPECT_TRUE(std::holds_alternative<StopMsg>(nextMessage(first)));

  // The image is complete and worker 0 has not sent its summary yet: a worker joins.
  net.join(1);
  LocalTransport late(net, 1);
  EXPECT_TRUE(std::holds_alternative<StopMsg>(nextMessage(late)));
  late.send(kMaster, Channel::Summary, encodeSummary(WorkerSummary{}));
  first.send(kMaster, Channel::Summary, encodeSummary(WorkerSummary{}));
  loop.join();

  EXPECT_TRUE(result.failure.empty()) << result.failure;
  ASSERT_EQ(master.workerCount(), 2);
  ASSERT_EQ(result.summaries.size(), 2u);
  EXPECT_TRUE(result.summaries[0].has_value());
  EXPECT_TRUE(result.summaries[1].has_value()) << "the late joiner's summary was dropped";
}

}  // namespace
}  // namespace prt
