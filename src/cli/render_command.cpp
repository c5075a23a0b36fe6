#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <memory>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "cli/checkpointing.h"
#include "cli/commands.h"
#include "net/tcp_door.h"
#include "cli/flag_checks.h"
#include "cli/parallel_render.h"
#include "cli/live_view.h"
#include "farm/run_progress.h"
#include "cli/run_page_output.h"
#include "cli/video_output.h"
#include "core/input_error.h"
#include "image/atomic_file.h"
#include "image/image_io.h"
#include "farm/checkpoint.h"
#include "farm/frame_renderer.h"
#include "farm/parallel_options.h"
#include "metrics/run_report.h"
#include "scene/animation.h"
#include "scene/environment_file.h"
#include "scene/number_text.h"
#include "scene/scene_file.h"
#include "sim/cost_map_file.h"
#include "trace/render_settings.h"
#include "trace/renderer.h"

namespace prt::cli {

FrameSequence framesOf(const RenderOptions& o) {
  if (!o.frames.empty() && !o.frame.empty()) {
    throw InputError("give --frames A-B for a sequence or --frame N for one frame, not both");
  }
  if (!(o.fps > 0 && o.fps <= 1e6)) {
    throw InputError("--fps must be a number of frames per second in (0, 1e6] (got " +
                     formatDouble(o.fps) + ")");
  }
  if (o.frames.empty() && o.frame.empty()) return FrameSequence{};
  const std::string& text = o.frames.empty() ? o.frame : o.frames;
  const char* flag = o.frames.empty() ? "--frame" : "--frames";
  if (!o.frame.empty() && o.frame.find_first_of(":") != std::string::npos) {
    throw InputError("--frame takes one frame number; use --frames A-B[:STEP] for a sequence");
  }
  std::string error;
  std::optional<FrameSequence> s = parseFrames(text, error);
  if (!s) throw InputError(std::string(flag) + " '" + text + "': " + error);
  if (!o.frame.empty() && s->count() != 1) {
    throw InputError("--frame takes one frame number; use --frames A-B[:STEP] for a sequence");
  }
  s->fps = o.fps;
  return *s;
}

namespace {

// Applies the command line over the scene's own settings; --spp and --drt win over --case.
RenderSettings resolveSettings(const RenderOptions& o, Scene& scene) {
  RenderSettings s{scene.sampling.samplesPerPixel, scene.sampling.drtRate};
  if (!o.testCase.empty()) s = *paperTestCase(o.testCase);
  if (o.spp) s.samplesPerPixel = *o.spp;
  if (o.drt) s.drtRate = *o.drt;
  if (!o.integrator.empty()) {
    scene.environment.integrator = o.integrator == "path" ? Integrator::path : Integrator::hall;
  }
  EnvironmentMap& map = scene.environment.map;
  if (!o.environment.empty()) {
    map.file = std::filesystem::absolute(o.environment).lexically_normal().string();
    map.image = readEnvironmentMap(o.environment);
  }
  if ((o.environmentStrength || o.environmentRotate) && !map.image) {
    throw InputError("--environment-strength and --environment-rotate apply to an environment "
                     "map: give one with --environment FILE (or the scene's environment { map "
                     "\"FILE\" })");
  }
  if (o.environmentStrength) map.strength = *o.environmentStrength;
  if (o.environmentRotate) map.rotateDegrees = *o.environmentRotate;
  applyImageSize(scene, o.width, o.height);
  if (!o.output.empty()) scene.image.output = o.output;
  const uint64_t pixels = static_cast<uint64_t>(scene.image.width) * scene.image.height;
  if (pixels > (1ull << 28)) {
    throw InputError("image too large: " + std::to_string(scene.image.width) + "x" +
                     std::to_string(scene.image.height) + " exceeds 2^28 pixels");
  }
  const FrameSequence frames = framesOf(o);
  if (frames.count() > 1) {
    // The master holds every frame of the job (3 floats and an owner per pixel).
    if (pixels * frames.count() > (1ull << 30)) {
      throw InputError(std::to_string(frames.count()) + " frames of " +
                       std::to_string(scene.image.width) + "x" +
                       std::to_string(scene.image.height) +
                       " exceed the 2^30 pixels one job may hold; split the range into jobs");
    }
    if (static_cast<uint64_t>(scene.image.height) * frames.count() > (1ull << 30)) {
      throw InputError("too many rows for one job: split the range into jobs");
    }
    if (!hasFramePattern(scene.image.output)) {
      throw InputError("a sequence of " + std::to_string(frames.count()) +
                       " frames needs an output pattern with one run of '#' for the frame "
                       "number, e.g. -o frame_####.png (got '" + scene.image.output + "')");
    }
    for (const std::string& path : {o.ownershipPath}) {
      if (!path.empty() && !hasFramePattern(path)) {
        throw InputError("--ownership '" + path + "': a sequence writes one map per frame; "
                         "give a pattern with '#', e.g. owners_####.png");
      }
    }
  } else if (frames.animated) {
    scene.image.output = framePath(scene.image.output, frames.first);  // --frame N
  }
  if (scene.animation) {
    // Every frame must render: a motion can carry the camera through what it looks at.
    for (uint64_t i = 0; i < frames.count(); ++i) {
      const std::string problem = frameProblem(sceneAt(scene, frames.seconds(i)));
      if (!problem.empty()) {
        throw InputError("frame " + std::to_string(frames.number(i)) + " (at " +
                         formatDouble(frames.seconds(i)) + " s): " + problem +
                         "; change the keys or leave the frame out");
      }
    }
  }
  for (const std::string& path : {scene.image.output, o.ownershipPath}) {
    if (path.empty() || isSupportedImagePath(path)) continue;
    std::string list;
    for (const auto& e : supportedImageExtensions()) list += (list.empty() ? "" : ", ") + e;
    throw InputError("image file '" + path + "' has an unsupported extension; use " + list);
  }
  return s;
}

// Every file the run will write, checked before any rendering: a render may take hours, and
// failing only at its end (or writing the image and then failing) wastes them. Two outputs
// naming one file would overwrite each other.
void checkOutputs(const RenderOptions& o, const Scene& scene) {
  namespace fs = std::filesystem;
  const std::pair<const char*, std::string> outputs[] = {{"-o", scene.image.output},
                                                         {"--cost-map", o.costMapPath},
                                                         {"--report", o.reportPath},
                                                         {"--trace", o.tracePath},
                                                         {"--ownership", o.ownershipPath},
                                                         {"--html", o.htmlPath},
                                                         {"--video", o.videoPath},
                                                         {"--checkpoint", o.checkpointPath}};
  std::vector<std::pair<const char*, fs::path>> seen;
  for (const auto& [flag, path] : outputs) {
    if (path.empty()) continue;
    std::error_code error;
    const fs::path resolved = fs::weakly_canonical(fs::absolute(path), error);
    for (const auto& [otherFlag, otherPath] : seen) {
      if (!error && resolved == otherPath) {
        throw InputError(std::string(flag) + " and " + otherFlag + " name the same file '" +
                         path + "'; each output needs its own");
      }
    }
    if (!error) seen.emplace_back(flag, resolved);
    checkWritable(path);
  }
}

ProgressBoard::RunFacts serialFacts(const RenderOptions& o, const Scene& scene,
                                    const FrameSequence& frames) {
  (void)o;
  return {"serial", "", scene.image.width, scene.image.height, frames.count(), scene.image.output};
}

// A tile of a serial render (of the frame whose first task is `firstTask`) into its progress.
void reportTile(RunProgress& progress, const TileDone& tile, uint64_t firstTask) {
  TaskSet tasks;
  const auto w = static_cast<uint64_t>(tile.image.width());
  for (int y = tile.y0; y < tile.y1; ++y) {
    tasks.append(TaskRun{firstTask + static_cast<uint64_t>(y) * w + static_cast<uint64_t>(tile.x0),
                         static_cast<uint64_t>(tile.x1 - tile.x0), 1});
  }
  const double now = steadySeconds();
  progress.measured(tasks, tile.seconds, now);
  progress.finished(tasks);
  progress.tick(now, tile.image, nullptr, false, firstTask);
}

// Said even with --quiet: such samples are a fault of the scene or the renderer.
void warnOfNonFiniteSamples(uint64_t count) {
  if (count > 0) std::fprintf(stderr, "prt: warning: %s\n", nonFiniteSamplesLine(count).c_str());
}

// The frames of a sequence one after another, each on every thread and written once done.
int renderSerialSequence(const RenderOptions& o, const Scene& scene,
                         const RenderSettings& settings, const FrameSequence& frames) {
  FrameRenderer renderer(scene, settings, frames);
  RenderStats total;
  LiveView view(o, serialFacts(o, scene, frames));
  RunProgress progress(view.board(), scene.image.width, scene.image.height, frames.count());
  const uint64_t perFrame = renderer.pixelsPerFrame();
  for (uint64_t i = 0; i < frames.count(); ++i) {
    RenderStats stats;
    Image image = renderImage(renderer.frame(i), o.threads, &stats, [&](const TileDone& tile) {
      reportTile(progress, tile, i * perFrame);
      return true;
    });
    const std::string path = framePath(scene.image.output, frames.number(i));
    if (i + 1 == frames.count()) {
      progress.end(steadySeconds(), image, nullptr, true, "frames written to " + scene.image.output,
                   i * perFrame);
    }
    writeImage(image, path, o.imageOptions);
    total.rays += stats.rays;
    total.seconds += stats.seconds;
    if (!o.quiet) {
      std::printf("frame %lld (%llu of %llu): %s, %.3f s\n",
                  static_cast<long long>(frames.number(i)),
                  static_cast<unsigned long long>(i + 1),
                  static_cast<unsigned long long>(frames.count()), path.c_str(), stats.seconds);
    }
  }
  view.finish();
  finishSequence(o, scene.image.output, frames);
  if (!o.quiet) {
    std::printf("%llu frames of %dx%d, %d spp, DRT %d: %.3f s rendering, %.3f s preparing "
                "frames (%.3f s the first, with the meshes' trees), %llu rays\n",
                static_cast<unsigned long long>(frames.count()), scene.image.width,
                scene.image.height, settings.samplesPerPixel, settings.drtRate, total.seconds,
                renderer.buildSeconds(), renderer.firstBuildSeconds(),
                static_cast<unsigned long long>(total.rays));
  }
  warnOfNonFiniteSamples(renderer.nonFiniteSamples());
  return 0;
}

int renderSerial(const RenderOptions& o, const Scene& scene, const RenderSettings& settings) {
  const FrameSequence frames = framesOf(o);
  if (frames.count() > 1) return renderSerialSequence(o, scene, settings, frames);
  if (!o.quiet && frames.animated == false && scene.animation) {
    std::fprintf(stderr, "prt: the scene is animated; rendering it at time 0 (--frames A-B "
                         "renders a sequence, --frame N one frame)\n");
  }
  const World world(sceneAt(scene, frames.seconds(0)));
  if (const World::MeshStats& m = world.meshStats(); m.meshes > 0 && !o.quiet) {
    std::printf("meshes: %zu, %zu triangles; trees built in %.3f s, %.1f MB (%.0f bytes per "
                "triangle)\n",
                m.meshes, m.triangles, m.buildSeconds, static_cast<double>(m.bytes) / 1e6,
                static_cast<double>(m.bytes) / static_cast<double>(m.triangles));
  }
  const Renderer renderer(world, settings);
  RenderStats stats;
  std::vector<float> pixelSeconds;
  // The automatic checkpoint (withCheckpointPlan): kept once the render proves long, and
  // when a signal stops it.
  (void)resumeCheckpoint(o, scene, settings);  // refuses to pass over an earlier run's
  const std::function<int()> interrupted = stopSignalsFor(o);
  const CheckpointKey key = checkpointKey(scene, settings, frames);
  LiveView view(o, serialFacts(o, scene, frames));
  RunProgress progress(view.board(), scene.image.width, scene.image.height);
  std::vector<bool> done(renderer.pixelCount(), false);
  bool armed = false;
  double lastSave = steadySeconds();
  const double start = lastSave;
  const auto save = [&](const Image& partial) {
    // Only finished pixels are read: other threads are writing the rest.
    Image copy(partial.width(), partial.height());
    TaskSet finished;
    for (uint64_t p = 0; p < done.size(); ++p) {
      if (!done[p]) continue;
      copy.set(p, partial.at(p));
      finished.append(TaskRun{p, 1, 1});
    }
    try {
      writeCheckpoint(o.checkpointPath, key, finished, copy, {});
    } catch (const std::exception& e) {
      std::fprintf(stderr, "prt: warning: checkpoint not written: %s\n", e.what());
    }
    lastSave = steadySeconds();
  };
  int signal = 0;
  Image image = renderImage(
      renderer, o.threads, &stats,
      [&](const TileDone& tile) {
        reportTile(progress, tile, 0);
        for (int y = tile.y0; y < tile.y1; ++y) {
          for (int x = tile.x0; x < tile.x1; ++x) done[tile.image.pixelIndex(x, y)] = true;
        }
        if (interrupted && (signal = interrupted()) != 0) return false;
        if (o.checkpointPath.empty()) return true;
        const double now = steadySeconds();
        if (!armed) {
          const std::optional<double> total = progress.expectedTotal(now);
          armed = (total && *total > kAutomaticCheckpointSeconds) ||
                  now - start > kAutomaticCheckpointSeconds;
          if (armed && !o.quiet) {
            std::fprintf(stderr,
                         "prt: this render is expected to take %.0f s: its finished pixels are "
                         "kept in '%s' (--no-checkpoint: not kept)\n",
                         total ? *total : now - start, o.checkpointPath.c_str());
          }
        }
        if (armed && now - lastSave >= o.checkpointEverySeconds) save(tile.image);
        return true;
      },
      o.costMapPath.empty() ? nullptr : &pixelSeconds);
  if (signal != 0) {
    progress.end(steadySeconds(), image, nullptr, false,
                 "interrupted by signal " + std::to_string(signal));
    view.finish();
    const uint64_t count = static_cast<uint64_t>(std::count(done.begin(), done.end(), true));
    if (count > 0) {
      save(image);
      std::fprintf(stderr, "prt: interrupted by signal %d; %llu of %llu pixels are saved in '%s'\n",
                   signal, static_cast<unsigned long long>(count),
                   static_cast<unsigned long long>(done.size()), o.checkpointPath.c_str());
      tellHowToResume(o);
    } else {
      std::fprintf(stderr, "prt: interrupted by signal %d before any pixel was done\n", signal);
    }
    return 128 + signal;
  }
  progress.end(steadySeconds(), image, nullptr, true,
               "written to " + scene.image.output, 0);
  try {
    writeImage(image, scene.image.output, o.imageOptions);
  } catch (const std::exception& e) {
    view.stopLines();
    keepPixelsOfUnwrittenImage(o, key, TaskSet::range(0, image.pixelCount()), image, {}, e);
  }
  if (armed) removeCheckpoint(o.checkpointPath);
  view.finish();
  if (!o.costMapPath.empty()) {
    writeCostMapFile(o.costMapPath,
                     CostMap(scene.image.width, scene.image.height, std::move(pixelSeconds)));
  }
  if (!o.quiet) {
    std::printf("%s: %dx%d, %d spp, DRT %d, %.3f s, %llu rays, %.2f Mrays/s\n",
                scene.image.output.c_str(), scene.image.width, scene.image.height,
                settings.samplesPerPixel, settings.drtRate, stats.seconds,
                static_cast<unsigned long long>(stats.rays),
                stats.seconds > 0 ? static_cast<double>(stats.rays) / stats.seconds / 1e6 : 0.0);
  }
  warnOfNonFiniteSamples(renderer.nonFiniteSamples());
  return 0;
}

int runRender(const RenderOptions& o) {
  checkHtmlPath(o.htmlPath);
  const bool mpi = launchedByMpirun();
  if ((mpi || o.workers || o.strategyFlags.strategy) && !o.costMapPath.empty()) {
    throw InputError("--cost-map records a serial render; drop --workers and --strategy (and "
                     "run without mpirun)");
  }
  if (!o.costMapPath.empty() && framesOf(o).count() > 1) {
    throw InputError("--cost-map records one frame: use --frame N (prt simulate reuses that "
                     "map for every frame of a sequence)");
  }
  if (mpi && o.workers) {
    throw InputError("--workers cannot be used under mpirun: the worker count is the number of "
                     "ranks minus one (rank 0 is the master)");
  }
  if (mpi && !o.joinAt.empty()) {
    throw InputError("--join-at starts threads that join a local render; under mpirun, add "
                     "workers with --accept-workers FILE and `mpirun -np K prt join FILE`");
  }
  if (!o.acceptAddress.empty()) {
    if (o.acceptWorkersPath.empty()) {
      throw InputError("--accept-address says where --accept-workers listens: add "
                       "--accept-workers FILE");
    }
    parseDoorAddress(o.acceptAddress);  // a mistake is reported before anything renders
  }
  if (!mpi && !o.acceptWorkersPath.empty() && !o.joinAt.empty()) {
    throw InputError("--accept-workers and --join-at cannot be combined in a local render: "
                     "workers that join come from other machines (prt join FILE) or from "
                     "--join-at, not both");
  }
  // --- MPI hook: only rank 0 reads the scene file; the workers get the scene from it.
  if (mpi) {
    return renderParallelMpi(o, [&] {
      Scene scene = loadScene(o.scene);
      const RenderSettings settings = resolveSettings(o, scene);
      checkOutputs(o, scene);
      checkVideo(o, framesOf(o));
      return std::pair{std::move(scene), settings};
    });
  }
  // --- end MPI hook
  Scene scene = loadScene(o.scene);
  const RenderSettings settings = resolveSettings(o, scene);
  const bool parallel = o.workers || o.strategyFlags.strategy;
  for (const bool parallelOnly : {!o.reportPath.empty(), !o.tracePath.empty(),
                                  !o.ownershipPath.empty(), !o.htmlPath.empty(),
                                  !o.slowdowns.empty(), !o.faults.empty(), !o.joinAt.empty(),
                                  !o.acceptWorkersPath.empty()}) {
    if (parallelOnly && !parallel) {
      throw InputError("--report, --trace, --ownership, --html, --slowdown, --join-at, "
                       "--accept-workers and --inject-fault describe a parallel run; add "
                       "--workers N (and optionally --strategy NAME)");
    }
  }
  checkOutputs(o, scene);
  checkVideo(o, framesOf(o));
  // A serial sequence writes each frame as it is done; it keeps a checkpoint when asked.
  const bool serialSequence = !parallel && framesOf(o).count() > 1;
  const RenderOptions planned =
      serialSequence && o.checkpointPath.empty() && !o.resume ? o : withCheckpointPlan(o, scene);
  if (parallel) return renderParallelLocal(planned, scene, settings);
  if (!planned.checkpointPath.empty() && (!planned.checkpointAutomatic || planned.resume)) {
    return renderSerialWithCheckpoint(planned, scene, settings);
  }
  if (planned.resume) {
    throw InputError("--resume continues from a checkpoint, and --no-checkpoint keeps none: "
                     "drop one of them (or name the file with --checkpoint FILE)");
  }
  return renderSerial(planned, scene, settings);
}

}  // namespace

Action addRenderCommand(CLI::App& app, const std::string& commandLine) {
  auto o = std::make_shared<RenderOptions>();
  o->commandLine = commandLine;
  auto* cmd = app.add_subcommand(
      "render",
      "Render a .scene file or a model file (glTF, OBJ, FBX, ...) to an image, serially or in "
      "parallel (--workers N, or under "
      "mpirun with rank 0 as the master)");
  addSceneSource(*cmd, o->scene);
  cmd->add_option("-o,--output", o->output,
                  "Output image; the extension picks the format (.png, .jpg, .exr, .pfm, .ppm). "
                  "Default: the scene's output file")
      ->check(fileName());
  cmd->add_option("--width", o->width,
                  "Image width in pixels (alone: the height follows the scene's aspect ratio)")
      ->check(CLI::Range(1, 32768));
  cmd->add_option("--height", o->height,
                  "Image height in pixels (alone: the width follows the scene's aspect ratio)")
      ->check(CLI::Range(1, 32768));
  cmd->add_flag("--exr-half", o->imageOptions.exrHalf,
                "Write .exr images as 16-bit half floats (default: 32-bit floats, every bit "
                "kept)");
  cmd->add_option("--jpeg-quality", o->imageOptions.jpegQuality,
                  "Quality of .jpg images, 1 (smallest) to 100 (best)")
      ->check(CLI::Range(1, 100))
      ->capture_default_str();
  cmd->add_option("--spp", o->spp, "Supersampling: samples per pixel (SS)")
      ->check(CLI::Range(1, 4096));
  cmd->add_option("--drt", o->drt,
                  "Distributed ray tracing rate: rays per glossy reflection, blurry "
                  "transmission and area light at each hit (DRT)")
      ->check(CLI::Range(1, 64));
  cmd->add_option("--integrator", o->integrator,
                  "hall: the paper's ray tracer (Whitted, Hall's model); path: the physically "
                  "based path tracer (next-event estimation, multiple importance sampling, "
                  "glTF's metallic-roughness materials). Default: the scene's own (environment "
                  "{ integrator ... }): path for a model file rendered directly, hall for a "
                  ".scene file that does not say")
      ->check(CLI::IsMember({"hall", "path"}));
  cmd->add_option("--environment", o->environment,
                  "An HDR environment map around the scene, in place of its world colour: an "
                  "equirectangular image of linear radiance, Radiance .hdr or OpenEXR .exr "
                  "(Blender's layout: the centre looks along +x, y is up). Lights both "
                  "integrators; the path tracer also samples it by its brightness");
  cmd->add_option("--environment-strength", o->environmentStrength,
                  "Multiplies the environment map's radiance (default 1, or the scene's "
                  "map_strength)")
      ->check(CLI::Range(0.0, 1e6));
  cmd->add_option("--environment-rotate", o->environmentRotate,
                  "Turns the environment map about the up axis by this many degrees (what it "
                  "showed at azimuth a, from +x towards +z, it shows at a + DEG)")
      ->check(CLI::Range(-1e6, 1e6));
  cmd->add_option("--case", o->testCase,
                  "The paper's test cases: A (DRT 1, SS 8), B (1, 16), C (2, 8), D (2, 16); "
                  "--spp and --drt override")
      ->check(CLI::IsMember({"A", "B", "C", "D"}));
  cmd->add_option("--threads", o->threads,
                  "Rendering threads: of a serial render (0: all cores), or of each worker of a "
                  "parallel one (0: one for each local worker; under mpirun, every CPU the "
                  "rank may use, as --bind-to sets it)")
      ->check(CLI::Range(0, 1024))
      ->capture_default_str();
  cmd->add_flag("-q,--quiet", o->quiet, "No progress lines, summary or report table");
  cmd->add_option("--serve", o->serve,
                  "While rendering, serve a live page of the render at [HOST:]PORT (the image "
                  "so far, each worker's progress, the ETA; /status.json for scripts). "
                  "Loopback by default; any other HOST needs the access token it prints. "
                  "PORT 0: any free port");
  const std::string animation = "Animation";
  cmd->add_option("--frames", o->frames,
                  "Render frames A to B (every STEP-th) of an animated scene as one job, each "
                  "written to the -o pattern with its number for the '#'s (frame_####.png)")
      ->group(animation);
  cmd->add_option("--frame", o->frame, "Render frame N of an animated scene alone")
      ->group(animation);
  cmd->add_option("--fps", o->fps, "Frames per second: frame N is the scene at N / FPS seconds")
      ->capture_default_str()
      ->group(animation);
  cmd->add_option("--video", o->videoPath,
                  "Once every frame is written, make them into a video FILE with ffmpeg at the "
                  "animation's speed (.mp4, .mkv, .mov: H.264; .webm, .gif, ...: ffmpeg's "
                  "choice)")
      ->check(fileName())
      ->group(animation);
  cmd->add_option("--video-timeout", o->videoTimeoutSeconds,
                  "Seconds ffmpeg may go without progress (taking a frame, its video or its log "
                  "growing) before prt ends it: the run then fails, the frames stay")
      ->check(finiteIn(1, 86400))
      ->capture_default_str()
      ->group(animation);
  cmd->add_option("--cost-map", o->costMapPath,
                  "Serial render: also write each pixel's render time to FILE, the cost map "
                  "prt simulate replays (use --threads 1 for times free of contention)")
      ->check(fileName());
  addParallelOptions(*cmd, *o);
  return [o] { return runRender(*o); };
}

}  // namespace prt::cli
