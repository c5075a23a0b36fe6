#pragma once
// LocalNetwork and LocalTransport: the driver kit's transport between threads of one process.
// Each endpoint (the master, each worker) has a mailbox; bytes are moved, never shared. The
// network's clock is shared, so event times need no alignment. A worker thread that ends
// without its StopMsg (a crash, an exception) drops its connection: the master's mailbox gets
// a PeerLost notice, as a TCP link would report a closed socket. Workers that join later have
// their mailboxes from the start; join() announces each to the master (PeerJoined).

#include <atomic>
#include <functional>
#include <chrono>
#include <memory>
#include <vector>

#include "drive/mailbox.h"
#include "drive/transport.h"

namespace prt {

class LocalNetwork {
 public:
  // Mailboxes for `workerCount` workers: those that start and those that join later (each
  // announced by join()).
  explicit LocalNetwork(int workerCount);
  Mailbox& boxOf(int endpoint);
  double now() const;
  void restartClock() { start_ = std::chrono::steady_clock::now(); }
  std::chrono::steady_clock::time_point timeAt(double seconds) const;
  // Tells every thread the run is over: a hung worker waits for this, and every worker still
  // in its loop hears that the master is gone.
  void shutDown();
  // Worker `endpoint` connects: the master hears of it before any of its packets.
  void join(int endpoint);
  // Workers beyond the mailboxes (joined over a network, numbered by the master's transport):
  // what the threads send them goes to the master's mailbox, and the master's LocalTransport
  // hands it to `relay` (from, to, channel, bytes) instead of returning it. Set before the run.
  using Relay = std::function<void(int from, int to, Channel channel, Bytes bytes)>;
  void setRelay(Relay relay) { relay_ = std::move(relay); }
  const Relay& relay() const { return relay_; }
  int mailboxCount() const { return static_cast<int>(workers_.size()); }
  bool isShutDown() const { return shutdown_; }

 private:
  std::chrono::steady_clock::time_point start_;
  Mailbox master_;
  std::vector<std::unique_ptr<Mailbox>> workers_;  // all made at the start: never resized
  std::atomic<bool> shutdown_{false};
  Relay relay_;
};

class LocalTransport final : public Transport {
 public:
  LocalTransport(LocalNetwork& network, int endpoint) : net_(network), self_(endpoint) {}
  void send(int to, Channel channel, Bytes bytes) override;
  Incoming poll(double deadline) override;
  double now() const override { return net_.now(); }
  bool sharedClock() const override { return true; }
  // The connection drops: the master hears that this endpoint is gone.
  void dropConnection();

 private:
  LocalNetwork& net_;
  int self_;
};

}  // namespace prt
