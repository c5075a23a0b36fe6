// prt join FILE: adds workers to a running render that was started with --accept-workers FILE
// (see docs/running.md, "Machines that join a running render"): this process over TCP, from
// any machine and under any launcher; or, under mpirun, this job's ranks through MPI's
// rendezvous (an ompi-server both mpiruns share).

#include <cstdlib>

#include "cli/commands.h"
#include "cli/flag_checks.h"
#include "cli/parallel_render.h"
#include "core/input_error.h"
#include "core/cpu_allocation.h"
#include "core/speed_schedule.h"
#include "net/tcp_join.h"
#ifdef PRT_HAVE_MPI
#include "mpi/mpi_driver.h"
#endif

namespace prt::cli {
namespace {

struct JoinOptions {
  std::string portFile;
  int threads = 0;
  double slowdown = 1;
  std::string slowdownAt;  // T:K,...
  double connectTimeoutSeconds = 30;
  double startupTimeoutSeconds = 120;
  std::string via = "auto";  // tcp, mpi, or auto: mpi under mpirun, tcp otherwise
};

// How many joiners a launcher started on this machine at once (they share its CPUs).
int joinersOnThisMachine() {
  for (const char* name : {"OMPI_COMM_WORLD_LOCAL_SIZE", "SLURM_NTASKS_PER_NODE"}) {
    if (const char* v = std::getenv(name)) {
      const int n = std::atoi(v);
      if (n >= 1 && n <= 4096) return n;
    }
  }
  return 1;
}

// --slowdown-at T:K,... of a joiner: read item by item as worker 0's W:T:K, an error given in
// the T:K the user typed.
std::vector<SpeedChange> parseJoinerSlowdownAt(const std::string& text) {
  std::vector<SpeedChange> out;
  for (size_t start = 0;;) {
    const size_t comma = text.find(',', start);
    const std::string item = text.substr(start, comma - start);
    try {
      if (item.find(':') == std::string::npos || item.find(':') != item.rfind(':')) {
        throw InputError("not two numbers");
      }
      out.push_back(parseSpeedChanges("0:" + item, "--slowdown-at", 1, 1).front());
    } catch (const InputError&) {
      throw InputError("--slowdown-at: '" + item +
                       "' is not T:K with a time T >= 0 seconds and a slowdown K >= 1 "
                       "(expected T:K,T:K,...)");
    }
    if (comma == std::string::npos) break;
    start = comma + 1;
  }
  return out;
}

int runJoin(const JoinOptions& o) {
  // The flags first: a mistake is reported as such, under mpirun or not.
  if (!(o.slowdown >= 1 && o.slowdown <= 1000)) {
    throw InputError("--slowdown must be in [1, 1000]");
  }
  if (!(o.connectTimeoutSeconds >= 1 && o.connectTimeoutSeconds <= 86400)) {
    throw InputError("--connect-timeout must be between 1 and 86400 seconds");
  }
  const std::vector<SpeedChange> slowdownChanges =
      o.slowdownAt.empty() ? std::vector<SpeedChange>{} : parseJoinerSlowdownAt(o.slowdownAt);
  const bool viaMpi = o.via == "mpi" || (o.via == "auto" && launchedByMpirun());
  if (!viaMpi) {
    TcpJoinRequest request;
    request.portFile = o.portFile;
    request.threads = o.threads;
    request.sharingProcesses = joinersOnThisMachine();
    request.slowdown = o.slowdown;
    request.slowdownChanges = slowdownChanges;
    request.connectTimeoutSeconds = o.connectTimeoutSeconds;
    return runTcpJoiner(request);
  }
  if (!launchedByMpirun()) {
    throw InputError("prt join --via mpi runs under mpirun: mpirun -np K --ompi-server file:URI "
                     "prt join --via mpi " + o.portFile);
  }
#ifdef PRT_HAVE_MPI
  JoinRequest request;
  request.portFile = o.portFile;
  request.threads = o.threads;
  request.slowdown = o.slowdown;
  request.slowdownChanges = slowdownChanges;
  request.connectTimeoutSeconds = o.connectTimeoutSeconds;
  MpiSession session(true, o.startupTimeoutSeconds);  // the connect watchdog may end the job from its own thread
  return session.exitCode(runJoinedWorkers(session, request));
#else
  (void)slowdownChanges;
  throw InputError("this prt was built without MPI; rebuild with Open MPI installed");
#endif
}

}  // namespace

Action addJoinCommand(CLI::App& app) {
  auto o = std::make_shared<JoinOptions>();
  CLI::App* cmd = app.add_subcommand(
      "join",
      "Add workers to a running render started with --accept-workers FILE: this process, over "
      "TCP (from any machine; under srun, one worker per task), or under mpirun this job's "
      "ranks (both mpiruns with the same --ompi-server)");
  cmd->add_option("file", o->portFile, "The file the render's master wrote its port name to")
      ->required();
  cmd->add_option("--threads", o->threads,
                  "Rendering threads of each joining worker (0: every CPU its affinity allows)")
      ->check(CLI::Range(0, 1024))
      ->capture_default_str();
  cmd->add_option("--slowdown", o->slowdown,
                  "Each joining worker runs this many times slower (emulating a slower machine)")
      ->capture_default_str();
  cmd->add_option("--slowdown-at", o->slowdownAt,
                  "T:K,...: from T seconds after it starts, run K times slower instead");
  cmd->add_option("--connect-timeout", o->connectTimeoutSeconds,
                  "Seconds to wait for the render's master to answer before giving up")
      ->check(finiteIn(1, 86400))
      ->capture_default_str();
  cmd->add_option("--via", o->via,
                  "tcp: join over TCP, from anywhere; mpi: through MPI (under mpirun, with the "
                  "render's --ompi-server); auto: mpi under mpirun, tcp otherwise")
      ->check(CLI::IsMember({"auto", "tcp", "mpi"}))
      ->capture_default_str();
  cmd->add_option("--startup-timeout", o->startupTimeoutSeconds,
                  "Seconds MPI start-up may take before this job ends (exit 1)")
      ->check(finiteIn(1, 86400))
      ->capture_default_str();
  return [o] { return runJoin(*o); };
}

}  // namespace prt::cli
