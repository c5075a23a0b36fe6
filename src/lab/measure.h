#pragma once
// The measurements experiments repeat: serial renders (the paper's SRT, one thread), real
// parallel runs under the local driver, simulated runs of the same configuration, and the
// medians and CSV cells of their reports.
// Reads clocks (through the renderer and the drivers); not thread-safe.

#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "farm/parallel_options.h"
#include "metrics/run_report.h"
#include "sim/cost_map.h"
#include "trace/render_settings.h"
#include "trace/scene.h"

namespace prt {

struct SerialMeasurement {
  std::vector<double> seconds;  // one per run, one thread each
  double medianSeconds = 0;
  uint64_t rays = 0;               // rays of one run (the same every run)
  std::optional<CostMap> costMap;  // the first run's per-pixel seconds, when asked for
};

SerialMeasurement measureSerial(const Scene& scene, const RenderSettings& settings, int runs,
                                bool recordCostMap);

// The serial time parallel runs are compared with, kept fresh. On a shared machine whose
// speed drifted by a third within minutes, a serial time measured once at the start made
// later speed-ups exceed what the workers could deliver; so seconds() renders serially again
// (one thread) whenever the last measurement is older than maxAgeSeconds, and each parallel
// run is compared with the serial render nearest to it in time.
class SerialReference {
 public:
  // Measures once at once, recording the cost map.
  SerialReference(const Scene& scene, const RenderSettings& settings, double maxAgeSeconds = 60);

  double seconds();  // the current serial time, measured again first if stale
  const CostMap& costMap() const { return *first_.costMap; }  // of the first measurement
  // For summaries: "2.66 s" or "2.61 s to 2.74 s (5 measurements)".
  std::string describe() const;

 private:
  Scene scene_;
  RenderSettings settings_;
  double maxAgeSeconds_;
  SerialMeasurement first_;
  std::vector<double> all_;
  double measuredAt_ = 0;  // steady-clock seconds
};

// One real run under the local driver.
RunReport runReal(const Scene& scene, const RenderSettings& settings,
                  const ParallelOptions& options, double serialSeconds,
                  double masterSpeedIndexSeconds);

// The same configuration in the simulator, replaying `costs` (its total is the serial time):
// worker speeds 1 / slowdown, speed indices `workerSpeedIndices` (one per worker, to replay a
// real run's) or, if empty, base / speed with base the master's.
RunReport runSimulated(const CostMap& costs, const ParallelOptions& options,
                       double masterSpeedIndexSeconds,
                       const std::vector<double>& workerSpeedIndices = {});

// The report measures experiments tabulate, each the median over runs.
struct RunSummary {
  double elapsedSeconds = 0;
  double speedup = 0;
  double efficiency = 0;
  double masu = 0;
  double asu = 0;
  double messages = 0;
  double bytes = 0;
};
RunSummary medianSummary(const std::vector<RunReport>& reports);

double median(std::vector<double> values);
// The median over `reports` of field(report) (a double).
template <typename Field>
double medianOf(const std::vector<RunReport>& reports, Field field) {
  std::vector<double> values;
  values.reserve(reports.size());
  for (const RunReport& r : reports) values.push_back(field(r));
  return median(std::move(values));
}

// A CSV header and row: the leading columns `head`, then a RunSummary's, in this order:
// elapsed_s, speedup, efficiency, masu, asu, messages, bytes.
std::vector<std::string> summaryColumns(std::vector<std::string> head);
std::vector<std::string> summaryRow(std::vector<std::string> head, const RunSummary& s);

// A ParallelOptions for `strategy` on the emulated workers `slowdowns`.
ParallelOptions parallelOptions(const std::string& strategy, const std::vector<double>& slowdowns);

}  // namespace prt
