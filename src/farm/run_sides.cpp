// The two sides of a parallel render over any transport: what the local driver runs on its
// threads and the MPI driver on its ranks (see parallel_run.h).

#include <chrono>
#include <condition_variable>
#include <cstdio>
#include <exception>
#include <filesystem>
#include <mutex>
#include <thread>
#include <memory>
#include <random>

#include "cluster/master.h"
#include "core/cpu_time.h"
#include "core/stop_signals.h"
#include "core/thread_start.h"
#include "farm/build_info.h"
#include "farm/frame_renderer.h"
#include "drive/master_loop.h"
#include "farm/parallel_run.h"
#include "farm/run_progress.h"
#include "farm/worker_engine.h"
#include "loops/run_info.h"

namespace prt {
namespace {

std::string percent(uint64_t part, uint64_t whole) {
  char text[32];
  std::snprintf(text, sizeof text, "%.1f%%",
                whole > 0 ? 100.0 * static_cast<double>(part) / static_cast<double>(whole) : 0.0);
  return text;
}

}  // namespace

ParallelRun runMasterSide(Transport& net, const RunRequest& request, const std::string& driver,
                          std::function<bool()> abandoned) {
  const Scene& scene = request.scene;
  const ParallelOptions& options = request.options;
  const FrameSequence& frames = request.frames;
  const uint64_t perFrame = static_cast<uint64_t>(scene.image.width) * scene.image.height;
  const uint64_t pixels = perFrame * frames.count();  // the tasks: every frame's pixels
  const int n = options.workers;  // at the start; more may join

  ImageAssembler assembler(scene.image.width,
                           scene.image.height * static_cast<int>(frames.count()),
                           scene.image.height);
  std::vector<FrameInfo> frameInfo(frames.count() > 1 ? frames.count() : 0);
  for (size_t i = 0; i < frameInfo.size(); ++i) frameInfo[i].number = frames.number(i);
  double startTime = net.now();
  // A frame the master could not write (a full disk): its own failure, never a worker's. The
  // run stops at once (the loop polls it as `abandoned`) and keeps what is finished.
  std::string writeFailure;
  const auto frameCompleted = [&](uint64_t ordinal) {
    if (!frameInfo.empty()) frameInfo[ordinal].doneSeconds = net.now() - startTime;
    if (!request.frameDone || !writeFailure.empty()) return;
    try {
      request.frameDone(ordinal, assembler.frame(ordinal));
    } catch (const std::exception& e) {
      writeFailure = e.what();
    }
  };
  // Progress is kept for the board, and for the automatic checkpoint's estimate of the
  // run's length.
  ProgressBoard ownBoard;
  std::optional<RunProgress> progress;
  // The master's own renderer: for the progress probe, and the spot checks' referee. Built
  // before the leases start when it is needed at once (a probe; a single worker, whose checks
  // the master renders), else when a check first needs it.
  std::unique_ptr<FrameRenderer> own;
  const auto ownRenderer = [&]() -> FrameRenderer& {
    if (!own) own = std::make_unique<FrameRenderer>(scene, request.settings, frames);
    return *own;
  };
  if (request.progress || options.checkpointAutomatic) {
    progress.emplace(request.progress ? *request.progress : ownBoard, scene.image.width,
                     scene.image.height, frames.count());
    // The cost of each part of the image, from a few pixels of frame 0 rendered here.
    progress->probeCosts(ownRenderer().frame(0));
  }
  if (options.verifyPercent > 0 && n == 1) ownRenderer().frame(0);
  MasterOptions masterOptions;
  masterOptions.endgame = options.endgame;
  // A worker that keeps tasks without returning results is lost as one that falls silent.
  masterOptions.taskLease = {kTaskLeaseBatches, options.workerTimeoutSeconds};
  // Spot checks: the referee is the master's own render, built when first needed (a
  // disagreement, or no other worker to check), on one thread of this machine.
  // The seed is drawn here unless given: no worker can know which of its pixels are checked.
  uint64_t seed = options.verifySeed;
  while (seed == 0) seed = (uint64_t{std::random_device{}()} << 32) ^ std::random_device{}();
  masterOptions.checks = {options.verifyPercent, seed};
  // It renders while the master heartbeats the workers (whileHeartbeating): a few costly
  // pixels can take seconds. So are checkpoints written, below.
  const double beat = options.heartbeatSeconds();
  std::function<int()> workerCount;  // set once the master exists
  masterOptions.referee = [&](const TaskSet& checked) {
    FrameRenderer& renderer = ownRenderer();
    std::vector<Color> colors;
    whileHeartbeating(net, beat, workerCount, [&] { renderer.render(checked, 1, colors); });
    return asFloats(colors);
  };
  // The version rule (farm/build_info.h): the same PRT version, any trace kernels.
  masterOptions.admit = [](const WorkerIdentity& id) -> std::string {
    if (versionOf(id.build) == prtVersion()) return "";
    std::string shown;
    for (const char c : id.build.substr(0, 120)) shown += (c >= 32 && c < 127) ? c : '?';
    return "it runs '" + shown + "', this render " + buildDescription() +
           ": workers of another version may not mix pixels";
  };
  masterOptions.rejected = [&](const RejectedWorker& r) {
    if (request.rejectedHost && !r.host.empty()) request.rejectedHost(r.host);
  };
  masterOptions.takenBack = [&](int, const TaskSet& t) {
    assembler.takeBack(t);
    if (progress) progress->takenBack(t);
  };
  if (request.resumeFrom) {
    if (progress) progress->resumed(request.resumeFrom->done);
    assembler.restore(*request.resumeFrom);
    masterOptions.resumedDone = request.resumeFrom->done;
    // Frames the earlier run completed are written again: it may have been killed while
    // writing one.
    if (frames.count() > 1) {
      for (uint64_t i = 0; i < frames.count(); ++i) {
        if (assembler.frameComplete(i)) frameCompleted(i);
      }
    }
  }
  Master master(makeStrategy(options.strategy, options.strategyOptions), n, pixels,
                makeSceneMessage(scene, request.settings, frames),
                [&](int w, const TaskSet& t, const std::vector<float>& rgb) {
                  if (!frameInfo.empty()) {
                    const double now = net.now() - startTime;
                    FrameRenderer::forEachFrame(t, perFrame, [&](uint64_t i, const TaskSet& px) {
                      FrameInfo& f = frameInfo[i];
                      if (!f.firstSeconds) f.firstSeconds = now;
                      f.pixels += px.size();
                    });
                  }
                  if (progress) progress->finished(t);
                  assembler.add(w, t, rgb, frames.count() > 1
                                               ? std::function<void(uint64_t)>(frameCompleted)
                                               : std::function<void(uint64_t)>());
                },
                std::move(masterOptions));
  workerCount = [&] { return master.workerCount(); };

  MasterLoopOptions loop;
  loop.leaseSeconds = options.workerTimeoutSeconds;
  loop.heartbeatSeconds = options.heartbeatSeconds();
  loop.checkpointEverySeconds = options.checkpointEverySeconds;
  loop.interrupted = request.interrupted;
  // After the last pixel a signal only cuts the goodbye short: the image is written as usual.
  if (request.interrupted) loop.stopPending = [] { return pendingStopSignal() != 0; };
  loop.abandoned = [&writeFailure, abandoned = std::move(abandoned)] {
    return !writeFailure.empty() || (abandoned && abandoned());
  };
  // The automatic checkpoint: armed once the run is expected to be long.
  bool armed = !options.checkpointAutomatic || options.checkpointFromStart;
  const auto arm = [&](double now) {
    if (armed) return;
    const std::optional<double> total = progress->expectedTotal(now);
    if ((total && *total > kAutomaticCheckpointSeconds) ||
        now - startTime > kAutomaticCheckpointSeconds) {
      armed = true;
      if (options.announceCheckpoint) {
        std::fprintf(stderr,
                   "prt: this render is expected to take %.0f s: its finished pixels are kept "
                   "in '%s' (--no-checkpoint: not kept)\n",
                     total ? *total : now - startTime, options.checkpointPath.c_str());
      }
    }
  };
  if (progress) {
    loop.results = [&](int, const ResultsMsg& r, double now) {
      progress->measured(r.tasks, r.computeSeconds, now);
    };
    loop.tick = [&](double now) {
      progress->tick(now, assembler.image(), &master, false, 0, &assembler.owner());
      arm(now);
    };
  }
  const CheckpointKey key = checkpointKey(scene, request.settings, frames);
  bool warned = false;
  std::string checkpointFailure;   // why the last checkpoint could not be written ("": it was)
  uint64_t checkpoints = 0;        // written during the run
  double checkpointSeconds = 0;    // the master's wall time writing them
  auto saveCheckpoint = [&](const std::string& why) {
    // Unarmed, only a stop saves the pixels done: a short run is cheap to render again.
    const bool periodic =
        why == "periodic" || why == "a worker was lost" || why == "a worker was rejected";
    const bool nothingNew = master.doneCount() == master.resumedCount();
    if (!armed && (periodic || nothingNew)) return;
    // An automatic checkpoint of nothing new would only stand in a later run's way.
    if (options.checkpointAutomatic && nothingNew) return;
    armed = true;
    const double from = net.now();
    try {
      const TaskSet done = master.checkedDoneSet();
      whileHeartbeating(net, beat, workerCount, [&] {
        writeCheckpoint(options.checkpointPath, key, done, assembler.image(), assembler.owner());
      });
      ++checkpoints;
      checkpointSeconds += net.now() - from;
      checkpointFailure.clear();
    } catch (const std::exception& e) {
      checkpointFailure = e.what();
      // The render goes on: a checkpoint that cannot be written loses nothing yet.
      if (!warned) {
        std::fprintf(stderr, "prt: warning: checkpoint (%s) not written: %s\n", why.c_str(),
                     e.what());
      }
      warned = true;
    }
  };
  if (!options.checkpointPath.empty()) {
    if (!options.checkpointAutomatic) {
      // Written before any rendering: a path that cannot take it fails now, not hours later.
      writeCheckpoint(options.checkpointPath, key, master.checkedDoneSet(), assembler.image(),
                      assembler.owner());
    }
    loop.checkpoint = [&](const std::string& why, double) {
      saveCheckpoint(why);
      return net.now();
    };
  }

  startTime = net.now();
  if (progress) progress->tick(startTime, assembler.image(), &master, true, 0, &assembler.owner());
  MasterLoopResult result = runMasterLoop(net, master, loop);
  if (progress) {
    progress->end(net.now(), assembler.image(), &master, result.failure.empty(),
                  result.failure, 0, &assembler.owner());
  }
  if (!result.failure.empty()) {
    std::string message = writeFailure.empty() ? result.failure
                                               : writeFailure + " (the frames written so far stay)";
    // Workers of --join-at that had not arrived yet: the run does not wait for them.
    const int due = options.joinerCount() - (master.workerCount() - options.workers);
    if (master.failed() && due > 0) {
      message += " (the run does not wait for the " + std::to_string(due) +
                 (due == 1 ? " worker" : " workers") + " still due to join (--join-at))";
    }
    std::error_code ec;
    const bool onDisk =
        !options.checkpointPath.empty() && std::filesystem::exists(options.checkpointPath, ec);
    if (!options.checkpointPath.empty() && !checkpointFailure.empty()) {
      message += "; the finished pixels could not be saved either (" + checkpointFailure + ")";
      if (onDisk) {
        message += ": '" + options.checkpointPath + "' keeps what it held before, and --resume "
                   "renders the rest";
      }
    } else if (onDisk && armed) {
      message += "; " + std::to_string(master.doneCount()) + " of " + std::to_string(pixels) +
                 " pixels (" + percent(master.doneCount(), pixels) + ") are saved in '" +
                 options.checkpointPath +
                 "': run the same command with --resume to render the rest";
    } else {
      message += "; add --checkpoint FILE to keep the finished pixels of a run";
    }
    throw RunFailed(message, result.interruptSignal);
  }

  ParallelRun run;
  run.events = std::move(result.log.events);
  RunInfo info;
  info.driver = driver;
  info.strategy = options.strategy;
  info.width = scene.image.width;
  info.height = scene.image.height;
  info.samplesPerPixel = request.settings.samplesPerPixel;
  info.drtRate = request.settings.drtRate;
  info.masterSpeedIndexSeconds = request.masterSpeedIndexSeconds;
  info.serialSeconds = request.serialSeconds;
  info.speedIndexRun = options.speedIndexKind != SpeedIndexKind::None;
  recordMaster(info, {master, result.summaries, run.events, net.sharedClock(),
                      loop.leaseSeconds, loop.heartbeatSeconds,
                      [&](int w) { return options.slowdownOf(w); }});
  info.faults.verifyPercent = master.spotChecks().enabled() ? options.verifyPercent : 0;
  info.faults.verifyLowestPercent = 100 * master.spotChecks().lowestRate(info.faults.verifyPercent);
  info.faults.verifySeed = seed;
  info.master = result.load;
  info.master->checkpoints = checkpoints;
  info.master->checkpointSeconds = checkpointSeconds;
  if (!frameInfo.empty()) {
    info.frames = std::move(frameInfo);
    info.fps = frames.fps;
  }
  run.report = makeReport(info, run.events, result.elapsedSeconds);
  run.image = std::move(assembler.image());
  run.owner = std::move(assembler.owner());
  return run;
}

WorkerExit runWorkerSide(Transport& net, int id, const ParallelOptions& options,
                         const WorkerFaultActions& faults) {
  const int threads = options.threads > 0 ? options.threads : affinityCpuCount();
  WorkerEngine engine(options.slowdownOf(id), options.speedIndexKind, options.speedIndexDiscs,
                      options.slowdownChangesOf(id), threads);
  WorkerLoopOptions loop;
  loop.batchPixels = options.batchPixels;
  loop.batchSeconds = options.batchSeconds;
  loop.heartbeatSeconds = options.heartbeatSeconds();
  loop.masterTimeoutSeconds = options.workerTimeoutSeconds;
  for (const FaultInjection& f : options.faults) {
    if (f.worker == id) loop.fault = f;
  }
  return runWorkerLoop(net, id, engine, loop, faults);
}

}  // namespace prt
