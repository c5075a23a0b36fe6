// The master's TCP door and a joiner's side of it, over loopback in one process.

#include "net/tcp_door.h"

#include <gtest/gtest.h>
#include <poll.h>

#include <chrono>
#include <cstring>
#include <optional>

#include "core/input_error.h"
#include "core/machine.h"
#include "farm/build_info.h"
#include "net/link_tags.h"
#include "net/tcp_frames.h"

namespace prt {
namespace {

// Polls both sides until `ready` holds or 5 s pass.
template <typename Ready>
bool pump(TcpDoor& door, FramedSocket& joiner, std::vector<TcpDoor::Event>& events, Ready ready) {
  const auto start = std::chrono::steady_clock::now();
  while (std::chrono::steady_clock::now() - start < std::chrono::seconds(5)) {
    while (std::optional<TcpDoor::Event> e = door.poll()) events.push_back(std::move(*e));
    joiner.receive();
    joiner.transmit();
    if (ready()) return true;
    door.wait(0.01);
  }
  return false;
}

std::unique_ptr<FramedSocket> connectToDoor(const TcpDoor& door) {
  std::string why;
  const int fd = connectTo("127.0.0.1:" + std::to_string(door.port()), 2.0, why);
  EXPECT_GE(fd, 0) << why;
  return std::make_unique<FramedSocket>(fd);
}

TEST(TcpDoor, AnInvitedJoinerIsAdmittedAndFramesGoBothWays) {
  const Secret secret = newSecret();
  TcpDoor door(secret, "127.0.0.1");
  ASSERT_EQ(door.addresses(), std::vector<std::string>{"127.0.0.1:" + std::to_string(door.port())});
  auto joiner = connectToDoor(door);
  std::vector<TcpDoor::Event> events;
  std::optional<Frame> challenge;
  ASSERT_TRUE(pump(door, *joiner, events, [&] { return (challenge = joiner->next()).has_value(); }));
  ASSERT_EQ(challenge->tag, kChallengeTag);
  ASSERT_EQ(challenge->bytes.size(), 32u);
  Challenge c{};
  std::memcpy(c.data(), challenge->bytes.data(), 32);
  const auto proof = proofFor(secret, c, buildDescription(), "host-a");
  joiner->send(kProofTag, Bytes(proof.begin(), proof.end()));
  ASSERT_TRUE(pump(door, *joiner, events, [&] { return !events.empty(); }));
  ASSERT_EQ(events[0].kind, TcpDoor::Event::Kind::Joined);
  EXPECT_EQ(events[0].joiner, 0);
  EXPECT_EQ(events[0].host, "host-a");
  // After admission, frames of any size both ways, in order.
  Bytes big(3 << 20);
  for (size_t i = 0; i < big.size(); ++i) big[i] = static_cast<uint8_t>(i * 7);
  joiner->send(kMessageTag, big);
  joiner->send(kSummaryTag, Bytes{1, 2, 3});
  door.send(0, kMessageTag, Bytes{9});
  std::optional<Frame> fromDoor;
  ASSERT_TRUE(pump(door, *joiner, events, [&] {
    if (!fromDoor) fromDoor = joiner->next();
    return events.size() >= 3 && fromDoor;
  }));
  EXPECT_EQ(events[1].tag, kMessageTag);
  EXPECT_EQ(events[1].bytes, big);
  EXPECT_EQ(events[2].tag, kSummaryTag);
  EXPECT_EQ(fromDoor->bytes, Bytes{9});
  // The joiner goes: its connection closes.
  joiner->close();
  ASSERT_TRUE(pump(door, *joiner, events, [&] { return events.size() >= 4; }));
  EXPECT_EQ(events[3].kind, TcpDoor::Event::Kind::Closed);
  EXPECT_TRUE(door.refused().empty());
}

// The wrong secret, a blocked machine, and a peer that floods before proving anything: each is
// turned away (told why, where it listens), and none is admitted.
TEST(TcpDoor, UninvitedBlockedAndFloodingPeersAreRefused) {
  const Secret secret = newSecret();
  TcpDoor door(secret, "127.0.0.1");
  door.block("bad-host");
  std::vector<TcpDoor::Event> events;
  struct Try {
    Secret secret;
    std::string host;
    std::string why;  // a part of the refusal
  };
  for (const Try& t : {Try{newSecret(), "host-a", "invited"}, Try{secret, "bad-host", "rejected"}}) {
    auto joiner = connectToDoor(door);
    std::optional<Frame> challenge;
    ASSERT_TRUE(pump(door, *joiner, events, [&] { return (challenge = joiner->next()).has_value(); }));
    Challenge c{};
    std::memcpy(c.data(), challenge->bytes.data(), 32);
    const auto proof = proofFor(t.secret, c, buildDescription(), t.host);
    joiner->send(kProofTag, Bytes(proof.begin(), proof.end()));
    std::optional<Frame> answer;
    ASSERT_TRUE(pump(door, *joiner, events, [&] { return (answer = joiner->next()).has_value(); }));
    EXPECT_EQ(answer->tag, kRefusedTag);
    EXPECT_NE(std::string(answer->bytes.begin(), answer->bytes.end()).find(t.why), std::string::npos);
  }
  auto flood = connectToDoor(door);
  flood->send(kProofTag, Bytes(1 << 20, 0));  // more than a proof can be
  ASSERT_TRUE(pump(door, *flood, events, [&] { return !flood->open(); }));
  EXPECT_TRUE(events.empty());
  EXPECT_EQ(door.joinerCount(), 0);
  EXPECT_EQ(door.refused().size(), 2u);
}

TEST(TcpDoor, AcceptAddressesAreAddressAndPortOrEither) {
  EXPECT_EQ(parseDoorAddress("").address, "");
  EXPECT_EQ(parseDoorAddress("").port, 0);
  EXPECT_EQ(parseDoorAddress("10.0.0.5").address, "10.0.0.5");
  EXPECT_EQ(parseDoorAddress(":7000").port, 7000);
  EXPECT_EQ(parseDoorAddress(":7000").address, "");
  const DoorAddress both = parseDoorAddress("127.0.0.1:65535");
  EXPECT_EQ(both.address, "127.0.0.1");
  EXPECT_EQ(both.port, 65535);
  for (const char* bad : {"host", "10.0.0", "10.0.0.5:", ":0", ":65536", ":70000000", ":-1",
                          ":7x", "::1", "10.0.0.5:7000:1"}) {
    EXPECT_THROW(parseDoorAddress(bad), InputError) << bad;
  }
  // A door on a port taken by another: a clear error, not a crash.
  TcpDoor first(newSecret(), "127.0.0.1");
  EXPECT_THROW(TcpDoor(newSecret(), "127.0.0.1", first.port()), std::runtime_error);
}

}  // namespace
}  // namespace prt
