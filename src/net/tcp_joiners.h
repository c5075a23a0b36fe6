#pragma once
// The workers that joined a master through its TcpDoor, as the master's transport sees them:
// each admitted joiner is numbered as the next endpoint and welcomed, and its frames become
// the transport's Incoming (a packet, a worker lost). Shared by the MPI link (src/mpi) and the
// local driver's door (net/local_door.h), which number their other workers their own way.
// Not thread-safe: the master loop's thread owns it.

#include <functional>
#include <optional>
#include <unordered_map>
#include <vector>

#include "drive/transport.h"
#include "net/tcp_door.h"

namespace prt {

class TcpJoiners {
 public:
  // `welcome` is encodeWelcome(the run's options) (net/join_welcome.h).
  TcpJoiners(TcpDoor& door, Bytes welcome) : door_(door), welcome_(std::move(welcome)) {}

  // The next Incoming from the door, if any: PeerJoined (the joiner numbered nextEndpoint()
  // and welcomed), Packet or PeerLost. What a joiner sends for another worker (kRelayTag) goes
  // to `relay` with its sender's endpoint, and polling goes on.
  std::optional<Incoming> poll(const std::function<int()>& nextEndpoint,
                               const std::function<void(int from, const Bytes& bytes)>& relay);
  // Sends to `endpoint` when it is one of the door's joiners; false when it is not.
  bool send(int endpoint, int tag, const Bytes& bytes);
  // The joiners' endpoints, in admission order.
  const std::vector<int>& endpoints() const { return endpoints_; }
  TcpDoor& door() { return door_; }

 private:
  TcpDoor& door_;
  Bytes welcome_;
  std::vector<int> endpoints_;                // per joiner of the door
  std::unordered_map<int, int> joinerOf_;     // endpoint -> joiner of the door
};

}  // namespace prt
