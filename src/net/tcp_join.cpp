#include "net/tcp_join.h"

#include <poll.h>

#include <chrono>
#include <cstdio>
#include <cstring>
#include <memory>
#include <optional>

#include "core/cpu_allocation.h"
#include "core/input_error.h"
#include "core/input_file.h"
#include "core/machine.h"
#include "farm/build_info.h"
#include "farm/parallel_run.h"
#include "drive/transport.h"
#include "net/invitation.h"
#include "net/join_welcome.h"
#include "net/link_tags.h"
#include "net/tcp_frames.h"

namespace prt {
namespace {

// A joined worker's Transport: one TCP connection to the master. Messages for another worker
// go through the master (kRelayTag), as from a joiner over MPI; a release or a closed
// connection is the master's loss to the worker loop, the release kept for the caller.
class TcpWorkerLink final : public Transport {
 public:
  explicit TcpWorkerLink(std::unique_ptr<FramedSocket> socket)
      : socket_(std::move(socket)), start_(std::chrono::steady_clock::now()) {}

  void send(int to, Channel channel, Bytes bytes) override {
    const int tag = channel == Channel::Summary ? kSummaryTag : kMessageTag;
    if (to == kMaster) {
      socket_->send(tag, bytes);
    } else {
      socket_->send(kRelayTag, withHeader(to, tag, bytes));
    }
  }

  Incoming poll(double deadline) override {
    Incoming in;
    for (;;) {
      while (std::optional<Frame> f = socket_->next()) {
        if (f->tag == kReleaseTag) {
          int32_t code = 1;
          if (f->bytes.size() >= sizeof code) std::memcpy(&code, f->bytes.data(), sizeof code);
          release_ = code;
          in.kind = Incoming::Kind::PeerLost;
          in.from = kMaster;
          return in;
        }
        int from = kMaster, tag = f->tag;
        if (f->tag == kRelayedTag) {
          int32_t sender = 0, inner = 0;
          if (!readHeader(f->bytes, sender, inner)) continue;
          from = sender;
          tag = inner;
          f->bytes.erase(f->bytes.begin(), f->bytes.begin() + 2 * sizeof(int32_t));
        }
        if (tag != kMessageTag && tag != kSummaryTag) continue;
        in.kind = Incoming::Kind::Packet;
        in.from = from;
        in.channel = tag == kSummaryTag ? Channel::Summary : Channel::Protocol;
        in.bytes = std::move(f->bytes);
        return in;
      }
      if (!socket_->open() || !socket_->receive() || !socket_->transmit()) {
        if (socket_->hasFrame()) continue;  // what came before the close first
        in.kind = Incoming::Kind::PeerLost;
        in.from = kMaster;
        return in;
      }
      if (socket_->hasFrame()) continue;
      const double left = deadline - now();
      if (left <= 0) return in;  // Timeout
      pollfd p{socket_->fd(), static_cast<short>(POLLIN | (socket_->pendingOutput() ? POLLOUT : 0)), 0};
      ::poll(&p, 1, static_cast<int>(std::min(left, 0.05) * 1000) + 1);
    }
  }

  double now() const override {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
  }
  bool flush(double timeoutSeconds) override { return socket_->drain(timeoutSeconds); }
  std::optional<int32_t> release() const { return release_; }

 private:
  std::unique_ptr<FramedSocket> socket_;
  std::chrono::steady_clock::time_point start_;
  std::optional<int32_t> release_;
};

double secondsFrom(std::chrono::steady_clock::time_point t) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t).count();
}

// The next frame from `socket` by `deadline` (seconds since `start`), or none.
std::optional<Frame> awaitFrame(FramedSocket& socket, std::chrono::steady_clock::time_point start,
                                double deadline) {
  for (;;) {
    if (std::optional<Frame> f = socket.next()) return f;
    if (!socket.receive() && !socket.open()) return socket.next();
    if (std::optional<Frame> f = socket.next()) return f;
    const double left = deadline - secondsFrom(start);
    if (left <= 0) return std::nullopt;
    pollfd p{socket.fd(), POLLIN, 0};
    ::poll(&p, 1, static_cast<int>(std::min(left, 0.1) * 1000) + 1);
  }
}

}  // namespace

int runTcpJoiner(const TcpJoinRequest& request) {
  const PortFile file = parsePortFile(readInputFile(request.portFile, "port file", 1 << 16));
  if (file.tcp.empty()) {
    throw InputError("'" + request.portFile +
                     "' lists no TCP address: start the render with --accept-workers " +
                     request.portFile + " (or join under mpirun, through an ompi-server)");
  }
  if (!file.secret) {
    std::fprintf(stderr,
                 "prt: warning: '%s' holds no invitation secret: the render will refuse this "
                 "worker (use the port file the render wrote, as it wrote it)\n",
                 request.portFile.c_str());
  }
  // The addresses in turn, until one answers or the time is up.
  const auto start = std::chrono::steady_clock::now();
  const double limit = request.connectTimeoutSeconds;
  int fd = -1;
  std::string why;
  while (fd < 0 && secondsFrom(start) < limit) {
    for (const std::string& address : file.tcp) {
      const double left = limit - secondsFrom(start);
      if (left <= 0) break;
      fd = connectTo(address, std::min(left, 3.0), why);
      if (fd >= 0) break;
    }
    if (fd < 0 && secondsFrom(start) < limit) ::poll(nullptr, 0, 500);
  }
  if (fd < 0) {
    std::fprintf(stderr,
                 "prt: error: could not reach the render's master at the addresses in '%s' "
                 "within %d s (%s): has that render ended?\n",
                 request.portFile.c_str(), static_cast<int>(limit), why.c_str());
    return 1;
  }
  auto socket = std::make_unique<FramedSocket>(fd);
  // The invitation, then the welcome: this worker's endpoint and the run's options.
  const std::optional<Frame> challenge = awaitFrame(*socket, start, limit);
  if (!challenge || challenge->tag != kChallengeTag || challenge->bytes.size() != 32) {
    std::fprintf(stderr, "prt: error: the render's master sent no invitation challenge: is it "
                         "an older prt?\n");
    return 1;
  }
  Challenge c{};
  std::memcpy(c.data(), challenge->bytes.data(), c.size());
  const std::vector<uint8_t> proof =
      proofFor(file.secret.value_or(Secret{}), c, buildDescription(), hostName());
  socket->send(kProofTag, Bytes(proof.begin(), proof.end()));
  const std::optional<Frame> answer = awaitFrame(*socket, start, limit + 15);
  if (answer && answer->tag == kRefusedTag) {
    std::fprintf(stderr, "prt: error: the render refused this worker: %s\n",
                 std::string(answer->bytes.begin(), answer->bytes.end()).c_str());
    return 1;
  }
  if (!answer || answer->tag != kWelcomeTag) {
    std::fprintf(stderr, "prt: error: joined the render but its master sent no welcome\n");
    return 1;
  }
  ParallelOptions options;
  int id = -1;
  try {
    id = decodeWelcome(answer->bytes, options);
  } catch (const std::exception& e) {
    std::fprintf(stderr, "prt: error: %s from the render's master\n", e.what());
    return 1;
  }
  options.threads = request.threads > 0 ? request.threads
                                        : allocatedCpuCount(request.sharingProcesses);
  options.slowdowns.assign(static_cast<size_t>(id) + 1, 1.0);
  options.slowdowns.back() = request.slowdown;
  for (SpeedChange change : request.slowdownChanges) {
    change.worker = id;
    options.slowdownChanges.push_back(change);
  }
  TcpWorkerLink link(std::move(socket));
  const WorkerExit exit = runWorkerSide(link, id, options, WorkerFaultActions{});
  if (exit == WorkerExit::MasterLost && !link.release()) {
    std::fprintf(stderr, "prt: joined worker %d: the master stopped answering; exiting\n", id);
    return 1;
  }
  // After its summary, the master's release (or its closing the connection) ends it.
  const double until = link.now() + options.workerTimeoutSeconds + 30;
  while (!link.release()) {
    const Incoming in = link.poll(until);
    if (in.kind == Incoming::Kind::Timeout || in.kind == Incoming::Kind::PeerLost) break;
  }
  link.flush(2.0);
  const int32_t code = link.release().value_or(kReleaseFinalize);
  return code > 0 ? code : 0;
}

}  // namespace prt
