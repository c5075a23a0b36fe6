// whileHeartbeating: a long step of the master's, run on a thread of its own, with heartbeats
// to every worker meanwhile.

#include "drive/transport.h"

#include <gtest/gtest.h>

#include <chrono>
#include <map>
#include <stdexcept>
#include <thread>
#include <variant>

namespace prt {
namespace {

// A transport that records what is sent to whom.
class RecordingTransport final : public Transport {
 public:
  void send(int to, Channel channel, Bytes bytes) override {
    ASSERT_EQ(channel, Channel::Protocol);
    EXPECT_TRUE(std::holds_alternative<HeartbeatMsg>(decode(bytes)));
    ++sent[to];
  }
  Incoming poll(double) override { return {}; }
  double now() const override {
    return std::chrono::duration<double>(std::chrono::steady_clock::now().time_since_epoch())
        .count();
  }
  std::map<int, int> sent;
};

TEST(WhileHeartbeating, EveryWorkerHearsFromTheMasterWhileItWorks) {
  RecordingTransport net;
  bool ran = false;
  whileHeartbeating(net, 0.02, [] { return 3; }, [&] {
    std::this_thread::sleep_for(std::chrono::milliseconds(200));
    ran = true;
  });
  EXPECT_TRUE(ran);
  ASSERT_EQ(net.sent.size(), 3u);
  for (const auto& [worker, beats] : net.sent) {
    EXPECT_GE(beats, 2) << worker;   // about ten; fewer on a busy machine
    EXPECT_LE(beats, 11) << worker;  // no more than one per interval
  }
}

TEST(WhileHeartbeating, AQuickStepSendsNothingAndAFailureComesBack) {
  RecordingTransport net;
  whileHeartbeating(net, 5.0, [] { return 2; }, [] {});
  EXPECT_TRUE(net.sent.empty());
  EXPECT_THROW(whileHeartbeating(net, 5.0, [] { return 2; },
                                 [] { throw std::runtime_error("disk full"); }),
               std::runtime_error);
}

}  // namespace
}  // namespace prt
