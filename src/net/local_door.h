#pragma once
// The local driver's master with a TCP door (net/tcp_door.h): `prt render --workers N
// --accept-workers FILE` on one machine, and `prt join FILE` on others, over TCP, with no MPI
// anywhere. Wraps the master's LocalTransport: the local workers keep their mailboxes, the
// joiners are numbered after them in arrival order, each welcomed and announced as
// PeerJoined; messages between a local worker and a joiner (a steal or diffusion transfer) go
// through the master, as they do for MPI joiners.

#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "drive/local_transport.h"
#include "farm/parallel_options.h"
#include "drive/transport.h"
#include "net/port_file.h"
#include "net/tcp_door.h"
#include "net/tcp_joiners.h"

namespace prt {

class LocalDoorTransport final : public Transport {
 public:
  // `door` is owned; `welcome` is encodeWelcome(the run's options). When it goes (the run is
  // over), `portFile` is released (removed) and `refused` gets why each turned-away joiner was.
  LocalDoorTransport(Transport& master, LocalNetwork& network, std::unique_ptr<TcpDoor> door,
                     Bytes welcome, PortFileClaim portFile,
                     std::shared_ptr<std::vector<std::string>> refused);
  ~LocalDoorTransport() override;

  void send(int to, Channel channel, Bytes bytes) override;
  Incoming poll(double deadline) override;
  double now() const override { return master_.now(); }
  bool sharedClock() const override { return false; }  // the joiners' clocks are their own
  bool flush(double timeoutSeconds) override;

 private:
  void relayFromJoiner(int from, const Bytes& bytes);

  Transport& master_;
  LocalNetwork& network_;
  std::unique_ptr<TcpDoor> door_;
  TcpJoiners joiners_;
  PortFileClaim portFile_;
  std::shared_ptr<std::vector<std::string>> refused_;
};

// The door of a local render's --accept-workers FILE: listens, writes FILE (private to its
// owner, never through a link, refused while another render holds it: net/port_file.h) with
// the invitation's secret and the addresses, and returns the
// transport wrapper for RunRequest::wrapLocalMaster. `opened` hears of the door once it is
// open (for the blocklist); when the wrapper goes, FILE is removed and `refused` receives why
// each turned-away joiner was. Throws InputError when it cannot listen or write FILE.
std::function<std::unique_ptr<Transport>(Transport&, LocalNetwork&)> localDoor(
    const std::string& portFile, const ParallelOptions& options,
    std::function<void(TcpDoor&)> opened,
    std::shared_ptr<std::vector<std::string>> refused);

}  // namespace prt
