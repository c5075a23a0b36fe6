#include "net/tcp_joiners.h"

#include "core/check.h"
#include "net/link_tags.h"

namespace prt {

std::optional<Incoming> TcpJoiners::poll(
    const std::function<int()>& nextEndpoint,
    const std::function<void(int from, const Bytes& bytes)>& relay) {
  while (std::optional<TcpDoor::Event> e = door_.poll()) {
    Incoming in;
    if (e->kind == TcpDoor::Event::Kind::Joined) {
      const int endpoint = nextEndpoint();
      PRT_CHECK(e->joiner == static_cast<int>(endpoints_.size()));
      endpoints_.push_back(endpoint);
      joinerOf_[endpoint] = e->joiner;
      door_.send(e->joiner, kWelcomeTag, withHeader(endpoint, 0, welcome_));
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
      relay(in.from, e->bytes);
      continue;
    }
    if (e->tag != kMessageTag && e->tag != kSummaryTag) continue;  // not ours: dropped
    in.kind = Incoming::Kind::Packet;
    in.channel = e->tag == kSummaryTag ? Channel::Summary : Channel::Protocol;
    in.bytes = std::move(e->bytes);
    return in;
  }
  return std::nullopt;
}

bool TcpJoiners::send(int endpoint, int tag, const Bytes& bytes) {
  const auto it = joinerOf_.find(endpoint);
  if (it == joinerOf_.end()) return false;
  door_.send(it->second, tag, bytes);
  return true;
}

}  // namespace prt
