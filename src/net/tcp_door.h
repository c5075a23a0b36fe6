#pragma once
// TcpDoor: the master's door for workers that join a running render over TCP (`prt join FILE`
// without mpirun): no MPI rendezvous, so it works across hosts and from any launcher (srun,
// ssh, a shell). It listens on every IPv4 interface (or the one asked for); the port file
// (net/invitation.h) lists the addresses a joiner may try.
//
// A connection is admitted as a mpirun joiner is: the door sends a random challenge, and the
// joiner must answer with proof of the port file's secret and a compatible version within
// kProofSeconds, in a frame of at most 4 KB; otherwise it is told why (kRefusedTag) and
// closed. Admitted joiners are numbered 0, 1, ... in admission order; their frames then come
// out of poll(), and a closed connection as Closed. Never blocks: poll() takes what arrived.
// Not thread-safe: the master loop's thread owns it.

#include <chrono>
#include <cstdint>
#include <memory>
#include <optional>
#include <set>
#include <string>
#include <vector>

#include "net/invitation.h"
#include "net/tcp_frames.h"

namespace prt {

// --accept-address [ADDRESS][:PORT]: "" is every interface and a free port, "10.0.0.5" that
// address, ":7000" every interface on port 7000, "10.0.0.5:7000" both. Throws InputError
// naming the flag for anything else.
struct DoorAddress {
  std::string address;  // "": every interface
  uint16_t port = 0;    // 0: any free one
};
DoorAddress parseDoorAddress(const std::string& text);

class TcpDoor {
 public:
  static constexpr double kProofSeconds = 10;

  // Listens on `bindAddress` ("" or "0.0.0.0": every interface) and `port` (0: any free one).
  // Throws std::runtime_error when it cannot.
  TcpDoor(const Secret& secret, const std::string& bindAddress = "", uint16_t port = 0);
  ~TcpDoor();
  TcpDoor(const TcpDoor&) = delete;
  TcpDoor& operator=(const TcpDoor&) = delete;

  // "A.B.C.D:PORT" for each address a joiner may reach it at: the interfaces' IPv4 addresses
  // (or the bound one), loopback last.
  std::vector<std::string> addresses() const;
  uint16_t port() const { return port_; }

  struct Event {
    enum class Kind { Joined, Frame, Closed };
    Kind kind = Kind::Frame;
    int joiner = 0;
    int tag = 0;
    Bytes bytes;
    std::string host;  // Joined: the machine's name its proof gave
  };
  // The next event, if any; does not wait.
  std::optional<Event> poll();
  // Waits until a connection or the listening socket has something, for at most `seconds`.
  void wait(double seconds);
  void send(int joiner, int tag, const Bytes& bytes);
  // Writes what is queued, waiting at most `timeoutSeconds`; false if something was left.
  bool flush(double timeoutSeconds);
  // Stops admitting (pending connections are closed); admitted joiners stay connected.
  void stopAdmitting();
  void closeAll();

  // Refuses joiners from `host` from now on (a machine whose worker was rejected).
  void block(const std::string& host) { blocked_.insert(host); }
  const std::vector<std::string>& refused() const { return refused_; }
  int joinerCount() const { return static_cast<int>(joiners_.size()); }

 private:
  struct Pending {
    std::unique_ptr<FramedSocket> socket;
    Challenge challenge{};
    std::chrono::steady_clock::time_point since;
    std::string peer;  // the address it connected from
  };
  void acceptNew();
  void refuse(Pending& p, const std::string& why);

  Secret secret_;
  int listener_ = -1;
  uint16_t port_ = 0;
  std::string bound_;
  bool admitting_ = true;
  std::vector<Pending> pending_;
  std::vector<std::unique_ptr<FramedSocket>> joiners_;  // null once closed
  std::vector<Event> events_;  // waiting to be polled, in order
  std::set<std::string> blocked_;
  std::vector<std::string> refused_;
};

}  // namespace prt
