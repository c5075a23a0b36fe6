#include "mpi/mpi_acceptor.h"

#include <chrono>
#include <cstdio>

#include "core/input_error.h"
#include "image/atomic_file.h"
#include "mpi/mpi_transport.h"

namespace prt::mpi_detail {

MpiAcceptor::MpiAcceptor(const std::string& portFile) : file_(portFile) {
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
  port_ = name;
  try {
    writeFileAtomically(file_, port_ + "\n");
  } catch (...) {
    MPI_Close_port(name);
    throw;
  }
  thread_ = std::thread([this] { acceptLoop(); });
}

MpiAcceptor::~MpiAcceptor() {
  finishStop(0);
}

void MpiAcceptor::acceptLoop() {
  std::vector<char> port(port_.begin(), port_.end());
  port.push_back('\0');
  for (;;) {
    MPI_Comm inter = MPI_COMM_NULL;
    const int code = MPI_Comm_accept(port.data(), MPI_INFO_NULL, 0, MPI_COMM_SELF, &inter);
    if (stopping_) {
      if (code == MPI_SUCCESS) MPI_Comm_disconnect(&inter);  // the wake-up call
      break;
    }
    if (code != MPI_SUCCESS) {
      // A joiner that failed half-way; the port stays open for the next.
      std::fprintf(stderr, "prt: warning: a worker could not join (MPI_Comm_accept failed)\n");
      continue;
    }
    std::lock_guard<std::mutex> lock(mutex_);
    accepted_.push_back(inter);
  }
  finished_ = true;
}

std::optional<MPI_Comm> MpiAcceptor::take() {
  std::lock_guard<std::mutex> lock(mutex_);
  if (accepted_.empty()) return std::nullopt;
  MPI_Comm c = accepted_.front();
  accepted_.pop_front();
  return c;
}

void MpiAcceptor::beginStop() {
  if (begun_) return;
  begun_ = true;
  std::remove(file_.c_str());
  stopping_ = true;
}

void MpiAcceptor::finishStop(double graceSeconds) {
  if (stopped_) return;
  beginStop();
  stopped_ = true;
  const auto until = std::chrono::steady_clock::now() +
                     std::chrono::duration_cast<std::chrono::steady_clock::duration>(
                         std::chrono::duration<double>(graceSeconds));
  while (!finished_ && std::chrono::steady_clock::now() < until) {
    std::this_thread::sleep_for(std::chrono::milliseconds(5));
  }
  if (finished_) {
    thread_.join();
    std::vector<char> port(port_.begin(), port_.end());
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
    MPI_Comm_disconnect(&c);
  }
}

}  // namespace prt::mpi_detail
