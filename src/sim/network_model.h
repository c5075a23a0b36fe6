#pragma once
// The simulator's network: a switched, full-duplex LAN in which every endpoint (the master,
// each worker) has its own link to the switch, `bandwidth` each way.
//
// A message of b bytes sent at time t
//   - waits for the sender's outgoing link, then occupies it for b / bandwidth;
//   - reaches the receiver's port `latency` after it started leaving;
//   - waits for the receiver's incoming link, then occupies it for b / bandwidth, and is
//     delivered when its last byte is in (cut-through switching: an uncontended message
//     takes latency + b / bandwidth).
// So a worker's results and its next batch overlap (sends are asynchronous, as MPI_Isend and
// the local driver's mailboxes are), and many workers sending to the master at once queue on
// the master's incoming link: the incast that limits a master-worker ray tracer at scale.
// Messages between two endpoints arrive in the order they were sent.
//
// Defaults, for a 1 Gbit/s Ethernet LAN such as the paper's:
//   bandwidth 125 MB/s    1 Gbit/s per link and direction;
//   latency   50 us       one way through a switch and the TCP/MPI stacks (a ping on a
//                         1 Gbit LAN is 50-150 us round trip);
//   service   5 us        master CPU per received message (decode, bookkeeping, strategy):
//                         the master handles one message at a time, so they queue there.
//
// Not thread-safe; owned by one simulator.

#include <cstdint>
#include <vector>

#include "cluster/messages.h"

namespace prt {

struct NetworkOptions {
  double latencySeconds = 50e-6;           // one way, per message
  double bandwidthBytesPerSecond = 125e6;  // per link and direction (1 Gbit/s)
  double masterServiceSeconds = 5e-6;      // master busy time per received message
};

// Throws InputError for a negative or non-finite latency or service time, or a bandwidth
// that is not positive.
void validateNetworkOptions(const NetworkOptions& options);

// The encoded size of `message` in bytes, as the real transports would move and count it. A
// ResultsMsg without colours (the simulator's) is counted with the 12 bytes per pixel its
// colours would take.
uint64_t messageBytes(const Message& message);

class NetworkModel {
 public:
  NetworkModel(int workerCount, NetworkOptions options);

  const NetworkOptions& options() const { return options_; }

  // A message of `bytes` from `from` leaves at `now`: reserves the sender's outgoing link
  // and returns when it reaches the receiver's port. Call in time order.
  double depart(int from, uint64_t bytes, double now);
  // The message reaches `to` at `now` (a time depart() returned): reserves the receiver's
  // incoming link and returns the delivery time. Call in time order.
  double arrive(int to, uint64_t bytes, double now);
  // One more worker (a machine that comes back after a repair): its links, free now.
  void addWorker() {
    outFree_.push_back(0.0);
    inFree_.push_back(0.0);
  }

 private:
  double transmitSeconds(uint64_t bytes) const;
  size_t linkOf(int endpoint) const {
    return endpoint == kMaster ? 0 : static_cast<size_t>(endpoint) + 1;
  }

  NetworkOptions options_;
  std::vector<double> outFree_;  // per endpoint (master first): when its outgoing link frees
  std::vector<double> inFree_;   // per endpoint: when its incoming link frees
};

}  // namespace prt
