// A hostile joiner for the fault tests: it proves its invitation as `prt join` does, over the
// real wire (net/tcp_frames.h, cluster/messages.h), and then misbehaves in one way.
//
//   prt_hostile_joiner PORTFILE MODE PIXELS [SECONDS]
//
// MODE
//   forge-notice  measures fast, and at its first tasks sends one transfer notice claiming
//                 every pixel (0..PIXELS-1) moved to worker 0, then disconnects
//   huge-tasks    measures fast, and at its first tasks relays to worker 0 a task message of
//                 2^40 copies of pixel 0, then disconnects
//   linger        never measures (so is given nothing), and heartbeats through and after the
//                 Stop, never saying goodbye; prints "stopped" when the Stop comes
//   hoard         measures fast, takes every task it is given and returns none, heartbeating
//   hoard-slow    as hoard, but claims a speed index of 10^6 s (a million times slower)
// Modes that stay connected leave after SECONDS (default 60) or when the master closes the
// connection. Exits 0 when it did what its mode says, 1 when it was not admitted.

#include <poll.h>

#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <memory>
#include <optional>
#include <string>

#include "cluster/messages.h"
#include "core/input_file.h"
#include "farm/build_info.h"
#include "net/invitation.h"
#include "net/link_tags.h"
#include "net/tcp_frames.h"

namespace {

using namespace prt;
using Clock = std::chrono::steady_clock;

double since(Clock::time_point t) {
  return std::chrono::duration<double>(Clock::now() - t).count();
}

// The next frame, waiting at most `seconds`; none on a timeout or a closed connection.
std::optional<Frame> nextFrame(FramedSocket& s, double seconds) {
  const auto start = Clock::now();
  for (;;) {
    if (std::optional<Frame> f = s.next()) return f;
    if (!s.open() || !s.receive()) return s.next();
    if (std::optional<Frame> f = s.next()) return f;
    s.transmit();
    const double left = seconds - since(start);
    if (left <= 0) return std::nullopt;
    pollfd p{s.fd(), static_cast<short>(POLLIN | (s.pendingOutput() ? POLLOUT : 0)), 0};
    ::poll(&p, 1, static_cast<int>(std::min(left, 0.05) * 1000) + 1);
  }
}

void sendMessage(FramedSocket& s, const Message& m) { s.send(kMessageTag, encode(m)); }

}  // namespace

int main(int argc, char** argv) {
  if (argc < 4) {
    std::fprintf(stderr, "usage: %s PORTFILE MODE PIXELS [SECONDS]\n", argv[0]);
    return 2;
  }
  const std::string mode = argv[2];
  const uint64_t pixels = std::strtoull(argv[3], nullptr, 10);
  const double lifetime = argc > 4 ? std::atof(argv[4]) : 60;
  const PortFile file = parsePortFile(readInputFile(argv[1], "port file", 1 << 16));
  std::string why;
  int fd = -1;
  for (const std::string& address : file.tcp) {
    if ((fd = connectTo(address, 3.0, why)) >= 0) break;
  }
  if (fd < 0 || !file.secret) {
    std::fprintf(stderr, "hostile joiner: cannot connect: %s\n", why.c_str());
    return 1;
  }
  FramedSocket socket(fd);
  const std::optional<Frame> challenge = nextFrame(socket, 10);
  if (!challenge || challenge->tag != kChallengeTag || challenge->bytes.size() != 32) return 1;
  Challenge c{};
  std::memcpy(c.data(), challenge->bytes.data(), c.size());
  const std::vector<uint8_t> proof = proofFor(*file.secret, c, buildDescription(), "hostile");
  socket.send(kProofTag, Bytes(proof.begin(), proof.end()));
  const std::optional<Frame> welcome = nextFrame(socket, 10);
  if (!welcome || welcome->tag != kWelcomeTag) {
    std::fprintf(stderr, "hostile joiner: not admitted\n");
    return 1;
  }
  const auto start = Clock::now();
  auto lastBeat = start;
  while (since(start) < lifetime && socket.open()) {
    if (since(lastBeat) >= 0.2) {
      sendMessage(socket, HeartbeatMsg{});
      lastBeat = Clock::now();
    }
    std::optional<Frame> f = nextFrame(socket, 0.05);
    if (!f) {
      if (!socket.open()) break;
      continue;
    }
    if (f->tag == kReleaseTag) break;
    if (f->tag == kRelayedTag) {  // from another worker, through the master: a transfer
      int32_t sender = 0, tag = 0;
      if (!readHeader(f->bytes, sender, tag)) continue;
      f->bytes.erase(f->bytes.begin(), f->bytes.begin() + 2 * sizeof(int32_t));
      f->tag = tag;
    }
    if (f->tag != kMessageTag) continue;
    Message m;
    try {
      m = decode(f->bytes);
    } catch (const std::exception&) {
      continue;
    }
    if (std::holds_alternative<SceneMsg>(m) && mode != "linger") {
      const double seconds = mode == "hoard-slow" ? 1e6 : 0.01;
      sendMessage(socket, SpeedIndexMsg{seconds, {buildDescription(), "hostile"}});
    } else if (std::holds_alternative<StopMsg>(m)) {
      std::printf("stopped\n");
      std::fflush(stdout);
    } else if (std::holds_alternative<TasksMsg>(m)) {
      if (mode == "forge-notice") {
        sendMessage(socket, TransferNoticeMsg{0, TaskSet::range(0, pixels)});
        break;
      }
      if (mode == "huge-tasks") {
        TaskSet copies;
        copies.append(TaskRun{0, uint64_t{1} << 40, 0});
        socket.send(kRelayTag, withHeader(0, kMessageTag, encode(TasksMsg{copies})));
        break;
      }
      // hoard, linger: kept.
    }
  }
  socket.drain(2.0);
  socket.close();
  return 0;
}
