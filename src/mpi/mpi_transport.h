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

#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include "cluster/messages.h"

namespace prt::mpi_detail {

// One tag per kind of traffic; protocol messages are typed, so one tag carries them all.
enum Tag : int {
  kMessageTag = 1,  // an encoded protocol Message (cluster/messages.h)
  kSummaryTag = 2,  // worker -> master after StopMsg: an encoded WorkerSummary
  kReleaseTag = 3,  // master -> worker instead of the scene: exit with this int32 code
};

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

// The idle wait of every polling loop: short enough not to add latency that matters next to
// rendering a batch, long enough to leave the cores to ranks that are computing.
void pollPause();

}  // namespace prt::mpi_detail
