#include "mpi/mpi_driver.h"

#include <fcntl.h>
#include <poll.h>
#include <sys/syscall.h>
#include <signal.h>
#include <unistd.h>

#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <thread>

#include "core/check.h"
#include "core/input_error.h"
#include "mpi/mpi_comm.h"
#include "mpi/mpi_transport.h"

namespace prt {
namespace {

using namespace mpi_detail;

std::string rankName(int worker) {
  return "worker rank " + std::to_string(rankOf(worker)) + " (worker " + std::to_string(worker) +
         ")";
}

[[noreturn]] void failAsInjected(const FaultInjection& fault, int id) {
  const bool crash = fault.kind == FaultInjection::Kind::Crash;
  std::fprintf(stderr, "prt: %s: injected %s after %llu pixels; %s\n", rankName(id).c_str(),
               crash ? "crash" : "hang", static_cast<unsigned long long>(fault.afterPixels),
               crash ? "exiting" : "no longer answering");
  std::fflush(stderr);
  if (crash) std::_Exit(3);  // as a machine dropping off the network: no goodbye to MPI
  for (;;) std::this_thread::sleep_for(std::chrono::milliseconds(100));
}

// The process that started this rank (mpirun, or Open MPI's daemon on another host), if it
// is one: its command name, read from /proc.
std::string launcherName(pid_t pid) {
  std::FILE* f = std::fopen(("/proc/" + std::to_string(pid) + "/comm").c_str(), "r");
  if (f == nullptr) return "";
  char name[64] = {};
  const bool ok = std::fgets(name, sizeof name, f) != nullptr;
  std::fclose(f);
  if (!ok) return "";
  std::string n(name);
  while (!n.empty() && (n.back() == '\n' || n.back() == ' ')) n.pop_back();
  return n;
}

// Forks a watchdog that, `graceSeconds` from now, sends SIGTERM to the launcher that started
// this rank if it is still running — the one way left to end a job whose lost rank hangs
// under --enable-recovery (MPI_Abort does not end it then). mpirun forwards the signal to the
// job, so the hung process ends too. A launcher that returned in time is left alone: the
// watchdog holds a pidfd of it, so a later process with the same pid is never signalled.
// False when this rank was not started by a launcher it recognises.
bool endLauncherIfStillRunningAfter(double graceSeconds) {
  const pid_t launcher = ::getppid();
  const std::string name = launcherName(launcher);
  if (name != "mpirun" && name != "mpiexec" && name != "orterun" && name != "orted" &&
      name != "prterun") {
    return false;
  }
  // A pidfd names this very process: once it ends, a new process that reuses its pid is
  // never signalled.
  const int launcherFd = static_cast<int>(::syscall(SYS_pidfd_open, launcher, 0));
  if (launcherFd < 0) return false;
  std::fflush(nullptr);
  const pid_t child = ::fork();
  if (child != 0) {
    ::close(launcherFd);
    return child > 0;
  }
  // The watchdog: no MPI, no inherited output pipes (mpirun waits for their end), its own
  // session so the job's signals do not reach it.
  ::setsid();
  const int devnull = ::open("/dev/null", O_RDWR);
  for (int fd = 0; fd < 1024; ++fd) {
    if (fd != devnull && fd != launcherFd) ::close(fd);
  }
  ::dup2(devnull, 0);
  ::dup2(devnull, 1);
  ::dup2(devnull, 2);
  // The pidfd becomes readable when the launcher ends: wait for that, or the grace period.
  pollfd ended{launcherFd, POLLIN, 0};
  const int waited = ::poll(&ended, 1, static_cast<int>(graceSeconds * 1000));
  if (waited == 0) ::syscall(SYS_pidfd_send_signal, launcherFd, SIGTERM, nullptr, 0);
  ::_exit(0);
}

}  // namespace

ParallelRun renderMpiMaster(MpiSession& session, const RunRequest& request) {
  PRT_CHECK(session.isMaster());
  const ParallelOptions& options = request.options;
  if (options.workers != session.workerCount()) {
    throw InputError("the run is set up for " + std::to_string(options.workers) +
                     " workers but mpirun started " + std::to_string(session.workerCount()));
  }
  validateParallelOptions(
      options, static_cast<uint64_t>(request.scene.image.width) * request.scene.image.height);
  session.comm().runStarted = true;
  MpiLink link(session.comm().comm);
  ParallelRun run = runMasterSide(link, request, "mpi");
  link.flush(options.workerTimeoutSeconds);
  return run;
}

void finishMpiMaster(MpiSession& session, const ParallelRun& run) {
  const FaultInfo& faults = run.report.info.faults;
  const bool clean = faults.lostWorkers.empty() && faults.missingSummaries.empty();
  if (!clean && !session.recoveryEnabled()) {
    // Without --enable-recovery the job is still alive only because the lost ranks hang, and a
    // rank that exits without MPI_Finalize would end it in error: end them all, and the job,
    // with MPI_Abort's code 0. The live workers wait for it (see runMpiWorker).
    session.comm().skipFinalize = true;
    std::fprintf(stderr,
                 "prt: %zu worker rank(s) were lost; the image and report are complete. Ending "
                 "the job with MPI_Abort(0) so that mpirun does not wait for them\n",
                 faults.lostWorkers.size() + faults.missingSummaries.size());
    std::fflush(stdout);
    std::fflush(stderr);
    MPI_Abort(session.comm().comm, 0);
    std::_Exit(0);
  }
  MpiTransport net(session.comm().comm);
  const int32_t code = clean ? kReleaseFinalize : kReleaseExit;
  const auto* p = reinterpret_cast<const uint8_t*>(&code);
  for (int r = 1; r < session.size(); ++r) {
    try {
      net.send(r, kReleaseTag, Bytes(p, p + sizeof code));
    } catch (const MpiError&) {
    }
  }
  net.flush(clean ? 30.0 : 2.0);
  if (clean) return;  // every rank finalizes
  // Under --enable-recovery, MPI_Finalize would wait for the lost ranks, which may never
  // come; mpirun returns once every process has ended: at once if the lost ones died, never
  // if one hangs (stopped, or cut off). A watchdog ends the job after a grace period then.
  session.comm().skipFinalize = true;
  std::fflush(stdout);
  const double grace = 2 * faults.workerTimeoutSeconds + 5;
  const bool watched = endLauncherIfStillRunningAfter(grace);
  std::fprintf(stderr,
               "prt: %zu worker rank(s) were lost; the image and report are complete. mpirun "
               "returns once the lost processes have ended%s\n",
               faults.lostWorkers.size() + faults.missingSummaries.size(),
               watched ? "; if one still hangs, the job is ended in a few seconds" : "");
}

int runMpiWorker(MpiSession& session, const ParallelOptions& options) {
  PRT_CHECK(!session.isMaster());
  const int id = endpointOf(session.rank());
  try {
    MpiLink link(session.comm().comm);
    WorkerFaultActions faults;  // set only for this rank's injected fault, if any
    ParallelOptions mine = options;
    // A slowdown list of the wrong length is the master's to report: it releases us.
    if (mine.slowdowns.size() != static_cast<size_t>(session.workerCount())) mine.slowdowns.clear();
    for (const FaultInjection& f : mine.faults) {
      if (f.worker == id) {
        faults.crash = [f, id] { failAsInjected(f, id); };
        faults.hang = faults.crash;
      }
    }
    const WorkerExit exit = runWorkerSide(link, id, mine, faults);
    if (exit == WorkerExit::MasterLost) {
      if (const auto code = link.release()) {
        // Released before the run started (bad input on the master) or after it.
        if (*code > 0) return *code;
        if (*code == kReleaseExit) session.comm().skipFinalize = true;
        return 0;
      }
      std::fprintf(stderr, "prt: %s: the master stopped answering; exiting\n",
                   rankName(id).c_str());
      session.comm().skipFinalize = true;
      return 1;
    }
    const auto code = link.awaitRelease(link.now() + options.workerTimeoutSeconds + 30);
    if (!code || *code != kReleaseFinalize) session.comm().skipFinalize = true;
    return 0;
  } catch (const MpiError& e) {
    session.abort(rankName(id) + ": MPI failed: " + e.what() + "; aborting");
  } catch (const std::exception& e) {
    session.abort(rankName(id) + ": " + e.what() + "; aborting");
  }
}

}  // namespace prt
