#pragma once
// MpiSession: MPI for the lifetime of one run under mpirun, as an RAII object
// (MPI_Init_thread in the constructor, MPI_Finalize in the destructor). Rank 0 is the master;
// rank r >= 1 is worker r - 1, so `mpirun -np N+1` gives N workers.
//
// Errors: the session's communicator returns MPI errors instead of aborting inside MPI, so the
// driver can say which rank failed; a failed run then ends every rank with abort(), which
// prints the reason and calls MPI_Abort — no rank is ever left waiting.
// Ending: MPI_Finalize in the destructor, unless a rank was lost (it would wait for it): then
// the process exits without it, as Open MPI allows under --enable-recovery.
// Threading: MPI_THREAD_FUNNELED, or MULTIPLE when asked for. Only the thread that created
// the session may use it or call the MPI driver, but for the master's port listener
// (--accept-workers) and prt join's connect watchdog; other threads (e.g. a multi-threaded
// render) must not call MPI.
// This header does not include <mpi.h>: nothing outside src/mpi sees MPI.

#include <memory>
#include <string>

namespace prt {

struct MpiComm;  // the communicator and run state; defined inside src/mpi only

inline constexpr double kDefaultMpiStartupSeconds = 120;

class MpiSession {
 public:
  // Throws std::runtime_error if MPI cannot start or provide MPI_THREAD_FUNNELED. With
  // `threadMultiple`, asks for MPI_THREAD_MULTIPLE (a port listener, a connect watchdog);
  // whether it came is threadMultiple() — otherwise FUNNELED, as every other run needs.
  //
  // Start-up has a deadline: a rank killed while the others are inside MPI_Init_thread leaves
  // them waiting there for ever, with no error and no CPU use. If initialisation has not
  // finished after `startupSeconds`, this rank says so and ends with exit code 1 (nothing has
  // been written yet: a checkpoint from before is kept as it was).
  explicit MpiSession(bool threadMultiple = false,
                      double startupSeconds = kDefaultMpiStartupSeconds);
  ~MpiSession();
  MpiSession(const MpiSession&) = delete;
  MpiSession& operator=(const MpiSession&) = delete;

  int rank() const { return rank_; }
  int size() const { return size_; }
  bool isMaster() const { return rank_ == 0; }
  int workerCount() const { return size_ - 1; }
  bool threadMultiple() const;
  // The ranks of this job on this rank's node (itself included), and whether rank 0 is among
  // them: what a worker's default thread count shares the node's CPUs among.
  int ranksOnThisNode() const { return ranksOnNode_; }
  bool rankZeroOnThisNode() const { return rankZeroOnNode_; }

  // Master only. Before a run has started: tells every worker there will be no run (bad input
  // on the master, which reports it), and they exit with `exitCode` without printing. Once the
  // master has sent the scene it does nothing: the run then either finishes, releasing the
  // workers with StopMsg, or ends the whole job with abort().
  void releaseWorkers(int exitCode);

  // Prints "prt: error: <message>" to stderr and ends every rank of the job with `exitCode`.
  [[noreturn]] void abort(const std::string& message, int exitCode = 1) const;

  // The process's exit code: returns `code`, or ends the process with it at once when a rank
  // was lost (MPI_Finalize would wait for it).
  int exitCode(int code) const;

  // True under `mpirun --enable-recovery`: a rank that dies does not end the job.
  bool recoveryEnabled() const;

  MpiComm& comm() const { return *comm_; }  // for the driver in src/mpi

 private:
  std::unique_ptr<MpiComm> comm_;
  int rank_ = 0;
  int ranksOnNode_ = 1;
  bool rankZeroOnNode_ = true;
  int size_ = 1;
};

}  // namespace prt
