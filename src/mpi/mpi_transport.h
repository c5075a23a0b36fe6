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
#include "drive/transport.h"

namespace prt::mpi_detail {

// One tag per kind of traffic; protocol messages are typed, so one tag carries them all.
enum Tag : int {
  kMessageTag = 1,  // an encoded protocol Message (cluster/messages.h)
  kSummaryTag = 2,  // worker -> master after StopMsg: an encoded WorkerSummary
  kReleaseTag = 3,  // master -> worker: the job's end; an int32 (see ReleaseCode)
};

// What a release tells a worker rank to do.
enum ReleaseCode : int32_t {
  kReleaseFinalize = 0,  // the run is over and every rank is there: MPI_Finalize, exit 0
  kReleaseExit = -1,     // the run is over but a rank was lost: exit 0 without MPI_Finalize
  // > 0: the master refused the run (bad input): exit with this code
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

// The driver kit's Transport over MPI ranks: protocol messages and summaries as tagged byte
// buffers (endpoint e is rank e + 1). Sends never block and never throw for a lost peer (a
// send to a dead rank may even succeed: loss is found by leases); polls sleep briefly between
// probes. A release from the master arrives as the master's loss (the loop ends) and is kept
// for the caller in release().
class MpiLink final : public Transport {
 public:
  explicit MpiLink(MPI_Comm comm);
  void send(int to, Channel channel, Bytes bytes) override;
  Incoming poll(double deadline) override;
  double now() const override;
  bool flush(double timeoutSeconds) override { return net_.flush(timeoutSeconds); }
  std::optional<int32_t> release() const { return release_; }
  // Waits until `deadline` for a release from the master (after the run).
  std::optional<int32_t> awaitRelease(double deadline);

 private:
  MpiTransport net_;
  std::optional<int32_t> release_;
  double start_;
};

// The idle wait of every polling loop: short enough not to add latency that matters next to
// rendering a batch, long enough to leave the cores to ranks that are computing.
void pollPause();

}  // namespace prt::mpi_detail
