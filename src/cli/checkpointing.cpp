#include "cli/checkpointing.h"

#include <atomic>
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <memory>

#include "cli/live_view.h"
#include "farm/run_progress.h"
#include "cli/video_output.h"
#include "core/input_error.h"
#include "core/stop_signals.h"
#include "image/image_io.h"
#include "farm/frame_renderer.h"
#include "farm/parallel_run.h"
#include "trace/renderer.h"

namespace prt::cli {

RenderOptions withCheckpointPlan(RenderOptions o, const Scene& scene) {
  if (o.checkpointPath.empty() && !o.noCheckpoint && o.costMapPath.empty()) {
    o.checkpointPath = scene.image.output + ".ckpt";
    o.checkpointAutomatic = true;
  }
  return o;
}

std::string resumeCommand(const RenderOptions& o) {
  const std::string& typed = o.commandLine;
  const bool has = typed.find(" --resume") != std::string::npos;
  return has ? typed : typed + " --resume";
}

namespace {
// Set once the resume command has been printed, so that it is printed once.
std::atomic<bool> resumeTold{false};
}  // namespace

std::string howToResume(const RenderOptions& o) {
  std::error_code ec;
  if (o.checkpointPath.empty() || !std::filesystem::exists(o.checkpointPath, ec)) return "";
  if (resumeTold.load()) return "";
  return "\nprt: to render the rest, run:\n  " + resumeCommand(o);
}

void tellHowToResume(const RenderOptions& o) {
  const std::string text = howToResume(o);
  if (text.empty()) return;
  std::fprintf(stderr, "%s\n", text.c_str() + 1);
  std::fflush(stderr);
}

std::optional<Checkpoint> resumeCheckpoint(const RenderOptions& o, const Scene& scene,
                                           const RenderSettings& settings) {
  if (o.checkpointPath.empty()) {
    if (o.resume) {
      throw InputError("--resume continues from a checkpoint, and --no-checkpoint keeps none: "
                       "drop one of them (or name the file with --checkpoint FILE)");
    }
    return std::nullopt;
  }
  const CheckpointKey key = checkpointKey(scene, settings, framesOf(o));
  if (!o.resume) {
    std::error_code ec;
    if (!std::filesystem::exists(o.checkpointPath, ec)) return std::nullopt;
    // What it holds, so the choice is an informed one.
    std::string holds;
    try {
      if (const auto c = readCheckpoint(o.checkpointPath, key)) {
        const uint64_t total = static_cast<uint64_t>(scene.image.width) * scene.image.height *
                               framesOf(o).count();
        char percent[32];
        std::snprintf(percent, sizeof percent, "%.1f%%",
                      total ? 100.0 * static_cast<double>(c->done.size()) /
                                  static_cast<double>(total)
                            : 0.0);
        holds = " holds " + std::to_string(c->done.size()) + " finished pixels (" + percent +
                ") of an earlier run of this render";
      }
    } catch (const InputError&) {
      holds = " is a checkpoint of another render (or damaged)";
    }
    const std::string rm = "rm '" + o.checkpointPath + "'";
    throw InputError("checkpoint '" + o.checkpointPath + "'" +
                     (holds.empty() ? " already exists" : holds) +
                     ": to continue it, run\n  " + resumeCommand(o) +
                     "\nor, to render from the start, remove it first:\n  " + rm +
                     (o.checkpointAutomatic ? "\n(or add --no-checkpoint to leave it be)" : ""));
  }
  std::optional<Checkpoint> c = readCheckpoint(o.checkpointPath, key);
  if (!c && !o.quiet) {
    std::fprintf(stderr, "prt: no checkpoint at '%s' yet; rendering from the start\n",
                 o.checkpointPath.c_str());
  }
  return c;
}

void keepPixelsOfUnwrittenImage(const RenderOptions& o, const CheckpointKey& key,
                                const TaskSet& done, const Image& image,
                                const std::vector<int16_t>& owner, const std::exception& failure) {
  std::string message = failure.what();
  if (o.checkpointPath.empty()) {
    throw InputError(message + "\nthe finished pixels are lost (--no-checkpoint); with a "
                               "checkpoint they would be kept for --resume");
  }
  try {
    writeCheckpoint(o.checkpointPath, key, done, image, owner);
    message += "\nthe " + std::to_string(done.size()) + " finished pixels are saved in '" +
               o.checkpointPath + "': once there is room, run\n  " + resumeCommand(o) +
               "\nto write them without rendering them again";
    resumeTold.store(true);
  } catch (const std::exception& also) {
    message += "\nthe finished pixels could not be saved either: " + std::string(also.what());
  }
  throw InputError(message);
}

std::function<int()> stopSignalsFor(const RenderOptions& o) {
  if (o.checkpointPath.empty()) return nullptr;
  installStopSignals();
  // Said the moment the signal is seen, before the checkpoint is written: a launcher may
  // follow SIGTERM with SIGKILL before the run's last words (Slurm after its KillWait;
  // Open MPI after a lost rank sends both at once, where only scripts/prt-mpirun can still
  // speak). The checkpoint already on disk (the last periodic one) resumes the render then.
  auto noticed = std::make_shared<std::atomic<bool>>(false);
  return [o, noticed] {
    const int sig = pendingStopSignal();
    if (sig != 0 && !noticed->exchange(true)) {
      // What is on disk now, too: a launcher's SIGKILL may come before the save.
      std::error_code ec;
      const bool saved = std::filesystem::exists(o.checkpointPath, ec);
      std::fprintf(stderr,
                   "prt: stopping on signal %d: saving the finished pixels in '%s' (%s)\n", sig,
                   o.checkpointPath.c_str(),
                   saved ? "until then it holds those of its last save" : "none is saved yet");
      const std::string text = howToResume(o);
      if (!text.empty()) {
        std::fprintf(stderr, "%s\n", text.c_str() + 1);
        resumeTold.store(true);
      }
      std::fflush(stderr);
    }
    return sig;
  };
}

int renderSerialWithCheckpoint(const RenderOptions& o, const Scene& scene,
                               const RenderSettings& settings) {
  if (!o.costMapPath.empty()) {
    throw InputError("--cost-map times a whole render; it cannot be combined with --checkpoint");
  }
  const FrameSequence frames = framesOf(o);
  const CheckpointKey key = checkpointKey(scene, settings, frames);
  std::optional<Checkpoint> resumed = resumeCheckpoint(o, scene, settings);
  const std::function<int()> interrupted = stopSignalsFor(o);
  FrameRenderer renderer(scene, settings, frames);
  // A sequence's pixels are its frames one above the other; each frame is written once its
  // last pixel is in.
  const uint64_t perFrame = renderer.pixelsPerFrame();
  const uint64_t pixels = renderer.taskCount();
  const bool sequence = frames.count() > 1;
  const int rows = scene.image.height * static_cast<int>(frames.count());
  Image image = resumed ? resumed->image : Image(scene.image.width, rows);
  TaskSet done = resumed ? resumed->done : TaskSet{};
  const std::vector<int16_t> noOwners;
  writeCheckpoint(o.checkpointPath, key, done, image, noOwners);  // the path works: go

  std::vector<bool> isDone(pixels, false);
  std::vector<uint64_t> frameCounts(frames.count(), 0);
  done.forEach([&](uint64_t p) {
    isDone[p] = true;
    ++frameCounts[p / perFrame];
  });
  const auto writeFrame = [&](uint64_t ordinal) {
    writeImage(frameOfSequence(image, scene.image.height, ordinal),
               framePath(scene.image.output, frames.number(ordinal)), o.imageOptions);
  };
  if (sequence) {  // what the earlier run completed, written again in case it was cut short
    for (uint64_t i = 0; i < frames.count(); ++i) {
      if (frameCounts[i] != perFrame) continue;
      try {
        writeFrame(i);
      } catch (const std::exception& e) {
        keepPixelsOfUnwrittenImage(o, key, done, image, noOwners, e);
      }
    }
  }
  const uint64_t resumedCount = done.size();
  using Clock = std::chrono::steady_clock;
  const auto start = Clock::now();
  auto lastSave = start;
  uint64_t rays = 0;
  // Pieces of a few rows: small enough to save often, large enough to keep every core busy.
  const uint64_t piece = std::max<uint64_t>(4096, 4 * static_cast<uint64_t>(scene.image.width));
  LiveView view(o, {"serial", "", scene.image.width, scene.image.height, frames.count(),
                    scene.image.output});
  RunProgress progress(view.board(), scene.image.width, scene.image.height, frames.count());
  progress.resumed(done);
  std::vector<Color> colors;
  uint64_t next = 0;
  while (next < pixels) {
    if (const int sig = interrupted ? interrupted() : 0) {
      writeCheckpoint(o.checkpointPath, key, done, image, noOwners);
      progress.end(steadySeconds(), image, nullptr, false,
                   "interrupted by signal " + std::to_string(sig));
      view.finish();
      std::fprintf(stderr,
                   "prt: interrupted by signal %d; %llu of %llu pixels are saved in '%s'\n",
                   sig, static_cast<unsigned long long>(done.size()),
                   static_cast<unsigned long long>(pixels), o.checkpointPath.c_str());
      tellHowToResume(o);
      return 128 + sig;
    }
    TaskSet todo;
    while (next < pixels && todo.size() < piece) {
      if (!isDone[next]) todo.append(TaskRun{next, 1, 1});
      ++next;
    }
    if (todo.empty()) continue;
    const double before = steadySeconds();
    rays += renderer.render(todo, o.threads, colors);
    const double after = steadySeconds();
    size_t i = 0;
    std::vector<uint64_t> completed;  // frames this piece completes
    todo.forEach([&](uint64_t p) {
      image.set(p, colors[i++]);
      if (++frameCounts[p / perFrame] == perFrame && sequence) completed.push_back(p / perFrame);
    });
    done.append(todo);
    for (const uint64_t frame : completed) {
      try {
        writeFrame(frame);
      } catch (const std::exception& e) {
        view.stopLines();
        keepPixelsOfUnwrittenImage(o, key, done, image, noOwners, e);
      }
    }
    progress.measured(todo, after - before, after);
    progress.finished(todo);
    progress.tick(after, image, nullptr);
    const auto now = Clock::now();
    if (std::chrono::duration<double>(now - lastSave).count() >= o.checkpointEverySeconds &&
        next < pixels) {
      writeCheckpoint(o.checkpointPath, key, done, image, noOwners);
      lastSave = now;
    }
  }
  const double seconds = std::chrono::duration<double>(Clock::now() - start).count();
  progress.end(steadySeconds(), image, nullptr, true, "written to " + scene.image.output);
  view.finish();
  if (!sequence) {
    try {
      writeImage(image, scene.image.output, o.imageOptions);
    } catch (const std::exception& e) {
      keepPixelsOfUnwrittenImage(o, key, done, image, noOwners, e);
    }
  }
  removeCheckpoint(o.checkpointPath);
  if (sequence) finishSequence(o, scene.image.output, frames);
  if (!o.quiet) {
    std::printf("%s: %dx%d, %d spp, DRT %d, %.3f s, %llu rays; %llu pixels from the checkpoint\n",
                scene.image.output.c_str(), scene.image.width, scene.image.height,
                settings.samplesPerPixel, settings.drtRate, seconds,
                static_cast<unsigned long long>(rays),
                static_cast<unsigned long long>(resumedCount));
  }
  return 0;
}

}  // namespace prt::cli
