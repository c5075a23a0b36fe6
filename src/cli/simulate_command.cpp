// prt simulate: a parallel run replayed in virtual time from a per-pixel cost map, with the
// real master, workers and strategies (src/sim). Prints and writes the same report and trace
// as prt render --workers N.

#include <chrono>
#include <cstdio>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "cli/commands.h"
#include "cli/parallel_render.h"
#include "cli/run_page_output.h"
#include "cli/flag_checks.h"
#include "cli/strategy_flags.h"
#include "cluster/leases.h"
#include "cluster/worker.h"
#include "core/speed_schedule.h"
#include "core/input_error.h"
#include "core/machine.h"
#include "image/atomic_file.h"
#include "metrics/chrome_trace.h"
#include "sim/cost_map_file.h"
#include "sim/simulator.h"
#include "sim/synthetic_cost.h"
#include "sim/worker_speeds.h"

namespace prt::cli {
namespace {

// RunPlanFlags: --strategy, --batch, --worker-timeout, --endgame, --inject-fault, --join-at,
// as in prt render.
struct SimulateOptions : RunPlanFlags {
  int workers = 4;
  std::optional<int> width;   // default: the cost map's, or 640 for the synthetic one
  std::optional<int> height;  // default: the cost map's, or 480
  std::string speedIndexRun = "auto";   // on | off | auto (off for the adaptive strategies)
  std::string speedAt;                  // --speed-at W:T:SPEED,...
  std::string slowdownAt;               // --slowdown-at W:T:K,..., as prt render's
  std::vector<double> speeds;           // per worker; empty: see slowShare, lognormal, else all 1
  std::optional<double> slowShare;      // fraction of the workers that are slow
  double slowFactor = 4;                // how many times slower they are
  std::optional<double> lognormal;      // sigma of log-normal speeds
  unsigned long long seed = 1;          // for --slow-share and --lognormal
  std::string costMapPath;              // empty: the synthetic complex-scene map
  uint64_t frames = 1;                  // --frames N: a sequence of N frames, the map reused
  std::optional<double> serialSeconds;  // rescale the map to this total; synthetic default 60
  double batchSeconds = 0;
  double batchOverheadMicroseconds = 0;
  double speedIndexSeconds = 0.08;
  std::vector<double> speedIndices;  // per worker, replaying a real run's measurements
  double latencyMicroseconds = 50;
  double bandwidthMbps = 1000;
  double masterServiceMicroseconds = 5;
  double mtbfSeconds = 0;                      // --mtbf
  std::optional<double> failShare;             // --fail-share, with --fail-at
  std::optional<double> failAtSeconds;
  double repairSeconds = 0;                    // --repair
  double checkpointEverySeconds = 0;           // --checkpoint-every (0: none)
  double checkpointNanosecondsPerPixel = kCheckpointSecondsPerPixel * 1e9;
  std::string reportPath;
  std::string tracePath;
  std::string htmlPath;     // the run's page
  std::string commandLine;  // as typed, for the report and the page
  bool quiet = false;
};

constexpr double kDefaultSerialSeconds = 60;

CostMap loadCostMap(const SimulateOptions& o, std::string& source) {
  if (o.costMapPath.empty()) {
    const int width = o.width.value_or(640);
    const int height = o.height.value_or(480);
    // As prt render: beyond 2^28 pixels the map alone takes gigabytes and the run hours.
    if (static_cast<uint64_t>(width) * static_cast<uint64_t>(height) > (uint64_t{1} << 28)) {
      throw InputError("image too large: " + std::to_string(width) + "x" +
                       std::to_string(height) + " exceeds 2^28 pixels");
    }
    source = "synthetic complex-scene cost map";
    return complexSceneCostMap(width, height, o.serialSeconds.value_or(kDefaultSerialSeconds));
  }
  CostMap map = readCostMapFile(o.costMapPath);
  if ((o.width && *o.width != map.width()) || (o.height && *o.height != map.height())) {
    throw InputError("cost map '" + o.costMapPath + "' is " + std::to_string(map.width()) + "x" +
                     std::to_string(map.height()) + " pixels but --width/--height ask for " +
                     std::to_string(o.width.value_or(map.width())) + "x" +
                     std::to_string(o.height.value_or(map.height())) +
                     "; drop them or record a map of that size");
  }
  source = "cost map " + o.costMapPath;
  return o.serialSeconds ? map.scaledTo(*o.serialSeconds) : map;
}

// One speed per worker, those that join (--join-at) included.
std::vector<double> workerSpeeds(const SimulateOptions& o, int joiners) {
  const int all = o.workers + joiners;
  const int given = (o.speeds.empty() ? 0 : 1) + (o.slowShare ? 1 : 0) + (o.lognormal ? 1 : 0);
  if (given > 1) {
    throw InputError("give at most one of --speeds, --slow-share and --lognormal");
  }
  if (!o.speeds.empty()) {
    validateWorkerSpeeds(o.speeds, all);
    return o.speeds;
  }
  if (o.slowShare) return slowShareSpeeds(all, *o.slowShare, o.slowFactor, o.seed);
  if (o.lognormal) return lognormalSpeeds(all, *o.lognormal, o.seed);
  return uniformSpeeds(all);
}

int runSimulate(const SimulateOptions& o) {
  SimulationOptions options;
  static_cast<RunPlan&>(options) = runPlanFrom(o, o.workers);
  options.speeds = workerSpeeds(o, options.joinerCount());
  const int everyWorker = static_cast<int>(options.speeds.size());
  if (!o.speedAt.empty()) {
    options.speedChanges = parseSpeedChanges(o.speedAt, "--speed-at", everyWorker, 0);
  }
  if (!o.slowdownAt.empty()) {
    // prt render's form: K times slower than full speed (the cost map's machine) from T on.
    for (SpeedChange c : parseSpeedChanges(o.slowdownAt, "--slowdown-at", everyWorker, 1)) {
      c.value = 1 / c.value;
      options.speedChanges.push_back(c);
    }
  }
  if (o.speedIndexRun != "auto" && o.speedIndexRun != "on" && o.speedIndexRun != "off") {
    throw InputError("--speed-index-run '" + o.speedIndexRun + "': expected on, off or auto");
  }
  options.speedIndexRun = o.speedIndexRun == "auto" ? runsSpeedIndexByDefault(options.strategy)
                                                    : o.speedIndexRun == "on";
  options.batchSeconds = o.batchSeconds;
  options.batchOverheadSeconds = o.batchOverheadMicroseconds * 1e-6;
  options.baseSpeedIndexSeconds = o.speedIndexSeconds;
  options.speedIndexSeconds = o.speedIndices;
  options.network.latencySeconds = o.latencyMicroseconds * 1e-6;
  options.network.bandwidthBytesPerSecond = o.bandwidthMbps * 1e6 / 8;
  options.network.masterServiceSeconds = o.masterServiceMicroseconds * 1e-6;
  options.mtbfSeconds = o.mtbfSeconds;
  if (o.failShare.has_value() != o.failAtSeconds.has_value()) {
    throw InputError("--fail-share F and --fail-at T go together: a fraction F of the workers "
                     "fails at T seconds");
  }
  options.failShare = o.failShare.value_or(0);
  options.failAtSeconds = o.failAtSeconds.value_or(0);
  options.repairSeconds = o.repairSeconds;
  options.checkpointEverySeconds = o.checkpointEverySeconds;
  options.checkpointSecondsPerPixel = o.checkpointNanosecondsPerPixel * 1e-9;
  options.seed = o.seed;
  // Cheap checks before building the map: a 4K synthetic map takes a moment.
  validateSimulationOptions(options, ~0ull);
  checkHtmlPath(o.htmlPath);

  std::string source;
  CostMap costs = loadCostMap(o, source);
  if (o.frames > 1) {
    // The same frame N times over, one above the other: the sequence's tasks (a scene whose
    // cost changes from frame to frame is beyond one map; the balance across frames is not).
    if (costs.pixelCount() * o.frames > (1ull << 30)) {
      throw InputError("--frames " + std::to_string(o.frames) + " of " +
                       std::to_string(costs.width()) + "x" + std::to_string(costs.height()) +
                       " exceed the 2^30 pixels one job may hold");
    }
    std::vector<float> all;
    all.reserve(costs.pixelCount() * o.frames);
    for (uint64_t f = 0; f < o.frames; ++f) {
      all.insert(all.end(), costs.secondsPerPixel().begin(), costs.secondsPerPixel().end());
    }
    costs = CostMap(costs.width(), costs.height() * static_cast<int>(o.frames), std::move(all));
    source += ", " + std::to_string(o.frames) + " frames";
    options.frames = o.frames;
  }
  const auto start = std::chrono::steady_clock::now();
  const SimulatedRun run = simulate(costs, options);
  const double wall =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();

  if (!o.reportPath.empty() || !o.htmlPath.empty()) {
    RunContext context;
    context.commandLine = o.commandLine;
    context.scene = source;
    context.machine = describeMachine() + " (the simulation's; the workers are modelled)";
    context.dateUtc = utcNow();
    context.parameters = strategyParameters(options.strategy, options.strategyOptions);
    context.parameters.emplace_back("batch_pixels", std::to_string(o.batchPixels));
    context.parameters.emplace_back("batch_overhead_us",
                                    parameterText(o.batchOverheadMicroseconds));
    context.parameters.emplace_back("latency_us", parameterText(o.latencyMicroseconds));
    context.parameters.emplace_back("bandwidth_mbps", parameterText(o.bandwidthMbps));
    context.parameters.emplace_back("master_service_us",
                                    parameterText(o.masterServiceMicroseconds));
    for (const auto& [name, path] :
         {std::pair<const char*, const std::string&>{"cost_map", o.costMapPath},
          {"report", o.reportPath},
          {"html", o.htmlPath},
          {"trace", o.tracePath}}) {
      if (!path.empty()) context.outputs.emplace_back(name, path);
    }
    writeReportAndPage(o.reportPath, o.htmlPath,
                       reportDocument(run.report, context, run.events, run.owner),
                       o.htmlPath.empty() ? PagePicture{} : costPicture(costs));
  }
  if (!o.tracePath.empty()) {
    writeFileAtomically(o.tracePath,
                        chromeTraceJson(run.events, static_cast<int>(run.report.workers.size()),
                                        run.report.elapsedSeconds));
  }
  if (!o.quiet) {
    std::printf("simulated %dx%d, %s (%.3f s serial); %llu events in %.3f s of wall time\n%s",
                costs.width(), costs.height(), source.c_str(), costs.totalSeconds(),
                static_cast<unsigned long long>(run.simulationEvents), wall,
                run.report.toTable().c_str());
  }
  return 0;
}

}  // namespace

Action addSimulateCommand(CLI::App& app, const std::string& commandLine) {
  auto o = std::make_shared<SimulateOptions>();
  o->commandLine = commandLine;
  auto* cmd = app.add_subcommand(
      "simulate",
      "Simulate a parallel render in virtual time: the real master, workers and strategies "
      "replaying a per-pixel cost map (prt render SCENE --cost-map FILE) on workers of given "
      "speeds and a network model; no rendering");
  cmd->add_option("--workers", o->workers, "Number of workers")
      ->check(CLI::Range(1, 1 << 20))
      ->capture_default_str();
  cmd->add_option("--width", o->width,
                  "Image width (synthetic map: default 640; with --cost-map: must match)")
      ->check(CLI::Range(1, 32768));
  cmd->add_option("--height", o->height,
                  "Image height (synthetic map: default 480; with --cost-map: must match)")
      ->check(CLI::Range(1, 32768));
  addStrategyFlags(*cmd, o->strategyFlags, "Strategy");
  cmd->add_option("--speed-index-run", o->speedIndexRun,
                  "Whether the workers run a speed index first: on, off (they start at once; "
                  "MASU and ASU then come from measured throughput) or auto (off for the "
                  "adaptive strategies)")
      ->capture_default_str()
      ->group("Strategy");

  const std::string speeds = "Worker speeds (default: all 1)";
  cmd->add_option("--speeds", o->speeds,
                  "Comma-separated relative speeds, one per worker: 1 full speed (the cost "
                  "map's machine), 0.5 twice as slow (a real run's --slowdown 2)")
      ->delimiter(',')
      ->group(speeds);
  auto* slowShare =
      cmd->add_option("--slow-share", o->slowShare,
                      "Fraction in [0, 1] of the workers, picked at random (--seed), that run "
                      "--slow-factor times slower")
          ->group(speeds);
  cmd->add_option("--slow-factor", o->slowFactor, "How many times slower the slow share runs")
      ->capture_default_str()
      ->needs(slowShare)
      ->group(speeds);
  cmd->add_option("--lognormal", o->lognormal,
                  "Log-normal speeds exp(SIGMA * z), median 1, drawn with --seed")
      ->group(speeds);
  cmd->add_option("--speed-at", o->speedAt,
                  "Speeds that change mid-run: W:T:SPEED,... makes worker W run at relative "
                  "speed SPEED (> 0) from T virtual seconds on")
      ->group(speeds);
  cmd->add_option("--slowdown-at", o->slowdownAt,
                  "As prt render's: W:T:K,... makes worker W run K times slower than full "
                  "speed (K >= 1, speed 1/K) from T virtual seconds on")
      ->group(speeds);
  cmd->add_option("--seed", o->seed, "Seed for --slow-share, --lognormal, --mtbf and --fail-share")
      ->capture_default_str()
      ->group(speeds);

  const std::string model = "Cost and network model";
  cmd->add_option("--frames", o->frames,
                  "Simulate a sequence of N frames as one job, each costing what the map says "
                  "(the map reused for every frame)")
      ->check(CLI::Range(1ull, 1ull << 20));
  cmd->add_option("--cost-map", o->costMapPath,
                  "Per-pixel costs recorded by prt render SCENE --cost-map FILE (default: a "
                  "synthetic map shaped like scenes/complex.scene)")
      ->group(model);
  cmd->add_option("--serial-seconds", o->serialSeconds,
                  "Scale the map to this serial time, seconds (synthetic default 60; a "
                  "recorded map keeps its own total)")
      ->check(positiveUpTo(1e9, "seconds"))
      ->group(model);
  cmd->add_option("--batch-seconds", o->batchSeconds,
                  "Batches grow past --batch pixels to what a worker renders in S simulated "
                  "seconds at its last batch's rate, as prt render's do (its default: 0.03); "
                  "0 keeps every batch --batch pixels")
      ->check(finiteIn(0, 60))
      ->capture_default_str()
      ->group(model);
  cmd->add_option("--batch-overhead-us", o->batchOverheadMicroseconds,
                  "Full-speed microseconds each batch costs besides its pixels (result "
                  "packing, cold caches), scaled by 1 / speed like the pixels")
      ->capture_default_str()
      ->group(model);
  cmd->add_option("--speed-index", o->speedIndexSeconds,
                  "Speed index of a full-speed worker and of the serial machine, seconds")
      ->capture_default_str()
      ->group(model);
  cmd->add_option("--speed-indices", o->speedIndices,
                  "Comma-separated speed indices, one per worker, to replay those a real run "
                  "measured (its report's speed_index_s); default --speed-index / speed")
      ->delimiter(',')
      ->group(model);
  cmd->add_option("--latency-us", o->latencyMicroseconds, "One-way message latency, microseconds")
      ->capture_default_str()
      ->group(model);
  cmd->add_option("--bandwidth-mbps", o->bandwidthMbps,
                  "Link bandwidth per endpoint and direction, Mbit/s")
      ->capture_default_str()
      ->group(model);
  cmd->add_option("--master-service-us", o->masterServiceMicroseconds,
                  "Master busy time per received message, microseconds (a heartbeat, in or "
                  "out, costs half of it)")
      ->capture_default_str()
      ->group(model);

  const std::string failures = "Failures";
  cmd->add_option("--mtbf", o->mtbfSeconds,
                  "Mean time between failures, virtual seconds: each starting worker's machine "
                  "fails once, at an exponentially distributed time (--seed), silently")
      ->check(finiteIn(0, 1e12))
      ->group(failures);
  cmd->add_option("--fail-share", o->failShare,
                  "With --fail-at T: this fraction of the workers, picked at random (--seed), "
                  "fails together at T (a switch or a rack lost)")
      ->check(CLI::Range(0.0, 1.0))
      ->group(failures);
  cmd->add_option("--fail-at", o->failAtSeconds, "When --fail-share's machines fail, seconds")
      ->check(finiteIn(0, 1e12))
      ->group(failures);
  cmd->add_option("--repair", o->repairSeconds,
                  "A machine that failed (--mtbf, --fail-share) comes back this many seconds "
                  "later, as a new worker joining the run; with --mtbf it may fail again")
      ->check(finiteIn(0, 1e12))
      ->group(failures);
  cmd->add_option("--checkpoint-every", o->checkpointEverySeconds,
                  "As prt render's: the master writes a checkpoint every S seconds and takes no "
                  "message while it writes (0: no checkpoints, the default here; prt render "
                  "writes them every 10 s once a render is expected to take over 30 s)")
      ->check(finiteIn(0, 86400))
      ->capture_default_str()
      ->group(failures);
  cmd->add_option("--checkpoint-ns-per-pixel", o->checkpointNanosecondsPerPixel,
                  "What a checkpoint costs the master per pixel done, nanoseconds (measured: "
                  "about 100 for a 3840x2160 image)")
      ->check(finiteIn(0, 1e6))
      ->capture_default_str()
      ->group(failures);
  addRunPlanFlags(*cmd, *o, {model, speeds, failures, /*simulated=*/true});

  cmd->add_option("--report", o->reportPath, "Write the run report as JSON")->check(fileName());
  cmd->add_option("--trace", o->tracePath, "Write a Chrome trace-event timeline (Perfetto)")
      ->check(fileName());
  cmd->add_option("--html", o->htmlPath,
                  "Write the run's page: one self-contained HTML file with the cost map, the "
                  "ownership map, the timeline and the measures")
      ->check(fileName());
  cmd->add_flag("-q,--quiet", o->quiet, "No report table");
  return [o] { return runSimulate(*o); };
}

}  // namespace prt::cli
