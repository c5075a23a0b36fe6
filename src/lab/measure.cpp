#include "lab/measure.h"

#include <algorithm>
#include <chrono>

#include "balance/registry.h"
#include "farm/local_driver.h"
#include "lab/csv_table.h"
#include "sim/simulator.h"
#include "trace/renderer.h"

namespace prt {

SerialMeasurement measureSerial(const Scene& scene, const RenderSettings& settings, int runs,
                                bool recordCostMap) {
  SerialMeasurement m;
  const World world(scene);
  const Renderer renderer(world, settings);
  for (int run = 0; run < std::max(1, runs); ++run) {
    RenderStats stats;
    std::vector<float> pixelSeconds;
    const bool record = recordCostMap && run == 0;
    renderImage(renderer, 1, &stats, nullptr, record ? &pixelSeconds : nullptr);
    m.seconds.push_back(stats.seconds);
    m.rays = stats.rays;
    if (record) m.costMap.emplace(scene.image.width, scene.image.height, std::move(pixelSeconds));
  }
  m.medianSeconds = median(m.seconds);
  return m;
}

namespace {

double steadySeconds() {
  return std::chrono::duration<double>(std::chrono::steady_clock::now().time_since_epoch()).count();
}

}  // namespace

SerialReference::SerialReference(const Scene& scene, const RenderSettings& settings,
                                 double maxAgeSeconds)
    : scene_(scene),
      settings_(settings),
      maxAgeSeconds_(maxAgeSeconds),
      first_(measureSerial(scene, settings, 1, true)),
      all_{first_.medianSeconds},
      measuredAt_(steadySeconds()) {}

double SerialReference::seconds() {
  if (steadySeconds() - measuredAt_ > maxAgeSeconds_) {
    all_.push_back(measureSerial(scene_, settings_, 1, false).medianSeconds);
    measuredAt_ = steadySeconds();
  }
  return all_.back();
}

std::string SerialReference::describe() const {
  const auto [lo, hi] = std::minmax_element(all_.begin(), all_.end());
  if (*hi == *lo) return csvNumber(*lo, 4) + " s";
  return csvNumber(*lo, 4) + " s to " + csvNumber(*hi, 4) + " s (" + std::to_string(all_.size()) +
         " measurements, each run compared with the latest)";
}

RunReport runReal(const Scene& scene, const RenderSettings& settings,
                  const ParallelOptions& options, double serialSeconds,
                  double masterSpeedIndexSeconds) {
  LocalRunRequest request;
  request.scene = scene;
  request.settings = settings;
  request.options = options;
  request.serialSeconds = serialSeconds;
  request.masterSpeedIndexSeconds = masterSpeedIndexSeconds;
  return renderLocal(request).report;
}

namespace {

// A real run's --slowdown-at factors as the simulator's speeds (1 / factor).
std::vector<SpeedChange> speedChangesOf(const ParallelOptions& options) {
  std::vector<SpeedChange> out = options.slowdownChanges;
  for (SpeedChange& c : out) c.value = 1.0 / c.value;
  return out;
}

}  // namespace

RunReport runSimulated(const CostMap& costs, const ParallelOptions& options,
                       double masterSpeedIndexSeconds,
                       const std::vector<double>& workerSpeedIndices) {
  SimulationOptions sim;
  static_cast<RunPlan&>(sim) = options;  // strategy, batches, lease, faults, joins, endgame
  for (int w = 0; w < options.totalWorkers(); ++w) {
    sim.speeds.push_back(1.0 / options.slowdownOf(w));
  }
  sim.batchSeconds = options.batchSeconds;
  sim.baseSpeedIndexSeconds = masterSpeedIndexSeconds;
  sim.speedIndexSeconds = workerSpeedIndices;
  sim.speedIndexRun = options.speedIndexKind != SpeedIndexKind::None;
  sim.oracleSpeedIndex = options.speedIndexKind == SpeedIndexKind::Slowdown;
  sim.speedChanges = speedChangesOf(options);
  return simulate(costs, sim).report;
}

double median(std::vector<double> values) {
  if (values.empty()) return 0;
  std::sort(values.begin(), values.end());
  const size_t n = values.size();
  return n % 2 ? values[n / 2] : 0.5 * (values[n / 2 - 1] + values[n / 2]);
}

RunSummary medianSummary(const std::vector<RunReport>& reports) {
  auto of = [&](auto field) { return medianOf(reports, field); };
  RunSummary s;
  s.elapsedSeconds = of([](const RunReport& r) { return r.elapsedSeconds; });
  s.speedup = of([](const RunReport& r) { return r.speedup.value_or(0.0); });
  s.efficiency = of([](const RunReport& r) { return r.efficiency; });
  s.masu = of([](const RunReport& r) { return r.masu; });
  s.asu = of([](const RunReport& r) { return r.asu.value_or(0.0); });
  s.messages = of([](const RunReport& r) { return static_cast<double>(r.messages); });
  s.bytes = of([](const RunReport& r) { return static_cast<double>(r.bytes); });
  return s;
}

std::vector<std::string> summaryColumns(std::vector<std::string> head) {
  for (const char* c : {"elapsed_s", "speedup", "efficiency", "masu", "asu", "messages", "bytes"}) {
    head.emplace_back(c);
  }
  return head;
}

std::vector<std::string> summaryRow(std::vector<std::string> head, const RunSummary& s) {
  for (const auto& [value, digits] : {std::pair{s.elapsedSeconds, 4},
                                      {s.speedup, 4},
                                      {s.efficiency, 4},
                                      {s.masu, 4},
                                      {s.asu, 4},
                                      {s.messages, 8},
                                      {s.bytes, 10}}) {
    head.push_back(csvNumber(value, digits));
  }
  return head;
}

ParallelOptions parallelOptions(const std::string& strategy, const std::vector<double>& slowdowns) {
  ParallelOptions o;
  o.workers = static_cast<int>(slowdowns.size());
  o.strategy = strategy;
  o.slowdowns = slowdowns;
  if (!runsSpeedIndexByDefault(strategy)) o.speedIndexKind = SpeedIndexKind::None;
  return o;
}

}  // namespace prt
