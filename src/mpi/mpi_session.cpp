#include "mpi/mpi_session.h"

#include <chrono>
#include <condition_variable>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <stdexcept>
#include <mutex>
#include <string>
#include <thread>

#include "core/exit_status.h"
#include "core/thread_start.h"
#include "mpi/mpi_comm.h"
#include "mpi/mpi_transport.h"

namespace prt {

using mpi_detail::check;

namespace {

// Ends the process if start-up has not finished by the deadline.
class StartupWatchdog {
 public:
  explicit StartupWatchdog(double seconds)
      : thread_(startThread([this, seconds] {
          std::unique_lock<std::mutex> lock(mutex_);
          if (done_.wait_for(lock, std::chrono::duration<double>(seconds), [&] { return disarmed_; })) {
            return;
          }
          std::fprintf(stderr,
                       "prt: error: MPI start-up did not finish within %.0f s (a rank died or "
                       "cannot be reached while the job started); this rank ends (exit 1)\n",
                       seconds);
          std::fflush(stderr);
          recordExitStatus(1);
          std::_Exit(1);
        })) {}
  ~StartupWatchdog() { disarm(); }
  StartupWatchdog(const StartupWatchdog&) = delete;
  StartupWatchdog& operator=(const StartupWatchdog&) = delete;
  void disarm() {
    {
      const std::lock_guard<std::mutex> lock(mutex_);
      disarmed_ = true;
    }
    done_.notify_all();
    if (thread_.joinable()) thread_.join();
  }

 private:
  std::mutex mutex_;
  std::condition_variable done_;
  bool disarmed_ = false;
  std::thread thread_;
};

}  // namespace

MpiSession::MpiSession(bool threadMultiple, double startupSeconds)
    : comm_(std::make_unique<MpiComm>()) {
  StartupWatchdog watchdog(startupSeconds);
  int initialized = 0;
  MPI_Initialized(&initialized);
  if (initialized) throw std::runtime_error("MPI is already initialised in this process");
  int provided = MPI_THREAD_SINGLE;
  const int wanted = threadMultiple ? MPI_THREAD_MULTIPLE : MPI_THREAD_FUNNELED;
  if (MPI_Init_thread(nullptr, nullptr, wanted, &provided) != MPI_SUCCESS) {
    throw std::runtime_error("MPI_Init_thread failed");
  }
  try {
    if (provided < MPI_THREAD_FUNNELED) {
      throw std::runtime_error("the MPI library does not support MPI_THREAD_FUNNELED");
    }
    comm_->threadMultiple = provided >= MPI_THREAD_MULTIPLE;
    // A communicator of our own, so a failure is returned to us instead of aborting inside
    // MPI with a message that does not say what went wrong.
    check(MPI_Comm_dup(MPI_COMM_WORLD, &comm_->comm), "MPI_Comm_dup", -1);
    check(MPI_Comm_set_errhandler(comm_->comm, MPI_ERRORS_RETURN), "MPI_Comm_set_errhandler", -1);
    check(MPI_Comm_rank(comm_->comm, &rank_), "MPI_Comm_rank", -1);
    check(MPI_Comm_size(comm_->comm, &size_), "MPI_Comm_size", -1);
    // Who shares this node: the ranks MPI can reach through shared memory.
    MPI_Comm node = MPI_COMM_NULL;
    check(MPI_Comm_split_type(comm_->comm, MPI_COMM_TYPE_SHARED, rank_, MPI_INFO_NULL, &node),
          "MPI_Comm_split_type", -1);
    int lowest = rank_;
    check(MPI_Comm_size(node, &ranksOnNode_), "MPI_Comm_size", -1);
    check(MPI_Allreduce(&rank_, &lowest, 1, MPI_INT, MPI_MIN, node), "MPI_Allreduce", -1);
    rankZeroOnNode_ = lowest == 0;
    MPI_Comm_free(&node);
  } catch (const std::exception& e) {
    abort(e.what(), 1);
  }
  watchdog.disarm();
}

MpiSession::~MpiSession() {
  int finalized = 0;
  MPI_Finalized(&finalized);
  if (finalized) return;
  if (comm_->acceptor) comm_->acceptor->finishStop(0);
  comm_->link.reset();
  if (comm_->skipFinalize) {
    std::fflush(stdout);
    std::fflush(stderr);
    return;  // the process exits without MPI_Finalize; mpirun accepts it under recovery
  }
  if (comm_->comm != MPI_COMM_NULL) MPI_Comm_free(&comm_->comm);
  MPI_Finalize();
}

int MpiSession::exitCode(int code) const {
  if (!comm_->skipFinalize) return code;
  recordExitStatus(code);
  std::fflush(stdout);
  std::fflush(stderr);
  std::_Exit(code);
}

bool MpiSession::threadMultiple() const {
  return comm_->threadMultiple;
}

bool MpiSession::recoveryEnabled() const {
  const char* v = std::getenv("OMPI_MCA_orte_enable_recovery");
  return v != nullptr && std::string(v) != "0" && std::string(v) != "false";
}

void MpiSession::releaseWorkers(int exitCode) {
  if (!isMaster() || comm_->runStarted || comm_->released) return;
  comm_->released = true;
  try {
    mpi_detail::MpiTransport transport(comm_->comm);
    for (int r = 1; r < size_; ++r) {
      transport.send(r, kReleaseTag,
                     releaseMessage(static_cast<int32_t>(exitCode)));
    }
    if (!transport.flush(10.0)) {
      throw std::runtime_error("the workers did not take the release message within 10 s");
    }
  } catch (const std::exception& e) {
    abort(std::string("could not release the workers: ") + e.what(), exitCode);
  }
}

void MpiSession::abort(const std::string& message, int exitCode) const {
  std::fprintf(stderr, "prt: error: %s\n", message.c_str());
  std::fflush(stderr);
  std::fflush(stdout);
  recordExitStatus(exitCode);
  MPI_Abort(comm_->comm != MPI_COMM_NULL ? comm_->comm : MPI_COMM_WORLD, exitCode);
  std::_Exit(exitCode);  // MPI_Abort does not return; if it did, still end this rank
}

}  // namespace prt
