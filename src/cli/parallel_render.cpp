#include "cli/parallel_render.h"

#include <cstdio>
#include <cstdlib>
#include <tuple>

#include "core/input_error.h"
#include "drive/local_driver.h"
#include "drive/speed_probe.h"
#include "image/atomic_file.h"
#include "image/image_io.h"
#include "metrics/chrome_trace.h"
#include "trace/renderer.h"
#ifdef PRT_HAVE_MPI
#include "mpi/mpi_driver.h"
#endif

namespace prt::cli {
namespace {

std::vector<FaultInjection> parseFaults(const std::vector<std::string>& specs) {
  std::vector<FaultInjection> faults;
  for (const std::string& spec : specs) {
    FaultInjection f;
    char kind[16] = {};
    unsigned long long pixels = 0;
    if (std::sscanf(spec.c_str(), "%d:%llu:%15s", &f.worker, &pixels, kind) != 3 ||
        (std::string(kind) != "crash" && std::string(kind) != "hang")) {
      throw InputError("--inject-fault '" + spec + "': expected WORKER:PIXELS:crash|hang");
    }
    f.afterPixels = pixels;
    f.kind = std::string(kind) == "crash" ? FaultInjection::Kind::Crash
                                          : FaultInjection::Kind::Hang;
    faults.push_back(f);
  }
  return faults;
}

// Serial time for speed-up: given, or measured here by rendering serially on one thread.
std::optional<double> serialSeconds(const RenderOptions& o, const Scene& scene,
                                    const RenderSettings& settings) {
  if (o.serialSeconds) return o.serialSeconds;
  if (!o.measureSerial) return std::nullopt;
  if (!o.quiet) std::fprintf(stderr, "measuring the serial time (one thread)...\n");
  const World world(scene);
  RenderStats stats;
  renderImage(Renderer(world, settings), 1, &stats);
  return stats.seconds;
}

}  // namespace

void addParallelOptions(CLI::App& cmd, RenderOptions& o) {
  const std::string parallel = "Parallel";
  cmd.add_option("--workers", o.workers,
                 "Render in parallel with N worker threads, each emulating one machine "
                 "(local driver); not under mpirun")
      ->check(CLI::Range(1, 4096))
      ->group(parallel);
  addStrategyFlags(cmd, o.strategyFlags, parallel);
  cmd.add_option("--slowdown", o.slowdowns,
                 "Comma-separated factors k_i >= 1, one per worker: worker i runs k_i times "
                 "slower (faithful while the sum of 1/k_i fits the free cores)")
      ->delimiter(',')
      ->group(parallel);
  cmd.add_option("--slowdown-at", o.slowdownAt,
                 "Speeds that change mid-render: W:T:K,... makes worker W run K times slower "
                 "(K >= 1, instead of its --slowdown) from T seconds after its start")
      ->group(parallel);
  cmd.add_option("--speed-index", o.speedIndex,
                 "Speed index the workers measure: hanoi (the paper's Towers of Hanoi run), "
                 "probe (rendering a fixed sample of the image's pixels), none (start at once; "
                 "MASU and ASU then come from measured throughput), slowdown (an oracle: each "
                 "worker reports its --slowdown factor, its true emulated speed) or auto (none "
                 "for the adaptive strategies, hanoi for the rest)")
      ->capture_default_str()
      ->group(parallel);
  cmd.add_option("--batch", o.batchPixels, "Pixels a worker renders between returning results")
      ->capture_default_str()
      ->group(parallel);
  cmd.add_option("--worker-timeout", o.workerTimeoutSeconds,
                 "Seconds of silence after which a worker that owes an answer is declared lost")
      ->capture_default_str()
      ->group(parallel);
  cmd.add_option("--serial-seconds", o.serialSeconds,
                 "The serial render time, for speed-up and ASU")
      ->check(CLI::PositiveNumber)
      ->group(parallel);
  cmd.add_flag("--measure-serial", o.measureSerial,
               "Render serially on one thread first to measure the serial time")
      ->group(parallel);
  cmd.add_option("--report", o.reportPath, "Write the load-balancing report as JSON")
      ->group(parallel);
  cmd.add_option("--trace", o.tracePath,
                 "Write a Chrome trace-event timeline (open in Perfetto)")
      ->group(parallel);
  cmd.add_option("--ownership", o.ownershipPath,
                 "Write the image coloured by the worker that rendered each pixel")
      ->group(parallel);
  cmd.add_option("--inject-fault", o.faults,
                 "Testing: WORKER:PIXELS:crash|hang makes worker WORKER (rank WORKER+1 under "
                 "MPI) fail after rendering that many pixels")
      ->group(parallel);
}

bool launchedByMpirun() {
  for (const char* v : {"OMPI_COMM_WORLD_SIZE", "PMI_SIZE", "PMIX_RANK"}) {
    if (std::getenv(v) != nullptr) return true;
  }
  return false;
}

ParallelOptions toParallelOptions(const RenderOptions& o, int workers) {
  ParallelOptions p;
  p.workers = workers;
  p.strategy = o.strategyFlags.name();
  p.strategyOptions = strategyOptionsFrom(o.strategyFlags);
  p.slowdowns = o.slowdowns;
  if (!o.slowdownAt.empty()) {
    p.slowdownChanges = parseSpeedChanges(o.slowdownAt, "--slowdown-at", workers, 1);
  }
  const bool automatic = o.speedIndex == "auto";
  p.speedIndexKind =
      automatic ? (runsSpeedIndexByDefault(p.strategy) ? SpeedIndexKind::Hanoi : SpeedIndexKind::None)
                : parseSpeedIndexKind(o.speedIndex);
  p.batchPixels = o.batchPixels;
  p.workerTimeoutSeconds = o.workerTimeoutSeconds;
  p.faults = parseFaults(o.faults);
  return p;
}

int finishParallelRun(const RenderOptions& o, const Scene& scene, const ParallelRun& run) {
  writeImage(run.image, scene.image.output);
  if (!o.reportPath.empty()) writeFileAtomically(o.reportPath, run.report.toJson());
  if (!o.tracePath.empty()) {
    writeFileAtomically(o.tracePath,
                        chromeTraceJson(run.events, static_cast<int>(run.report.workers.size()),
                                        run.report.elapsedSeconds));
  }
  if (!o.ownershipPath.empty()) writeImage(ownershipImage(run.image, run.owner), o.ownershipPath);
  if (!o.quiet) {
    std::printf("%s: %dx%d, %d spp, DRT %d\n%s", scene.image.output.c_str(), scene.image.width,
                scene.image.height, run.report.info.samplesPerPixel, run.report.info.drtRate,
                run.report.toTable().c_str());
  }
  return 0;
}

int renderParallelLocal(const RenderOptions& o, const Scene& scene, const RenderSettings& s) {
  LocalRunRequest request;
  request.scene = scene;
  request.settings = s;
  request.options = toParallelOptions(o, o.workers.value_or(4));
  validateParallelOptions(request.options,
                          static_cast<uint64_t>(scene.image.width) * scene.image.height);
  request.serialSeconds = serialSeconds(o, scene, s);
  request.masterSpeedIndexSeconds =
      serialSpeedIndexSeconds(request.options.speedIndexKind, scene, s);
  return finishParallelRun(o, scene, renderLocal(request));
}

// --- MPI hook (the driver is in src/mpi; this is only the command-line glue) ---------------
int renderParallelMpi(const RenderOptions& o, const SceneLoader& loadScene) {
#ifdef PRT_HAVE_MPI
  MpiSession session;
  if (!session.isMaster()) {
    // Every rank parses the same command line. Options that are bad here are bad on the
    // master too, which reports them once and releases the workers; until then run with
    // defaults.
    ParallelOptions options;
    try {
      options = toParallelOptions(o, session.workerCount());
    } catch (const InputError&) {
    }
    return runMpiWorker(session, options);
  }
  try {
    if (session.size() < 2) {
      throw InputError(
          "prt render under MPI needs at least 2 ranks: mpirun -np N+1 prt render "
          "... (rank 0 is the master, ranks 1..N the workers)");
    }
    MpiRunRequest request;
    std::tie(request.scene, request.settings) = loadScene();
    request.options = toParallelOptions(o, session.workerCount());
    if (!o.slowdowns.empty() && o.slowdowns.size() != static_cast<size_t>(session.workerCount())) {
      throw InputError("--slowdown lists " + std::to_string(o.slowdowns.size()) +
                       " values but mpirun started " + std::to_string(session.workerCount()) +
                       " workers (ranks 1.." + std::to_string(session.workerCount()) +
                       "; rank 0 is the master); give one per worker");
    }
    validateParallelOptions(request.options, static_cast<uint64_t>(request.scene.image.width) *
                                                 request.scene.image.height);
    request.serialSeconds = serialSeconds(o, request.scene, request.settings);
    request.masterSpeedIndexSeconds = serialSpeedIndexSeconds(
        request.options.speedIndexKind, request.scene, request.settings);
    // From here a lost worker or an MPI failure ends the whole job with a message.
    const ParallelRun run = renderMpiMaster(session, request);
    return finishParallelRun(o, request.scene, run);
  } catch (const InputError& e) {
    // Report before releasing: a released worker's exit can make mpirun end rank 0 at once.
    std::fprintf(stderr, "%s\n", e.format().c_str());
    std::fflush(stderr);
    session.releaseWorkers(2);
    return 2;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "prt: error: %s\n", e.what());
    std::fflush(stderr);
    session.releaseWorkers(1);
    return 1;
  }
#else
  (void)o;
  (void)loadScene;
  throw InputError("this prt was built without MPI; rebuild with Open MPI installed");
#endif
}
// --- end MPI hook --------------------------------------------------------------------------

}  // namespace prt::cli
