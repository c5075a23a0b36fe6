#include "cli/parallel_render.h"

#include "net/local_door.h"

#include "cli/flag_checks.h"
#include "cli/live_view.h"
#include "cli/run_page_output.h"
#include "cli/video_output.h"

#include <cstdio>
#include <cstdlib>
#include <limits>
#include <optional>
#include <string_view>
#include <tuple>

#include "cli/checkpointing.h"
#include "core/exit_status.h"
#include "core/input_error.h"
#include "farm/frame_renderer.h"
#include "farm/local_driver.h"
#include "farm/speed_probe.h"
#include "image/atomic_file.h"
#include "image/image_io.h"
#include "metrics/chrome_trace.h"
#include "trace/renderer.h"
#ifdef PRT_HAVE_MPI
#include "mpi/mpi_driver.h"
#endif

namespace prt::cli {
namespace {

// Serial time for speed-up: given, or measured here by rendering serially on one thread.
std::optional<double> serialSeconds(const RenderOptions& o, const Scene& scene,
                                    const RenderSettings& settings) {
  if (o.serialSeconds) return o.serialSeconds;
  if (!o.measureSerial) return std::nullopt;
  if (!o.quiet) std::fprintf(stderr, "measuring the serial time (one thread)...\n");
  // Every frame of a sequence, each with its preparation, as a serial render pays for them.
  FrameRenderer frames(scene, settings, framesOf(o));
  double seconds = 0;
  for (uint64_t i = 0; i < frames.frames().count(); ++i) {
    const double before = frames.buildSeconds();
    RenderStats stats;
    renderImage(frames.frame(i), 1, &stats);
    seconds += stats.seconds + (frames.buildSeconds() - before);
  }
  return seconds;
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
  cmd.add_option("--accept-workers", o.acceptWorkersPath,
                 "Let machines join the running render: write to FILE (readable by you only) "
                 "the master's TCP addresses and a secret, so that `prt join FILE` on another "
                 "machine adds it as a worker (over TCP, no MPI needed); under mpirun FILE also "
                 "names an MPI port for `mpirun -np K prt join FILE` (both mpiruns with the same "
                 "--ompi-server; see docs/running.md)")
      ->group(parallel);
  cmd.add_option("--accept-address", o.acceptAddress,
                 "[ADDRESS][:PORT] the TCP door of --accept-workers listens on: an IPv4 address "
                 "of this machine and a port a firewall lets through (default: every interface, "
                 "a free port)")
      ->group(parallel);
  cmd.add_option("--speed-index", o.speedIndex,
                 "Speed index the workers measure: hanoi (the paper's Towers of Hanoi run), "
                 "probe (rendering a fixed sample of the image's pixels), none (start at once; "
                 "MASU and ASU then come from measured throughput), slowdown (an oracle: each "
                 "worker reports its --slowdown factor, its true emulated speed) or auto (none "
                 "for the adaptive strategies, hanoi for the rest)")
      ->capture_default_str()
      ->group(parallel);
  cmd.add_option("--batch-seconds", o.batchSeconds,
                 "Batches grow past --batch pixels to what a worker renders in S seconds at its "
                 "last batch's rate (0: every batch --batch pixels). Default: 0.03 s, longer "
                 "past about 1,200 workers (25 us per worker) so that one master is never "
                 "more than a fifth busy with results")
      ->check(finiteIn(0, 60))
      ->default_str("auto")
      ->group(parallel);
  cmd.add_option("--startup-timeout", o.startupTimeoutSeconds,
                 "Under mpirun: seconds MPI start-up may take; a rank killed while the job "
                 "starts would leave the others waiting in it for ever, so each ends instead "
                 "(exit 1)")
      ->check(finiteIn(1, 86400))
      ->capture_default_str()
      ->group(parallel);
  cmd.add_option("--serial-seconds", o.serialSeconds,
                 "The serial render time, for speed-up and ASU")
      ->check(positiveUpTo(1e9, "seconds"))
      ->group(parallel);
  cmd.add_flag("--measure-serial", o.measureSerial,
               "Render serially on one thread first to measure the serial time")
      ->group(parallel);
  const std::string checkpoints = "Checkpoints";
  cmd.add_option("--checkpoint", o.checkpointPath,
                 "Keep the finished pixels in FILE (written atomically every --checkpoint-every "
                 "seconds, when a worker is lost and when the run stops), so that a killed render "
                 "resumes with --resume; removed once the image is written")
      ->group(checkpoints);
  cmd.add_flag("--no-checkpoint", o.noCheckpoint,
               "Keep no automatic checkpoint: without --checkpoint, a render expected to take "
               "more than 30 s keeps its finished pixels in OUTPUT.ckpt (removed once the "
               "image is written), so that Ctrl-C, a kill or a lost master loses nothing")
      ->group(checkpoints);
  cmd.add_option("--checkpoint-every", o.checkpointEverySeconds,
                 "Seconds between checkpoints")
      ->check(finiteIn(0.01, 86400))
      ->capture_default_str()
      ->group(checkpoints);
  cmd.add_flag("--resume", o.resume,
               "Start from the checkpoint (--checkpoint FILE, or the automatic OUTPUT.ckpt): "
               "render only the pixels it lacks (the image is the same as an uninterrupted "
               "render's)")
      ->group(checkpoints);
  cmd.add_option("--report", o.reportPath, "Write the load-balancing report as JSON")
      ->check(fileName())
      ->group(parallel);
  cmd.add_option("--trace", o.tracePath,
                 "Write a Chrome trace-event timeline (open in Perfetto)")
      ->check(fileName())
      ->group(parallel);
  cmd.add_option("--html", o.htmlPath,
                 "Write the run's page: one self-contained HTML file with the image, the "
                 "ownership map, the timeline and the measures")
      ->group(parallel);
  cmd.add_option("--ownership", o.ownershipPath,
                 "Write the image coloured by the worker that rendered each pixel")
      ->check(fileName())
      ->group(parallel);
  cmd.add_option("--verify", o.verifyPercent,
                 "Spot checks: PERCENT of each worker's pixels (4 times as many for a new "
                 "worker, half once it passed 32 checks) are rendered again by another worker, "
                 "or by the master, and compared bit for bit; a worker that fails one is "
                 "rejected and its pixels rendered again. A sample: the report's verify_guarantee "
                 "says the odds of catching k wrong pixels; 100: every pixel (exact); 0: no "
                 "checks")
      ->check(finiteIn(0, 100))
      ->capture_default_str()
      ->group(parallel);
  cmd.add_option("--verify-seed", o.verifySeed,
                 "Which pixels the spot checks sample: the report's verify_seed repeats a run's "
                 "sample (default: drawn at random for each run, so that no worker can know "
                 "which of its pixels are checked)")
      ->check(CLI::Range(uint64_t{1}, std::numeric_limits<uint64_t>::max()))
      ->group(parallel);
  addRunPlanFlags(cmd, o, {parallel, parallel, "Testing", /*simulated=*/false});
}

bool launchedByMpirun() {
  for (const char* v : {"OMPI_COMM_WORLD_SIZE", "PMI_SIZE", "PMIX_RANK"}) {
    if (std::getenv(v) != nullptr) return true;
  }
  return false;
}

ParallelOptions toParallelOptions(const RenderOptions& o, int workers) {
  ParallelOptions p;
  static_cast<RunPlan&>(p) = runPlanFrom(o, workers);
  p.workers = workers;
  p.slowdowns = o.slowdowns;
  p.acceptWorkersPath = o.acceptWorkersPath;
  p.acceptAddress = o.acceptAddress;
  if (!o.slowdownAt.empty()) {
    p.slowdownChanges = parseSpeedChanges(o.slowdownAt, "--slowdown-at", p.totalWorkers(), 1);
  }
  const bool automatic = o.speedIndex == "auto";
  p.speedIndexKind =
      automatic ? (runsSpeedIndexByDefault(p.strategy) ? SpeedIndexKind::Hanoi : SpeedIndexKind::None)
                : parseSpeedIndexKind(o.speedIndex);
  p.batchSeconds = o.batchSeconds.value_or(defaultBatchSeconds(p.totalWorkers()));
  p.threads = o.threads;
  p.checkpointPath = o.checkpointPath;
  p.checkpointAutomatic = o.checkpointAutomatic;
  p.announceCheckpoint = !o.quiet;
  p.checkpointEverySeconds = o.checkpointEverySeconds;
  p.verifyPercent = o.verifyPercent;
  p.verifySeed = o.verifySeed;
  return p;
}

int finishParallelRun(const RenderOptions& o, const Scene& scene, const RenderSettings& settings,
                      const ParallelRun& run) {
  const FrameSequence frames = framesOf(o);
  const bool sequence = frames.count() > 1;
  if (!sequence) {  // a sequence's frames are written
    try {
      writeImage(run.image, scene.image.output, o.imageOptions);
    } catch (const std::exception& e) {
      keepPixelsOfUnwrittenImage(o, checkpointKey(scene, settings, frames),
                                 TaskSet::range(0, run.image.pixelCount()), run.image, run.owner,
                                 e);
    }
  }
  writeRenderReportAndPage(o, scene, run);  // --report and --html
  if (!o.tracePath.empty()) {
    writeFileAtomically(o.tracePath,
                        chromeTraceJson(run.events, static_cast<int>(run.report.workers.size()),
                                        run.report.elapsedSeconds));
  }
  if (!o.ownershipPath.empty() && !sequence) {
    writeImage(ownershipImage(run.image, run.owner), o.ownershipPath);
  } else if (!o.ownershipPath.empty()) {  // one map per frame
    const Image all = ownershipImage(run.image, run.owner);
    for (uint64_t i = 0; i < frames.count(); ++i) {
      writeImage(frameOfSequence(all, scene.image.height, i),
                 framePath(o.ownershipPath, frames.number(i)));
    }
  }
  // The image holds every pixel now: the checkpoint has nothing more to give.
  if (!o.checkpointPath.empty()) removeCheckpoint(o.checkpointPath);
  if (sequence) finishSequence(o, scene.image.output, frames);
  if (!o.quiet && sequence) {
    std::printf("%s: %llu frames (%lld-%lld:%lld) of %dx%d, %d spp, DRT %d\n%s",
                scene.image.output.c_str(), static_cast<unsigned long long>(frames.count()),
                static_cast<long long>(frames.first), static_cast<long long>(frames.last),
                static_cast<long long>(frames.step), scene.image.width, scene.image.height,
                run.report.info.samplesPerPixel, run.report.info.drtRate,
                run.report.toTable().c_str());
  } else if (!o.quiet) {
    std::printf("%s: %dx%d, %d spp, DRT %d\n%s", scene.image.output.c_str(), scene.image.width,
                scene.image.height, run.report.info.samplesPerPixel, run.report.info.drtRate,
                run.report.toTable().c_str());
  }
  return 0;
}

namespace {
ProgressBoard::RunFacts runFacts(const std::string& driver, const RunRequest& request) {
  return {driver, request.options.strategy, request.scene.image.width,
          request.scene.image.height, request.frames.count(), request.scene.image.output};
}
}  // namespace

RunRequest makeRunRequest(const RenderOptions& o, const Scene& scene, const RenderSettings& s,
                          int workers) {
  RunRequest request;
  request.scene = scene;
  request.settings = s;
  request.options = toParallelOptions(o, workers);
  request.frames = framesOf(o);
  validateParallelOptions(request.options, static_cast<uint64_t>(scene.image.width) *
                                               scene.image.height * request.frames.count());
  if (request.frames.count() > 1) {
    const FrameSequence frames = request.frames;
    const std::string pattern = scene.image.output;
    const bool quiet = o.quiet;
    const ImageWriteOptions imageOptions = o.imageOptions;
    request.frameDone = [frames, pattern, quiet, imageOptions](uint64_t ordinal,
                                                               const Image& frame) {
      const std::string path = framePath(pattern, frames.number(ordinal));
      writeImage(frame, path, imageOptions);
      if (!quiet) std::fprintf(stderr, "prt: frame %lld written: %s\n",
                               static_cast<long long>(frames.number(ordinal)), path.c_str());
    };
  }
  request.resumeFrom = resumeCheckpoint(o, scene, s);
  request.interrupted = stopSignalsFor(o);
  return request;
}

int renderParallelLocal(const RenderOptions& o, const Scene& scene, const RenderSettings& s) {
  RunRequest request = makeRunRequest(o, scene, s, o.workers.value_or(4));
  // Each emulated worker is one core unless told otherwise.
  if (request.options.threads == 0) request.options.threads = 1;
  request.serialSeconds = serialSeconds(o, scene, s);
  request.masterSpeedIndexSeconds =
      serialSpeedIndexSeconds(request.options.speedIndexKind, scene, s);
  LiveView view(o, runFacts("threads", request));
  request.progress = &view.board();
  // --accept-workers: machines join over TCP (prt join FILE); the door's refusals go in the
  // report.
  auto door = std::make_shared<TcpDoor*>(nullptr);
  auto refused = std::make_shared<std::vector<std::string>>();
  if (!o.acceptWorkersPath.empty()) {
    request.wrapLocalMaster = localDoor(o.acceptWorkersPath, request.options,
                                        [door](TcpDoor& d) { *door = &d; }, refused);
    request.rejectedHost = [door](const std::string& host) {
      if (*door != nullptr) (*door)->block(host);
    };
  }
  try {
    ParallelRun run = renderLocal(request);
    for (const std::string& why : *refused) run.report.info.faults.refusedJoiners.push_back(why);
    view.stopLines();
    const int code = finishParallelRun(o, scene, s, run);
    view.finish();
    return code;
  } catch (const RunFailed& e) {
    view.stopLines();
    std::fprintf(stderr, "prt: error: %s\n", e.what());
    tellHowToResume(o);
    return e.signal() > 0 ? 128 + e.signal() : 1;
  }
}

// --- MPI hook (the driver is in src/mpi; this is only the command-line glue) ---------------
int renderParallelMpi(const RenderOptions& o, const SceneLoader& loadScene) {
#ifdef PRT_HAVE_MPI
  MpiSession session(!o.acceptWorkersPath.empty(), o.startupTimeoutSeconds);
  std::optional<RenderOptions> plan;  // once the scene is read: the checkpoint settled
  if (!session.isMaster()) {
    // Every rank parses the same command line. Options that are bad here are bad on the
    // master too, which reports them once and releases the workers; until then run with
    // defaults.
    ParallelOptions options;
    try {
      options = toParallelOptions(o, session.workerCount());
    } catch (const InputError&) {
    }
    return session.exitCode(runMpiWorker(session, options));
  }
  try {
    if (session.size() < 2) {
      throw InputError(
          "prt render under MPI needs at least 2 ranks: mpirun -np N+1 prt render "
          "... (rank 0 is the master, ranks 1..N the workers)");
    }
    auto [scene, settings] = loadScene();
    plan = withCheckpointPlan(o, scene);
    const RenderOptions& planned = *plan;
    recordCheckpointPath(planned.checkpointPath);
    if (!o.slowdowns.empty() && o.slowdowns.size() != static_cast<size_t>(session.workerCount())) {
      throw InputError("--slowdown lists " + std::to_string(o.slowdowns.size()) +
                       " values but mpirun started " + std::to_string(session.workerCount()) +
                       " workers (ranks 1.." + std::to_string(session.workerCount()) +
                       "; rank 0 is the master); give one per worker");
    }
    RunRequest request = makeRunRequest(planned, scene, settings, session.workerCount());
    // Without --enable-recovery a worker that dies ends the job within about a second, before
    // the master can notice: the automatic checkpoint is kept from the start.
    request.options.checkpointFromStart = !session.recoveryEnabled();
    request.serialSeconds = serialSeconds(o, request.scene, request.settings);
    request.masterSpeedIndexSeconds = serialSpeedIndexSeconds(
        request.options.speedIndexKind, request.scene, request.settings);
    LiveView view(o, runFacts("mpi", request));
    request.progress = &view.board();
    // From here the driver kit survives lost workers; only losing them all fails the run.
    const ParallelRun run = [&] {
      try {
        return renderMpiMaster(session, request);
      } catch (...) {
        view.stopLines();
        throw;
      }
    }();
    view.stopLines();
    const int code = finishParallelRun(planned, request.scene, request.settings, run);
    view.finish();
    finishMpiMaster(session, run);
    return session.exitCode(code);
  } catch (const RunFailed& e) {
    session.abort(std::string(e.what()) + (plan ? howToResume(*plan) : ""),
                  e.signal() > 0 ? 128 + e.signal() : 1);
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
