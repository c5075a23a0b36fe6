#include "mpi/mpi_transport.h"

#include "core/check.h"

#include <algorithm>
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

namespace {

int remoteSize(MPI_Comm inter) {
  int size = 0;
  check(MPI_Comm_remote_size(inter, &size), "MPI_Comm_remote_size", -1);
  return size;
}

}  // namespace

MpiLink::MpiLink(MPI_Comm world) : start_(MPI_Wtime()) {
  int rank = 0, size = 1;
  check(MPI_Comm_rank(world, &rank), "MPI_Comm_rank", -1);
  check(MPI_Comm_size(world, &size), "MPI_Comm_size", -1);
  master_ = rank == 0;
  self_ = master_ ? kMaster : endpointOf(rank);
  worldWorkers_ = size - 1;
  Route r;
  r.comm = world;
  r.net = std::make_unique<MpiTransport>(world);
  r.first = 0;
  r.count = size - 1;
  r.rankOffset = 1;
  routes_.push_back(std::move(r));
  endpoints_ = size - 1;
}

MpiLink::MpiLink(MPI_Comm inter, int self) : self_(self), start_(MPI_Wtime()) {
  Route r;
  r.comm = inter;
  r.net = std::make_unique<MpiTransport>(inter);
  routes_.push_back(std::move(r));
}

double MpiLink::now() const {
  return MPI_Wtime() - start_;
}

MpiLink::Route* MpiLink::routeOf(int endpoint, int& rank) {
  if (!master_) {
    if (endpoint == kMaster) {
      rank = 0;
      return &routes_[0];
    }
    if (worldWorkers_ > 0 && endpoint >= 0 && endpoint < worldWorkers_) {
      rank = rankOf(endpoint);
      return &routes_[0];
    }
    return nullptr;  // another job's worker: through the master
  }
  for (Route& r : routes_) {
    if (endpoint >= r.first && endpoint < r.first + r.count) {
      rank = endpoint - r.first + r.rankOffset;
      return &r;
    }
  }
  return nullptr;
}

void MpiLink::send(int to, Channel channel, Bytes bytes) {
  const int tag = channel == Channel::Summary ? kSummaryTag : kMessageTag;
  if (master_ && joiners_ && joiners_->send(to, tag, bytes)) return;
  try {
    int rank = 0;
    if (Route* r = routeOf(to, rank)) {
      r->net->send(rank, tag, std::move(bytes));
    } else if (!master_) {
      routes_[0].net->send(0, kRelayTag, withHeader(to, tag, bytes));
    }
  } catch (const MpiError&) {
    // The peer is gone or its link is down: its lease will run out.
  }
}

// Master: a worker's message for another worker it cannot reach.
void MpiLink::relay(int from, const Bytes& bytes) {
  int32_t to = 0, tag = 0;
  if (!readHeader(bytes, to, tag) || (tag != kMessageTag && tag != kSummaryTag)) return;
  const Bytes payload(bytes.begin() + 2 * sizeof(int32_t), bytes.end());
  if (joiners_ && joiners_->send(to, kRelayedTag, withHeader(from, tag, payload))) return;
  int rank = 0;
  Route* r = routeOf(to, rank);
  if (r == nullptr) return;  // no such worker: dropped, as a message to a dead one would be
  try {
    r->net->send(rank, kRelayedTag, withHeader(from, tag, payload));
  } catch (const MpiError&) {
  }
}

void MpiLink::adopt(MPI_Comm inter, const Bytes& welcome) {
  check(MPI_Comm_set_errhandler(inter, MPI_ERRORS_RETURN), "MPI_Comm_set_errhandler", -1);
  Route r;
  r.comm = inter;
  r.net = std::make_unique<MpiTransport>(inter);
  r.first = endpoints_;
  r.count = remoteSize(inter);
  endpoints_ += r.count;
  r.rankOffset = 0;
  for (int k = 0; k < r.count; ++k) {
    const int endpoint = r.first + k;
    r.net->send(k, kWelcomeTag, withHeader(endpoint, 0, welcome));
    pendingJoins_.push_back(endpoint);
  }
  routes_.push_back(std::move(r));
}

void MpiLink::setAcceptSource(std::function<std::optional<MPI_Comm>()> source, Bytes welcome) {
  acceptSource_ = std::move(source);
  welcome_ = std::move(welcome);
}

std::vector<MpiLink::JoinedJob> MpiLink::joinedJobs() const {
  std::vector<JoinedJob> out;
  for (size_t i = 1; i < routes_.size(); ++i) {
    out.push_back({routes_[i].comm, routes_[i].first, routes_[i].count});
  }
  return out;
}

void MpiLink::sendTagged(int endpoint, int tag, Bytes bytes) {
  if (joiners_ && joiners_->send(endpoint, tag, bytes)) return;
  int rank = 0;
  Route* r = routeOf(endpoint, rank);
  if (r == nullptr) return;
  try {
    r->net->send(rank, tag, std::move(bytes));
  } catch (const MpiError&) {
  }
}

bool MpiLink::flush(double timeoutSeconds) {
  bool all = !joiners_ || joiners_->door().flush(timeoutSeconds);
  for (Route& r : routes_) all = r.net->flush(timeoutSeconds) && all;
  return all;
}

Incoming MpiLink::poll(double deadline) {
  Incoming in;
  for (;;) {
    if (master_ && acceptSource_) {
      while (std::optional<MPI_Comm> inter = acceptSource_()) adopt(*inter, welcome_);
    }
    if (master_ && joiners_) {
      if (std::optional<Incoming> fromDoor = pollDoor()) return *fromDoor;
    }
    if (!pendingJoins_.empty()) {
      in.kind = Incoming::Kind::PeerJoined;
      in.from = pendingJoins_.front();
      pendingJoins_.erase(pendingJoins_.begin());
      return in;
    }
    for (size_t n = 0; n < routes_.size(); ++n) {
      Route& route = routes_[nextRoute_++ % routes_.size()];
      std::optional<Packet> p;
      try {
        p = route.net->poll();
      } catch (const MpiError& e) {
        if (e.rank() < 0) throw;
        // A failed request to one peer: treat it as that peer's loss.
        in.kind = Incoming::Kind::PeerLost;
        in.from = master_ ? route.first + e.rank() - route.rankOffset
                          : (e.rank() == 0 ? kMaster : endpointOf(e.rank()));
        return in;
      }
      if (!p) continue;
      const bool fromMaster = !master_ && p->rank == 0;
      in.from = master_ ? route.first + p->rank - route.rankOffset
                        : (fromMaster ? kMaster : endpointOf(p->rank));
      if (p->tag == kReleaseTag && fromMaster) {
        int32_t code = 1;
        if (p->bytes.size() >= sizeof code) std::memcpy(&code, p->bytes.data(), sizeof code);
        if (p->bytes.size() > sizeof code) {
          wakePort_.assign(p->bytes.begin() + sizeof code, p->bytes.end());
        }
        release_ = code;
        in.kind = Incoming::Kind::PeerLost;
        in.from = kMaster;
        return in;
      }
      if (p->tag == kRelayTag && master_) {
        relay(in.from, p->bytes);
        continue;
      }
      int tag = p->tag;
      if (p->tag == kRelayedTag && fromMaster) {
        int32_t from = 0, inner = 0;
        if (!readHeader(p->bytes, from, inner)) continue;
        in.from = from;
        tag = inner;
        p->bytes.erase(p->bytes.begin(), p->bytes.begin() + 2 * sizeof(int32_t));
      }
      if (tag != kMessageTag && tag != kSummaryTag) continue;  // not ours: dropped
      in.kind = Incoming::Kind::Packet;
      in.channel = tag == kSummaryTag ? Channel::Summary : Channel::Protocol;
      in.bytes = std::move(p->bytes);
      return in;
    }
    if (now() >= deadline) return in;
    pollPause();
  }
}

// Master: a TCP joiner is numbered after every worker adopted so far and announced in turn,
// after the MPI joiners still to be announced.
std::optional<Incoming> MpiLink::pollDoor() {
  for (;;) {
    std::optional<Incoming> in = joiners_->poll([this] { return endpoints_++; },
                                                [this](int from, const Bytes& bytes) { relay(from, bytes); });
    if (!in || in->kind != Incoming::Kind::PeerJoined) return in;
    pendingJoins_.push_back(in->from);
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
