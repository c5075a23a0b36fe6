#pragma once
// Internal to src/mpi (it includes <mpi.h>; public headers never include it).
//
// MpiTransport: byte buffers between ranks without ever blocking inside MPI. Sends are
// MPI_Isend with the buffer kept until MPI is done with it, so two ranks sending each other
// large messages at once cannot deadlock; receives are MPI_Improbe + MPI_Mrecv of whatever has
// arrived. Open MPI's blocking calls spin at full speed, which would steal the cores that
// oversubscribed ranks render on, so callers poll and sleep briefly instead of blocking.
// Every MPI error becomes an MpiError naming the peer rank (the session's communicator uses
// MPI_ERRORS_RETURN). One transport per rank; only the thread that created the session.

#include <mpi.h>

#include <functional>
#include <memory>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include "cluster/messages.h"
#include "drive/transport.h"
#include "net/link_tags.h"
#include "net/tcp_joiners.h"

namespace prt::mpi_detail {

// Tags and release codes: net/link_tags.h (one numbering for the MPI and TCP links).

// A protocol endpoint (worker index, or kMaster = -1) and its rank: rank 0 is the master.
inline int rankOf(int endpoint) {
  return endpoint + 1;
}
inline int endpointOf(int rank) {
  return rank - 1;
}

// An MPI call failed. `rank` is the peer involved, or -1 when MPI could not say.
class MpiError : public std::runtime_error {
 public:
  MpiError(const std::string& message, int rank) : std::runtime_error(message), rank_(rank) {}
  int rank() const { return rank_; }

 private:
  int rank_;
};

// Throws MpiError if `code` is not MPI_SUCCESS.
void check(int code, const char* call, int rank);

struct Packet {
  int rank = 0;  // the sender
  int tag = 0;
  Bytes bytes;
};

class MpiTransport {
 public:
  explicit MpiTransport(MPI_Comm comm) : comm_(comm) {}
  MpiTransport(const MpiTransport&) = delete;
  MpiTransport& operator=(const MpiTransport&) = delete;

  // Starts sending; the bytes are kept until the send completes.
  void send(int rank, int tag, Bytes bytes);
  // The next message that has arrived from any rank, with any tag, if there is one.
  std::optional<Packet> poll();
  // Lets pending sends advance and releases the finished ones.
  void progress();
  // Waits (polling) until every send has completed. False if `timeoutSeconds` passed first.
  bool flush(double timeoutSeconds);
  size_t pendingSends() const { return requests_.size(); }

 private:
  MPI_Comm comm_;
  std::vector<MPI_Request> requests_;  // parallel to buffers_ and peers_
  std::vector<Bytes> buffers_;
  std::vector<int> peers_;
};

// The driver kit's Transport over MPI ranks: protocol messages and summaries as tagged byte
// buffers. Sends never block and never throw for a lost peer (a send to a dead rank may even
// succeed: loss is found by leases); polls sleep briefly between probes. A release from the
// master arrives as the master's loss (the loop ends) and is kept for the caller in release().
//
// Routes. The starting workers are ranks of the job's world (endpoint e is rank e + 1).
// Workers that join later (`prt join`) come in another job, over an intercommunicator the
// master accepted (adopt()); the master numbers them in arrival order after the others and
// reports each as PeerJoined. A worker reaches the master and its own job's world directly;
// a message to any other worker (a Transfer between a starting worker and a joiner) goes
// through the master, which relays it unseen by the loops.
class MpiLink final : public Transport {
 public:
  // On the job's world: the master (rank 0) or a starting worker.
  explicit MpiLink(MPI_Comm world);
  // A joiner: `inter` reaches the master as remote rank 0; this endpoint is `self`.
  MpiLink(MPI_Comm inter, int self);

  void send(int to, Channel channel, Bytes bytes) override;
  Incoming poll(double deadline) override;
  double now() const override;
  bool flush(double timeoutSeconds) override;
  std::optional<int32_t> release() const { return release_; }
  // Waits until `deadline` for a release from the master (after the run).
  std::optional<int32_t> awaitRelease(double deadline);
  // With the release, the port this worker must connect to once, to wake the master's
  // listener (empty: none).
  const std::string& wakePort() const { return wakePort_; }

  // Master: the workers of an accepted intercommunicator become the next endpoints; each gets
  // a welcome (its endpoint, then `welcome`) and is reported as PeerJoined by later polls.
  void adopt(MPI_Comm inter, const Bytes& welcome);
  // Master: where accepted intercommunicators come from (polled by poll()); may be null.
  void setAcceptSource(std::function<std::optional<MPI_Comm>()> source, Bytes welcome);
  // Master: the intercommunicators adopted, for the end of the job, with the endpoints each
  // carries (first, count).
  struct JoinedJob {
    MPI_Comm comm = MPI_COMM_NULL;
    int first = 0, count = 0;
  };
  std::vector<JoinedJob> joinedJobs() const;
  // Master: every worker's endpoint, 0 .. endpointCount()-1, the joiners' included.
  int endpointCount() const { return endpoints_; }
  // Master: workers that join over TCP come through `door` (net/tcp_door.h), numbered with
  // the others in arrival order; each gets the welcome and is reported as PeerJoined.
  void setTcpDoor(TcpDoor& door, Bytes welcome) { joiners_.emplace(door, std::move(welcome)); }
  // Master: the endpoints of the workers that joined over TCP.
  std::vector<int> tcpJoiners() const { return joiners_ ? joiners_->endpoints() : std::vector<int>{}; }
  // Master: sends `bytes` with a tag of its own (a release) to worker `endpoint`.
  void sendTagged(int endpoint, int tag, Bytes bytes);

 private:
  struct Route {
    MPI_Comm comm = MPI_COMM_NULL;
    std::unique_ptr<MpiTransport> net;
    int first = 0;      // master: the endpoint of its rank `rankOffset` (see below)
    int count = 0;      // endpoints on it
    int rankOffset = 0; // rank of endpoint `first` (1 on the world, 0 on an intercomm)
  };
  Route* routeOf(int endpoint, int& rank);
  void relay(int from, const Bytes& bytes);
  // Master: takes what the TCP door has; an Incoming to return, if one came.
  std::optional<Incoming> pollDoor();

  bool master_ = false;
  int self_ = kMaster;
  int worldWorkers_ = 0;  // starting workers (the world's size - 1); 0 for a joiner
  std::vector<Route> routes_;
  std::vector<int> pendingJoins_;  // endpoints adopted, not yet reported
  std::function<std::optional<MPI_Comm>()> acceptSource_;
  Bytes welcome_;
  std::optional<int32_t> release_;
  std::string wakePort_;
  int endpoints_ = 0;  // master: endpoints numbered so far
  std::optional<TcpJoiners> joiners_;  // master: those that joined through the TCP door
  size_t nextRoute_ = 0;  // round robin over the routes' polls
  double start_;
};

// The idle wait of every polling loop: short enough not to add latency that matters next to
// rendering a batch, long enough to leave the cores to ranks that are computing.
void pollPause();

}  // namespace prt::mpi_detail
