// speed-index: the paper's Fig. 17. The reservoir (80 %) on emulated slow workers, once with
// the Towers of Hanoi speed index and once with a ray-tracing probe of the scene (the render
// time of one pixel in 64), comparing the MASU and ASU each gives, and how well each index
// predicts the emulated speeds (worker i is k_i times slower than the master).

#include <cmath>

#include "farm/speed_probe.h"
#include "lab/context.h"
#include "lab/experiments.h"
#include "lab/measure.h"

namespace prt {
namespace {

std::string percent(double fraction) {
  char buffer[32];
  std::snprintf(buffer, sizeof buffer, "%.1f %%", 100 * fraction);
  return buffer;
}

double relativeDifference(double a, double b) {
  return std::abs(a - b) / std::max(std::abs(a), std::abs(b));
}

}  // namespace

void runSpeedIndex(ExperimentContext& cx) {
  const Scene scene = cx.scene(96, 72);
  const std::string testCase = cx.testCase("A");
  const RenderSettings settings = cx.settings(testCase);
  const std::vector<double> slowdowns = cx.slowdowns();
  const double emulatedMasu = cx.emulatedMasu();

  cx.progress("serial time, case " + testCase);
  SerialReference serial(scene, settings);

  CsvTable workers(
      {"speed_index", "run", "worker", "slowdown", "speed_index_s", "relative_to_master", "error"});
  CsvTable runs({"speed_index", "run", "master_speed_index_s", "elapsed_s", "speedup", "efficiency",
                 "masu", "asu"});
  CsvTable table({"speed_index", "runs", "master_speed_index_s", "elapsed_s", "speedup",
                  "efficiency", "masu", "asu", "emulated_masu", "mean_index_error", "source"});
  std::vector<RunSummary> summaries;
  for (const SpeedIndexKind kind : {SpeedIndexKind::Hanoi, SpeedIndexKind::RenderProbe}) {
    const std::string name = speedIndexKindName(kind);
    const double master = serialSpeedIndexSeconds(kind, scene, settings);
    ParallelOptions options = parallelOptions("reservoir", slowdowns);
    options.speedIndexKind = kind;
    std::vector<RunReport> reports;
    std::vector<double> errors;
    for (int run = 1; run <= cx.runs(); ++run) {
      cx.progress(name + " speed index: run " + std::to_string(run) + " of " +
                  std::to_string(cx.runs()));
      reports.push_back(runReal(scene, settings, options, serial.seconds(), master));
      const RunReport& r = reports.back();
      for (const WorkerReport& w : r.workers) {
        const double relative = w.speedIndexSeconds / master;
        const double error = relative / w.slowdown - 1;
        errors.push_back(std::abs(error));
        workers.addRow({name, std::to_string(run), std::to_string(w.worker), csvNumber(w.slowdown),
                        csvNumber(w.speedIndexSeconds, 5), csvNumber(relative, 4),
                        csvNumber(error, 4)});
      }
      runs.addRow({name, std::to_string(run), csvNumber(master, 5), csvNumber(r.elapsedSeconds, 5),
                   csvNumber(r.speedup.value_or(0), 4), csvNumber(r.efficiency, 4),
                   csvNumber(r.masu, 4), csvNumber(r.asu.value_or(0), 4)});
    }
    const RunSummary s = medianSummary(reports);
    summaries.push_back(s);
    double meanError = 0;
    for (double e : errors) meanError += e / static_cast<double>(errors.size());
    table.addRow({name, std::to_string(cx.runs()), csvNumber(master, 5),
                  csvNumber(s.elapsedSeconds, 4), csvNumber(s.speedup, 4),
                  csvNumber(s.efficiency, 4), csvNumber(s.masu, 4), csvNumber(s.asu, 4),
                  csvNumber(emulatedMasu, 4), csvNumber(meanError, 4), "real"});
  }
  cx.write(table, "speed-index.csv");
  cx.write(runs, "speed-index-runs.csv");
  cx.write(workers, "speed-index-workers.csv");

  Chart chart;
  chart.kind = Chart::Kind::Bars;
  chart.title =
      "Fig. 17: speed indices, Towers of Hanoi vs a ray-tracing probe (reservoir 80 %, case " +
      testCase + ")";
  chart.yLabel = "median of " + std::to_string(cx.runs()) + " run(s)";
  chart.categories = {"MASU", "ASU", "speed-up"};
  const char* titles[] = {"Towers of Hanoi (the paper's)", "ray-tracing probe"};
  for (size_t i = 0; i < summaries.size(); ++i) {
    chart.series.push_back(
        {titles[i], {}, {summaries[i].masu, summaries[i].asu, summaries[i].speedup}, false});
  }
  chart.referenceLines = {cx.emulatedMasuLine()};
  cx.draw(chart, "speed-index.png");

  cx.say("Real runs: the reservoir (initial 80 %) on `" + cx.options().scenePath + "`, case " +
         testCase + ", " + std::to_string(scene.image.width) + "x" +
         std::to_string(scene.image.height) + ", median of " + std::to_string(cx.runs()) +
         " run(s) per speed index; serial time (one thread) " + serial.describe() + ". " +
         cx.emulationNote() + "\n\n");
  cx.say(markdownTable(table, {"speed_index", "master_speed_index_s", "elapsed_s", "speedup",
                               "efficiency", "masu", "asu", "emulated_masu", "mean_index_error"}));
  cx.say(
      "\n`mean_index_error`: how far each worker's index, relative to the master's, is from "
      "its emulated slowdown k_i (0 = a perfect predictor). The emulated MASU is the sum of "
      "1/k_i, what a perfect index would give.\n\n");
  cx.say(
      "Difference between the two indices, relative to the larger (the paper: 23.81 % for "
      "the MASU, 3.14 % for the ASU): MASU " +
      percent(relativeDifference(summaries[0].masu, summaries[1].masu)) + ", ASU " +
      percent(relativeDifference(summaries[0].asu, summaries[1].asu)) + ".\n");
}

}  // namespace prt
