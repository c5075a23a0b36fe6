#include "net/local_door.h"

#include <sys/stat.h>

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <filesystem>

#include "core/input_error.h"
#include "drive/mailbox.h"
#include "image/atomic_file.h"
#include "net/invitation.h"
#include "net/join_welcome.h"
#include "net/link_tags.h"

namespace prt {

LocalDoorTransport::LocalDoorTransport(Transport& master, LocalNetwork& network,
                                       std::unique_ptr<TcpDoor> door, Bytes welcome)
    : master_(master), network_(network), door_(std::move(door)), welcome_(std::move(welcome)) {
  // The local workers' messages for a joiner reach the master's mailbox; they go on from here.
  network_.setRelay([this](int from, int to, Channel channel, Bytes bytes) {
    const int j = joinerOf(to);
    if (j < 0) return;  // no such worker: dropped, as a message to a dead one would be
    const int tag = channel == Channel::Summary ? kSummaryTag : kMessageTag;
    door_->send(j, kRelayedTag, withHeader(from, tag, bytes));
  });
}

LocalDoorTransport::~LocalDoorTransport() {
  network_.setRelay({});
  door_->flush(2.0);
  door_->closeAll();
}

int LocalDoorTransport::joinerOf(int endpoint) const {
  for (size_t j = 0; j < endpoints_.size(); ++j) {
    if (endpoints_[j] == endpoint) return static_cast<int>(j);
  }
  return -1;
}

void LocalDoorTransport::send(int to, Channel channel, Bytes bytes) {
  if (const int j = joinerOf(to); j >= 0) {
    door_->send(j, channel == Channel::Summary ? kSummaryTag : kMessageTag, bytes);
    return;
  }
  master_.send(to, channel, std::move(bytes));
}

// A joiner's message for a local worker: into that worker's mailbox, from the joiner.
void LocalDoorTransport::relayFromJoiner(int from, const Bytes& bytes) {
  int32_t to = 0, tag = 0;
  if (!readHeader(bytes, to, tag) || (tag != kMessageTag && tag != kSummaryTag)) return;
  if (to < 0 || to >= network_.mailboxCount()) return;
  Bytes payload(bytes.begin() + 2 * sizeof(int32_t), bytes.end());
  network_.boxOf(to).push(Mail{from, tag == kSummaryTag ? Channel::Summary : Channel::Protocol,
                               std::move(payload), false});
}

Incoming LocalDoorTransport::poll(double deadline) {
  for (;;) {
    while (std::optional<TcpDoor::Event> e = door_->poll()) {
      Incoming in;
      if (e->kind == TcpDoor::Event::Kind::Joined) {
        // Numbered after the local workers and every joiner before it.
        const int endpoint = network_.mailboxCount() + static_cast<int>(endpoints_.size());
        endpoints_.push_back(endpoint);
        door_->send(e->joiner, kWelcomeTag, withHeader(endpoint, 0, welcome_));
        in.kind = Incoming::Kind::PeerJoined;
        in.from = endpoint;
        return in;
      }
      in.from = endpoints_[static_cast<size_t>(e->joiner)];
      if (e->kind == TcpDoor::Event::Kind::Closed) {
        in.kind = Incoming::Kind::PeerLost;
        return in;
      }
      if (e->tag == kRelayTag) {
        relayFromJoiner(in.from, e->bytes);
        continue;
      }
      if (e->tag != kMessageTag && e->tag != kSummaryTag) continue;  // not ours: dropped
      in.kind = Incoming::Kind::Packet;
      in.channel = e->tag == kSummaryTag ? Channel::Summary : Channel::Protocol;
      in.bytes = std::move(e->bytes);
      return in;
    }
    // The mailbox in short slices, so that the door is looked at every few milliseconds.
    const double now = master_.now();
    Incoming in = master_.poll(std::min(deadline, now + 0.002));
    if (in.kind != Incoming::Kind::Timeout || master_.now() >= deadline) return in;
  }
}

bool LocalDoorTransport::flush(double timeoutSeconds) {
  return door_->flush(timeoutSeconds) && master_.flush(timeoutSeconds);
}

namespace {

// Removes the port file when the run's transport goes (the run is over: no more joiners).
class PortFileOwner final : public Transport {
 public:
  PortFileOwner(std::unique_ptr<LocalDoorTransport> inner, std::string file,
                std::shared_ptr<std::vector<std::string>> refused)
      : inner_(std::move(inner)), file_(std::move(file)), refused_(std::move(refused)) {}
  ~PortFileOwner() override {
    inner_->door().stopAdmitting();
    if (refused_) *refused_ = inner_->door().refused();
    std::error_code ignored;
    std::filesystem::remove(file_, ignored);
  }
  void send(int to, Channel channel, Bytes bytes) override { inner_->send(to, channel, std::move(bytes)); }
  Incoming poll(double deadline) override { return inner_->poll(deadline); }
  double now() const override { return inner_->now(); }
  bool sharedClock() const override { return inner_->sharedClock(); }
  bool flush(double timeoutSeconds) override { return inner_->flush(timeoutSeconds); }

 private:
  std::unique_ptr<LocalDoorTransport> inner_;
  std::string file_;
  std::shared_ptr<std::vector<std::string>> refused_;
};

}  // namespace

std::function<std::unique_ptr<Transport>(Transport&, LocalNetwork&)> localDoor(
    const std::string& portFile, const ParallelOptions& options,
    std::function<void(TcpDoor&)> opened, std::shared_ptr<std::vector<std::string>> refused) {
  const Bytes welcome = encodeWelcome(options);
  const DoorAddress where = parseDoorAddress(options.acceptAddress);
  return [portFile, welcome, opened, refused, where](Transport& master, LocalNetwork& network) {
    const Secret secret = newSecret();
    std::unique_ptr<TcpDoor> door;
    try {
      door = std::make_unique<TcpDoor>(secret, where.address, where.port);
    } catch (const InputError&) {
      throw;
    } catch (const std::exception& e) {
      throw InputError(std::string("--accept-workers: ") + e.what());
    }
    // Readable by its owner only: whoever reads it can join. No MPI port: the first line is
    // empty.
    writeFileAtomically(portFile, [&](std::FILE* f) {
      if (::fchmod(::fileno(f), 0600) != 0) {
        throw InputError("cannot make the port file '" + portFile + "' private: " +
                         std::strerror(errno));
      }
      std::fputs(portFileText("", secret, door->addresses()).c_str(), f);
    });
    if (opened) opened(*door);
    auto transport =
        std::make_unique<LocalDoorTransport>(master, network, std::move(door), welcome);
    return std::unique_ptr<Transport>(
        std::make_unique<PortFileOwner>(std::move(transport), portFile, refused));
  };
}

}  // namespace prt
