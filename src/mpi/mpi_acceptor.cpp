#include "mpi/mpi_acceptor.h"

#include <chrono>
#include <cstdio>
#include <cstring>

#include "core/thread_start.h"
#include "core/input_error.h"
#include "mpi/mpi_transport.h"

namespace prt::mpi_detail {

MpiAcceptor::MpiAcceptor(const std::string& portFile, const Secret& secret,
                         const std::vector<std::string>& tcpAddresses)
    : file_(portFile) {
  int provided = MPI_THREAD_SINGLE;
  check(MPI_Query_thread(&provided), "MPI_Query_thread", -1);
  if (provided < MPI_THREAD_MULTIPLE) {
    throw MpiError("--accept-workers needs MPI_THREAD_MULTIPLE, which this MPI does not provide",
                   -1);
  }
  check(MPI_Comm_set_errhandler(MPI_COMM_SELF, MPI_ERRORS_RETURN), "MPI_Comm_set_errhandler",
        -1);
  char name[MPI_MAX_PORT_NAME] = {};
  check(MPI_Open_port(MPI_INFO_NULL, name), "MPI_Open_port", -1);
  state_->port = name;
  state_->secret = secret;
  try {
    claim_.emplace(file_, portFileText(state_->port, state_->secret, tcpAddresses));
  } catch (...) {
    MPI_Close_port(name);
    throw;
  }
  thread_ = startThread([state = state_] { acceptLoop(state); });
}

namespace {

constexpr int kWakeTag = 7;

// After the stop began: whether `inter` is the wake-up call (a one-process job that sends
// kWakeTag at once) rather than a late joiner.
bool isWakeUp(MPI_Comm inter) {
  int remote = 0;
  if (MPI_Comm_remote_size(inter, &remote) != MPI_SUCCESS || remote != 1) return false;
  const auto until = std::chrono::steady_clock::now() + std::chrono::seconds(2);
  while (std::chrono::steady_clock::now() < until) {
    int found = 0;
    MPI_Status status;
    if (MPI_Iprobe(0, kWakeTag, inter, &found, &status) != MPI_SUCCESS) return false;
    if (found) {
      int32_t word = 0;
      MPI_Recv(&word, 1, MPI_INT32_T, 0, kWakeTag, inter, MPI_STATUS_IGNORE);
      return true;
    }
    std::this_thread::sleep_for(std::chrono::milliseconds(1));
  }
  return false;
}

}  // namespace

MpiAcceptor::~MpiAcceptor() {
  finishStop(0);
}

void MpiAcceptor::acceptLoop(const std::shared_ptr<State>& state) {
  std::vector<char> port(state->port.begin(), state->port.end());
  port.push_back('\0');
  for (;;) {
    MPI_Comm inter = MPI_COMM_NULL;
    const int code = MPI_Comm_accept(port.data(), MPI_INFO_NULL, 0, MPI_COMM_SELF, &inter);
    if (code != MPI_SUCCESS) {
      if (state->stopping) break;
      // A joiner that failed half-way; the port stays open for the next.
      std::fprintf(stderr, "prt: warning: a worker could not join (MPI_Comm_accept failed)\n");
      continue;
    }
    MPI_Comm_set_errhandler(inter, MPI_ERRORS_RETURN);
    if (state->stopping) {
      const bool wake = isWakeUp(inter);
      MPI_Comm_disconnect(&inter);  // the wake-up call, or a joiner too late to help
      if (wake) break;
      continue;
    }
    const std::string refusal = admit(*state, inter);
    if (!refusal.empty()) {
      std::fprintf(stderr, "prt: a joiner was refused: %s\n", refusal.c_str());
      int remote = 0;
      MPI_Comm_remote_size(inter, &remote);
      // Small enough to go out at once (eager), whether or not anyone receives it.
      for (int k = 0; k < remote; ++k) {
        MPI_Send(refusal.data(), static_cast<int>(refusal.size()), MPI_CHAR, k, kRefusedTag, inter);
      }
      // Not MPI_Comm_disconnect: it waits for the other side, which may never come.
      MPI_Comm_free(&inter);
      std::lock_guard<std::mutex> lock(state->mutex);
      state->refused.push_back(refusal);
      continue;
    }
    std::lock_guard<std::mutex> lock(state->mutex);
    state->accepted.push_back(inter);
  }
  state->finished = true;
}

std::string MpiAcceptor::admit(const State& state, MPI_Comm inter) {
  int remote = 0;
  if (MPI_Comm_remote_size(inter, &remote) != MPI_SUCCESS || remote < 1) {
    return "its connection could not be read";
  }
  std::vector<Challenge> challenges(static_cast<size_t>(remote));
  for (int k = 0; k < remote; ++k) {
    challenges[static_cast<size_t>(k)] = newChallenge();
    if (MPI_Send(challenges[static_cast<size_t>(k)].data(), 32, MPI_BYTE, k, kChallengeTag,
                 inter) != MPI_SUCCESS) {
      return "its rank " + std::to_string(k) + " could not be reached";
    }
  }
  const auto until = std::chrono::steady_clock::now() +
                     std::chrono::duration_cast<std::chrono::steady_clock::duration>(
                         std::chrono::duration<double>(kProofSeconds));
  for (int k = 0; k < remote; ++k) {
    for (;;) {
      int found = 0;
      MPI_Status status;
      if (MPI_Iprobe(k, kProofTag, inter, &found, &status) != MPI_SUCCESS) {
        return "its rank " + std::to_string(k) + " failed";
      }
      if (found) {
        int count = 0;
        MPI_Get_count(&status, MPI_BYTE, &count);
        if (count < 0 || count > 4096) return "its proof was not one";
        std::vector<uint8_t> proof(static_cast<size_t>(count));
        MPI_Recv(proof.data(), count, MPI_BYTE, k, kProofTag, inter, MPI_STATUS_IGNORE);
        std::string host;
        const std::string why =
            checkProof(state.secret, challenges[static_cast<size_t>(k)], proof, &host);
        if (!why.empty()) return why;
        std::lock_guard<std::mutex> lock(state.mutex);
        if (state.blocked.count(host)) {
          return "its machine '" + host + "' had a worker rejected earlier in this run";
        }
        break;
      }
      if (state.stopping) return "the render was ending";
      if (std::chrono::steady_clock::now() > until) {
        return "it did not prove it was invited within " +
               std::to_string(static_cast<int>(kProofSeconds)) + " s";
      }
      std::this_thread::sleep_for(std::chrono::milliseconds(1));
    }
  }
  return "";
}

void MpiAcceptor::block(const std::string& host) {
  std::lock_guard<std::mutex> lock(state_->mutex);
  state_->blocked.insert(host);
}

std::vector<std::string> MpiAcceptor::refused() const {
  std::lock_guard<std::mutex> lock(state_->mutex);
  return state_->refused;
}

std::optional<MPI_Comm> MpiAcceptor::take() {
  std::lock_guard<std::mutex> lock(state_->mutex);
  if (state_->accepted.empty()) return std::nullopt;
  MPI_Comm c = state_->accepted.front();
  state_->accepted.pop_front();
  return c;
}

void MpiAcceptor::beginStop() {
  if (begun_) return;
  begun_ = true;
  if (claim_) claim_->release();
  state_->stopping = true;
}

void MpiAcceptor::finishStop(double graceSeconds) {
  if (stopped_) return;
  beginStop();
  stopped_ = true;
  const auto until = std::chrono::steady_clock::now() +
                     std::chrono::duration_cast<std::chrono::steady_clock::duration>(
                         std::chrono::duration<double>(graceSeconds));
  while (!state_->finished && std::chrono::steady_clock::now() < until) {
    std::this_thread::sleep_for(std::chrono::milliseconds(5));
  }
  if (state_->finished) {
    thread_.join();
    std::vector<char> port(state_->port.begin(), state_->port.end());
    port.push_back('\0');
    MPI_Close_port(port.data());
  } else {
    thread_.detach();  // nobody could wake it: left blocked (see the header)
  }
  while (std::optional<MPI_Comm> late = take()) MPI_Comm_disconnect(&*late);
}

void wakeAcceptor(const std::string& port) {
  std::vector<char> name(port.begin(), port.end());
  name.push_back('\0');
  MPI_Comm c = MPI_COMM_NULL;
  if (MPI_Comm_connect(name.data(), MPI_INFO_NULL, 0, MPI_COMM_SELF, &c) == MPI_SUCCESS) {
    const int32_t word = 1;
    MPI_Send(&word, 1, MPI_INT32_T, 0, kWakeTag, c);
    MPI_Comm_disconnect(&c);
  }
}

}  // namespace prt::mpi_detail
