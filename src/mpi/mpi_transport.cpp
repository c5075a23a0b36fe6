#include "mpi/mpi_transport.h"

#include <chrono>
#include <climits>
#include <cstring>
#include <thread>

namespace prt::mpi_detail {

void check(int code, const char* call, int rank) {
  if (code == MPI_SUCCESS) return;
  char text[MPI_MAX_ERROR_STRING] = {};
  int length = 0;
  if (MPI_Error_string(code, text, &length) != MPI_SUCCESS) length = 0;
  throw MpiError(std::string(call) + " failed: " + std::string(text, static_cast<size_t>(length)),
                 rank);
}

void pollPause() {
  std::this_thread::sleep_for(std::chrono::milliseconds(1));
}

// The analyzer cannot see that progress() and flush() complete the request kept in requests_.
// NOLINTBEGIN(clang-analyzer-optin.mpi.MPI-Checker)
void MpiTransport::send(int rank, int tag, Bytes bytes) {
  if (bytes.size() > static_cast<size_t>(INT_MAX)) {
    throw MpiError("message of " + std::to_string(bytes.size()) + " bytes exceeds MPI's limit",
                   rank);
  }
  MPI_Request request = MPI_REQUEST_NULL;
  // Moving the vector keeps its heap buffer, so the pointer stays valid in buffers_.
  buffers_.push_back(std::move(bytes));
  const Bytes& b = buffers_.back();
  const int code =
      MPI_Isend(b.data(), static_cast<int>(b.size()), MPI_BYTE, rank, tag, comm_, &request);
  if (code != MPI_SUCCESS) buffers_.pop_back();
  check(code, "MPI_Isend", rank);
  requests_.push_back(request);
  peers_.push_back(rank);
  progress();
}
// NOLINTEND(clang-analyzer-optin.mpi.MPI-Checker)

void MpiTransport::progress() {
  if (requests_.empty()) return;
  int done = 0;
  std::vector<int> indices(requests_.size());
  std::vector<MPI_Status> statuses(requests_.size());
  const int code = MPI_Testsome(static_cast<int>(requests_.size()), requests_.data(), &done,
                                indices.data(), statuses.data());
  if (code != MPI_SUCCESS) {
    // MPI_ERR_IN_STATUS: the failed request's status names it.
    int rank = -1;
    for (int i = 0; i < done && done != MPI_UNDEFINED; ++i) {
      if (statuses[static_cast<size_t>(i)].MPI_ERROR != MPI_SUCCESS) {
        rank = peers_[static_cast<size_t>(indices[static_cast<size_t>(i)])];
        break;
      }
    }
    check(code, "MPI_Isend (completion)", rank);
  }
  if (done == MPI_UNDEFINED || done == 0) return;
  // Completed requests are MPI_REQUEST_NULL now: drop them with their buffers.
  size_t kept = 0;
  for (size_t i = 0; i < requests_.size(); ++i) {
    if (requests_[i] == MPI_REQUEST_NULL) continue;
    if (kept != i) {
      requests_[kept] = requests_[i];
      buffers_[kept] = std::move(buffers_[i]);
      peers_[kept] = peers_[i];
    }
    ++kept;
  }
  requests_.resize(kept);
  buffers_.resize(kept);
  peers_.resize(kept);
}

std::optional<Packet> MpiTransport::poll() {
  progress();
  int found = 0;
  MPI_Message message = MPI_MESSAGE_NULL;
  MPI_Status status;
  check(MPI_Improbe(MPI_ANY_SOURCE, MPI_ANY_TAG, comm_, &found, &message, &status), "MPI_Improbe",
        -1);
  if (!found) return std::nullopt;
  int count = 0;
  check(MPI_Get_count(&status, MPI_BYTE, &count), "MPI_Get_count", status.MPI_SOURCE);
  Packet packet{status.MPI_SOURCE, status.MPI_TAG, Bytes(static_cast<size_t>(count))};
  check(MPI_Mrecv(packet.bytes.data(), count, MPI_BYTE, &message, MPI_STATUS_IGNORE), "MPI_Mrecv",
        status.MPI_SOURCE);
  return packet;
}

MpiLink::MpiLink(MPI_Comm comm) : net_(comm), start_(MPI_Wtime()) {}

double MpiLink::now() const {
  return MPI_Wtime() - start_;
}

void MpiLink::send(int to, Channel channel, Bytes bytes) {
  try {
    net_.send(rankOf(to), channel == Channel::Summary ? kSummaryTag : kMessageTag,
              std::move(bytes));
  } catch (const MpiError&) {
    // The peer is gone or its link is down: its lease will run out.
  }
}

Incoming MpiLink::poll(double deadline) {
  Incoming in;
  for (;;) {
    std::optional<Packet> p;
    try {
      p = net_.poll();
    } catch (const MpiError& e) {
      if (e.rank() < 0) throw;
      // A failed request to one peer: treat it as that peer's loss.
      in.kind = Incoming::Kind::PeerLost;
      in.from = endpointOf(e.rank());
      return in;
    }
    if (p) {
      in.from = endpointOf(p->rank);
      if (p->tag == kReleaseTag && p->rank == 0) {
        int32_t code = 1;
        if (p->bytes.size() == sizeof code) std::memcpy(&code, p->bytes.data(), sizeof code);
        release_ = code;
        in.kind = Incoming::Kind::PeerLost;
        return in;
      }
      if (p->tag != kMessageTag && p->tag != kSummaryTag) continue;  // not ours: dropped
      in.kind = Incoming::Kind::Packet;
      in.channel = p->tag == kSummaryTag ? Channel::Summary : Channel::Protocol;
      in.bytes = std::move(p->bytes);
      return in;
    }
    if (now() >= deadline) return in;
    pollPause();
  }
}

std::optional<int32_t> MpiLink::awaitRelease(double deadline) {
  while (!release_) {
    const Incoming in = poll(deadline);
    if (in.kind == Incoming::Kind::Timeout) break;
  }
  return release_;
}

bool MpiTransport::flush(double timeoutSeconds) {
  const auto deadline = std::chrono::steady_clock::now() +
                        std::chrono::duration_cast<std::chrono::steady_clock::duration>(
                            std::chrono::duration<double>(timeoutSeconds));
  for (;;) {
    progress();
    if (requests_.empty()) return true;
    if (std::chrono::steady_clock::now() > deadline) return false;
    pollPause();
  }
}

}  // namespace prt::mpi_detail
