#pragma once
// Transport: the seam between the driver kit's loops (drive/master_loop.h,
// drive/worker_loop.h) and whatever carries their bytes — mailboxes between threads
// (drive/local_transport.h) or MPI ranks (src/mpi). The loops hold all the policy (leases,
// heartbeats, reissue, checkpoints, the report); a transport only moves bytes, says when a
// peer is known to be gone, and tells the time. Every wait has a deadline.
//
// Endpoints are worker indices 0..c-1 and kMaster; c grows as workers join a running render.
// One transport per endpoint, used by one thread.

#include <cstdint>
#include <functional>

#include "cluster/messages.h"
#include "metrics/events.h"

namespace prt {

// What a packet carries: a protocol Message, or a worker's end-of-run summary.
enum class Channel : uint8_t { Protocol = 1, Summary = 2 };

struct Incoming {
  enum class Kind {
    Packet,    // `bytes` arrived from `from` on `channel`
    PeerLost,  // the transport knows `from` is gone (its thread ended, its link dropped)
    PeerJoined,  // a new worker `from` connected (the master's transport only); joiners are
                 // numbered in arrival order after the others, and this notice comes before
                 // any packet from it
    Timeout,   // nothing arrived before the deadline
  };
  Kind kind = Kind::Timeout;
  int from = kMaster;
  Channel channel = Channel::Protocol;
  Bytes bytes;
};

class Transport {
 public:
  virtual ~Transport() = default;
  // Starts sending; never blocks for the receiver. A send to a peer that is gone may succeed
  // silently: loss is found by leases, not by errors.
  virtual void send(int to, Channel channel, Bytes bytes) = 0;
  // The next incoming packet or loss notice, waiting at most until `deadline` (seconds on
  // now()'s clock; a deadline in the past polls without waiting).
  virtual Incoming poll(double deadline) = 0;
  // Seconds on this endpoint's steady clock.
  virtual double now() const = 0;
  // True when every endpoint reads the same clock (threads of one process), so workers'
  // event times need no alignment.
  virtual bool sharedClock() const { return false; }
  // Lets pending sends complete, for at most `timeoutSeconds`; false if some did not.
  virtual bool flush(double timeoutSeconds) {
    (void)timeoutSeconds;
    return true;
  }
};

// Encodes and sends every message of `out` from endpoint `from`, logging each as a
// MessageSent event on the transport's clock: how both loops send what a state machine says.
void sendOutbox(Transport& net, int from, const Outbox& out, EventLog& log);

// The master runs `work` on a thread of its own while this one sends workers 0 ..
// workers() - 1 a heartbeat every `beat` seconds: a long step of its own (a spot check it
// renders, a checkpoint it writes — a second or more for a 4K image) must not make the
// workers take it for gone. Their messages wait meanwhile; the master loop drains them before
// it judges any lease. Rethrows what `work` throws.
void whileHeartbeating(Transport& net, double beat, const std::function<int()>& workers,
                       const std::function<void()>& work);

}  // namespace prt
