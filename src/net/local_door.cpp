#include "net/local_door.h"

#include "core/input_error.h"
#include "drive/mailbox.h"
#include "net/invitation.h"
#include "net/join_welcome.h"
#include "net/link_tags.h"

namespace prt {

LocalDoorTransport::LocalDoorTransport(Transport& master, LocalNetwork& network,
                                       std::unique_ptr<TcpDoor> door, Bytes welcome,
                                       PortFileClaim portFile,
                                       std::shared_ptr<std::vector<std::string>> refused)
    : master_(master),
      network_(network),
      door_(std::move(door)),
      joiners_(*door_, std::move(welcome)),
      portFile_(std::move(portFile)),
      refused_(std::move(refused)) {
  // The local workers' messages for a joiner reach the master's mailbox; they go on from here
  // (to no such worker: dropped, as a message to a dead one would be).
  network_.setRelay([this](int from, int to, Channel channel, Bytes bytes) {
    const int tag = channel == Channel::Summary ? kSummaryTag : kMessageTag;
    joiners_.send(to, kRelayedTag, withHeader(from, tag, bytes));
  });
}

LocalDoorTransport::~LocalDoorTransport() {
  network_.setRelay({});
  door_->stopAdmitting();
  portFile_.release();  // no more joiners
  if (refused_) *refused_ = door_->refused();
  door_->flush(2.0);
  door_->closeAll();
}

void LocalDoorTransport::send(int to, Channel channel, Bytes bytes) {
  if (joiners_.send(to, channel == Channel::Summary ? kSummaryTag : kMessageTag, bytes)) return;
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

// Joiners are numbered after the local workers and every joiner before them.
Incoming LocalDoorTransport::poll(double deadline) {
  for (;;) {
    if (std::optional<Incoming> in = joiners_.poll(
            [this] { return network_.mailboxCount() + static_cast<int>(joiners_.endpoints().size()); },
            [this](int from, const Bytes& bytes) { relayFromJoiner(from, bytes); })) {
      return *in;
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
    // No MPI port: an empty first line.
    PortFileClaim claim(portFile, portFileText("", secret, door->addresses()));
    if (opened) opened(*door);
    return std::unique_ptr<Transport>(std::make_unique<LocalDoorTransport>(
        master, network, std::move(door), welcome, std::move(claim), refused));
  };
}

}  // namespace prt
