#include "mpi/mpi_driver.h"

#include <fcntl.h>
#include <poll.h>
#include <sys/syscall.h>
#include <signal.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <condition_variable>
#include <mutex>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <string>
#include <thread>

#include "core/thread_start.h"
#include "core/check.h"
#include "core/cpu_allocation.h"
#include "core/exit_status.h"
#include "core/input_error.h"
#include "core/input_file.h"
#include "core/byte_codec.h"
#include "core/machine.h"
#include "farm/build_info.h"
#include "net/invitation.h"
#include "net/join_welcome.h"
#include "net/tcp_door.h"
#include "mpi/mpi_acceptor.h"
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
  MpiComm& comm = session.comm();
  comm.link = std::make_unique<MpiLink>(comm.comm);
  if (!options.acceptWorkersPath.empty()) {
    if (!comm.threadMultiple) {
      throw InputError("--accept-workers needs MPI_THREAD_MULTIPLE, which this MPI does not "
                       "provide");
    }
    // Two doors, one invitation: an MPI port for `mpirun prt join` (through an ompi-server),
    // and a TCP one for `prt join` anywhere else, across hosts included.
    const Secret secret = newSecret();
    try {
      const DoorAddress where = parseDoorAddress(options.acceptAddress);
      comm.door = std::make_unique<TcpDoor>(secret, where.address, where.port);
    } catch (const InputError&) {
      throw;
    } catch (const std::exception& e) {
      throw InputError(std::string("--accept-workers: ") + e.what());
    }
    try {
      comm.acceptor = std::make_unique<MpiAcceptor>(options.acceptWorkersPath, secret,
                                                    comm.door->addresses());
    } catch (const MpiError& e) {
      throw InputError(std::string("--accept-workers: ") + e.what() +
                       " (run both mpiruns with the same --ompi-server; see docs/running.md)");
    }
    MpiAcceptor* acceptor = comm.acceptor.get();
    comm.link->setAcceptSource([acceptor] { return acceptor->take(); }, encodeWelcome(options));
    comm.link->setTcpDoor(*comm.door, encodeWelcome(options));
  }
  comm.runStarted = true;
  RunRequest withBlocklist = request;
  if (comm.acceptor) {
    // A machine whose worker was rejected may not join again in this run.
    MpiAcceptor* acceptor = comm.acceptor.get();
    TcpDoor* door = comm.door.get();
    withBlocklist.rejectedHost = [acceptor, door](const std::string& host) {
      acceptor->block(host);
      door->block(host);
    };
  }
  ParallelRun run = runMasterSide(*comm.link, withBlocklist, "mpi");
  if (comm.acceptor) {
    run.report.info.faults.refusedJoiners = comm.acceptor->refused();
    for (const std::string& why : comm.door->refused()) {
      run.report.info.faults.refusedJoiners.push_back(why);
    }
  }
  comm.link->flush(options.workerTimeoutSeconds);
  return run;
}

void finishMpiMaster(MpiSession& session, const ParallelRun& run) {
  const FaultInfo& faults = run.report.info.faults;
  MpiComm& comm = session.comm();
  MpiLink& link = *comm.link;
  if (comm.acceptor) comm.acceptor->beginStop();  // no more joiners: the port file goes
  if (comm.door) comm.door->stopAdmitting();
  // Whether every worker of endpoints [first, first + count) is still there at the end: each
  // job (this one, and every joining one) ends on its own terms.
  auto allThere = [&](int first, int count) {
    for (const LostWorkerInfo& l : faults.lostWorkers) {
      if (l.worker >= first && l.worker < first + count) return false;
    }
    for (int w : faults.missingSummaries) {
      if (w >= first && w < first + count) return false;
    }
    return true;
  };
  const bool clean = allThere(0, session.workerCount());
  const size_t losses = faults.lostWorkers.size() + faults.missingSummaries.size();
  // Every joining job first, on its own terms: all its workers there, it finalizes and is
  // disconnected below; one that lost a worker is told to exit.
  const std::vector<MpiLink::JoinedJob> joined = link.joinedJobs();
  std::vector<bool> joinedClean;
  for (const MpiLink::JoinedJob& j : joined) {
    joinedClean.push_back(allThere(j.first, j.count));
    for (int w = j.first; w < j.first + j.count; ++w) {
      link.sendTagged(w, kReleaseTag, releaseMessage(joinedClean.back() ? kReleaseFinalize : kReleaseExit));
    }
  }
  // Each worker that joined over TCP is released on its own (it is its own job).
  for (int w : link.tcpJoiners()) {
    link.sendTagged(w, kReleaseTag, releaseMessage(allThere(w, 1) ? kReleaseFinalize : kReleaseExit));
  }
  // A joining job whose workers are all there disconnects; one that lost a worker is left:
  // disconnecting could wait for the lost one.
  auto disconnectJoined = [&] {
    for (size_t i = 0; i < joined.size(); ++i) {
      MPI_Comm inter = joined[i].comm;
      if (joinedClean[i]) MPI_Comm_disconnect(&inter);
    }
  };
  if (!clean && !session.recoveryEnabled()) {
    // Without --enable-recovery the job is still alive only because the lost ranks hang, and a
    // rank that exits without MPI_Finalize would end it in error: end them all, and the job,
    // with MPI_Abort's code 0. The live workers wait for it (see runMpiWorker); the joining
    // jobs, released above, end on their own.
    session.comm().skipFinalize = true;
    if (!joined.empty()) {
      link.flush(2.0);
      disconnectJoined();
    }
    std::fprintf(stderr,
                 "prt: %zu worker(s) were lost; the image and report are complete. Ending "
                 "the job with MPI_Abort(0) so that mpirun does not wait for them\n",
                 losses);
    std::fflush(stdout);
    std::fflush(stderr);
    recordExitStatus(0);
    MPI_Abort(session.comm().comm, 0);
    std::_Exit(0);
  }
  // The first live worker of this job also wakes the port listener on its way out.
  int waker = -1;
  if (comm.acceptor) {
    for (int w = 0; w < session.workerCount() && waker < 0; ++w) {
      if (!run.report.workers[static_cast<size_t>(w)].lost) waker = w;
    }
  }
  for (int w = 0; w < session.workerCount(); ++w) {
    link.sendTagged(w, kReleaseTag,
                    releaseMessage(clean ? kReleaseFinalize : kReleaseExit,
                                   w == waker ? comm.acceptor->portName() : std::string()));
  }
  link.flush(losses == 0 ? 30.0 : 2.0);
  if (comm.acceptor) comm.acceptor->finishStop(waker >= 0 ? 10.0 : 0.0);
  disconnectJoined();
  if (clean) {
    if (losses > 0) {
      std::fprintf(stderr,
                   "prt: %zu joining worker(s) were lost; the image and report are complete\n",
                   losses);
    }
    return;  // every rank of this job finalizes
  }
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
    if (mine.threads <= 0) {
      // The workers on this node share its CPUs; the master, if here, mostly waits.
      mine.threads = allocatedCpuCount(session.ranksOnThisNode() -
                                       (session.rankZeroOnThisNode() ? 1 : 0));
    }
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
    if (!link.wakePort().empty()) wakeAcceptor(link.wakePort());
    if (!code || *code != kReleaseFinalize) session.comm().skipFinalize = true;
    return 0;
  } catch (const MpiError& e) {
    session.abort(rankName(id) + ": MPI failed: " + e.what() + "; aborting");
  } catch (const std::exception& e) {
    session.abort(rankName(id) + ": " + e.what() + "; aborting");
  }
}

namespace {

// Rank 0 of the joining job reads the port file; every rank gets the port name (empty: none)
// and the invitation's secret. `problem` says why rank 0 could not read the file (a FIFO, a
// device, too large).
PortFile sharedPortFile(MpiSession& session, const std::string& file, std::string& problem) {
  PortFile read;
  std::error_code missing;
  if (session.rank() == 0 && std::filesystem::exists(file, missing)) {
    try {
      read = parsePortFile(readInputFile(file, "port file", 1 << 16));
      if (read.port.size() >= MPI_MAX_PORT_NAME) read.port.resize(MPI_MAX_PORT_NAME - 1);
    } catch (const InputError& e) {
      problem = e.what();
    }
  }
  int length = static_cast<int>(read.port.size());
  check(MPI_Bcast(&length, 1, MPI_INT, 0, session.comm().comm), "MPI_Bcast", -1);
  read.port.resize(static_cast<size_t>(length));
  if (length > 0) {
    check(MPI_Bcast(read.port.data(), length, MPI_CHAR, 0, session.comm().comm), "MPI_Bcast", -1);
  }
  int hasSecret = read.secret.has_value() ? 1 : 0;
  check(MPI_Bcast(&hasSecret, 1, MPI_INT, 0, session.comm().comm), "MPI_Bcast", -1);
  if (hasSecret) {
    if (!read.secret) read.secret = Secret{};
    check(MPI_Bcast(read.secret->data(), 32, MPI_BYTE, 0, session.comm().comm), "MPI_Bcast", -1);
  } else {
    read.secret.reset();
  }
  return read;
}

// A joining rank answers the master's challenge (without a secret it still answers, and is
// refused). False when no challenge came by `deadline` (MPI_Wtime).
bool proveInvitation(MPI_Comm inter, const std::optional<Secret>& secret, double deadline) {
  for (;;) {
    int found = 0;
    MPI_Status status;
    check(MPI_Iprobe(0, kChallengeTag, inter, &found, &status), "MPI_Iprobe", 0);
    if (found) break;
    if (MPI_Wtime() > deadline) return false;
    pollPause();
  }
  Challenge challenge{};
  check(MPI_Recv(challenge.data(), 32, MPI_BYTE, 0, kChallengeTag, inter, MPI_STATUS_IGNORE),
        "MPI_Recv", 0);
  const std::vector<uint8_t> proof = proofFor(secret.value_or(Secret{}), challenge, buildDescription(), hostName());
  check(MPI_Send(proof.data(), static_cast<int>(proof.size()), MPI_BYTE, 0, kProofTag, inter),
        "MPI_Send", 0);
  return true;
}

}  // namespace

int runJoinedWorkers(MpiSession& session, const JoinRequest& request) {
  if (!session.threadMultiple()) {
    session.abort("prt join needs MPI_THREAD_MULTIPLE, which this MPI does not provide", 1);
  }
  std::string problem;
  const PortFile portFile = sharedPortFile(session, request.portFile, problem);
  const std::string& port = portFile.port;
  if (port.empty()) {
    if (session.rank() == 0 && !problem.empty()) {
      std::fprintf(stderr, "prt: error: %s\n", problem.c_str());
    } else if (session.rank() == 0) {
      std::fprintf(stderr,
                   "prt: error: '%s' holds no port name: start the render with "
                   "--accept-workers %s under mpirun first (and keep it running)\n",
                   request.portFile.c_str(), request.portFile.c_str());
    }
    return 2;
  }
  if (!portFile.secret && session.rank() == 0) {
    std::fprintf(stderr,
                 "prt: warning: '%s' holds no invitation secret: the render will refuse this "
                 "job (use the port file the render wrote, as it wrote it)\n",
                 request.portFile.c_str());
  }
  // A port nobody answers (the render ended) makes MPI_Comm_connect wait for ever: a
  // watchdog ends the job if the connection has not come by the deadline.
  std::mutex mutex;
  std::condition_variable done;
  bool connected = false;
  std::thread watchdog = startThread([&] {
    std::unique_lock<std::mutex> lock(mutex);
    if (done.wait_for(lock, std::chrono::duration<double>(request.connectTimeoutSeconds),
                      [&] { return connected; })) {
      return;
    }
    session.abort("could not reach the render's master at the port in '" + request.portFile +
                      "' within " + std::to_string(static_cast<int>(request.connectTimeoutSeconds)) +
                      " s: has that render ended? Both mpiruns need the same --ompi-server",
                  1);
  });
  MPI_Comm inter = MPI_COMM_NULL;
  std::vector<char> name(port.begin(), port.end());
  name.push_back('\0');
  const int code = MPI_Comm_connect(name.data(), MPI_INFO_NULL, 0, session.comm().comm, &inter);
  {
    std::lock_guard<std::mutex> lock(mutex);
    connected = true;
  }
  done.notify_all();
  watchdog.join();
  if (code != MPI_SUCCESS) {
    session.abort("could not join the render at the port in '" + request.portFile +
                      "' (MPI_Comm_connect failed): both mpiruns need the same --ompi-server",
                  1);
  }
  try {
    check(MPI_Comm_set_errhandler(inter, MPI_ERRORS_RETURN), "MPI_Comm_set_errhandler", -1);
    // The invitation, then the welcome: this worker's endpoint and the run's options.
    const double deadline = MPI_Wtime() + request.connectTimeoutSeconds;
    if (!proveInvitation(inter, portFile.secret, deadline)) {
      session.abort("joined the render but its master asked for no invitation: is it an "
                    "older prt?", 1);
    }
    ParallelOptions options;
    int id = -1;
    {
      MpiTransport net(inter);
      while (id < 0) {
        std::optional<Packet> p = net.poll();
        if (p && p->tag == kRefusedTag) {
          const std::string why(p->bytes.begin(), p->bytes.end());
          if (session.rank() == 0) {
            std::fprintf(stderr, "prt: error: the render refused this job: %s\n", why.c_str());
          }
          session.comm().skipFinalize = true;
          return 1;
        }
        if (p && p->tag == kWelcomeTag) {
          id = decodeWelcome(p->bytes, options);
        } else if (MPI_Wtime() > deadline) {
          session.abort("joined the render but its master sent no welcome", 1);
        } else if (!p) {
          pollPause();
        }
      }
    }
    // Every joining process of this job renders: they share the node's allocation.
    options.threads =
        request.threads > 0 ? request.threads : allocatedCpuCount(session.ranksOnThisNode());
    options.slowdowns.assign(static_cast<size_t>(id) + 1, 1.0);
    options.slowdowns.back() = request.slowdown;
    for (SpeedChange c : request.slowdownChanges) {
      c.worker = id;
      options.slowdownChanges.push_back(c);
    }
    MpiLink link(inter, id);
    const WorkerExit exit = runWorkerSide(link, id, options, WorkerFaultActions{});
    if (exit == WorkerExit::MasterLost && !link.release()) {
      std::fprintf(stderr, "prt: joined worker %d: the master stopped answering; exiting\n", id);
      session.comm().skipFinalize = true;
      return 1;
    }
    const auto release = link.awaitRelease(link.now() + options.workerTimeoutSeconds + 30);
    if (!release || *release != kReleaseFinalize) {
      // A worker of this job was lost: if it only hangs (stopped, cut off), this job's mpirun
      // would wait for it for ever. As the master does for its own job, each live rank (any
      // may be the lost one) leaves a watchdog that ends its launcher after a grace period if
      // it is still running then; a launcher that returned in time is left alone.
      session.comm().skipFinalize = true;
      endLauncherIfStillRunningAfter(2 * options.workerTimeoutSeconds + 5);
      return 0;
    }
    MPI_Comm_disconnect(&inter);
    return 0;
  } catch (const std::exception& e) {
    session.abort(std::string("joined worker: ") + e.what() + "; aborting");
  }
}

}  // namespace prt
