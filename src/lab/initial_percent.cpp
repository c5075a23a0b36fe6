// initial-percent: the paper's Fig. 18. Reservoir speed-up and efficiency against the initial
// percentage, real runs on emulated slow workers and the same configurations simulated from
// the serial render's cost map, for the paper's reservoir and for reservoir-scatter.

#include <map>

#include "balance/registry.h"
#include "lab/context.h"
#include "lab/experiments.h"
#include "lab/measure.h"

namespace prt {

void runInitialPercent(ExperimentContext& cx) {
  const Scene scene = cx.scene(64, 48);
  const std::string testCase = cx.testCase("C");
  const RenderSettings settings = cx.settings(testCase);
  const std::vector<double> slowdowns = cx.slowdowns();
  const std::vector<double> percents =
      cx.quick() ? std::vector<double>{20, 80, 100}
                 : std::vector<double>{5, 10, 20, 30, 40, 50, 60, 70, 75, 80, 90, 100};
  const std::vector<std::string> strategies = strategiesTaking("initial-percent");

  cx.progress("serial time and cost map, case " + testCase);
  SerialReference serial(scene, settings);
  const double masterIndex = cx.masterSpeedIndex(scene);

  CsvTable table(summaryColumns({"strategy", "initial_percent", "source", "runs"}));
  CsvTable runs({"strategy", "initial_percent", "run", "serial_s", "elapsed_s", "speedup",
                 "efficiency", "asu"});
  auto optionsFor = [&](const std::string& strategy, double percent) {
    ParallelOptions options = parallelOptions(strategy, slowdowns);
    options.strategyOptions.initialPercent = percent;
    return options;
  };
  // Real runs round-robin over every configuration, so that a noisy spell on the machine
  // hits them alike; reports[strategy][percent index].
  std::map<std::string, std::vector<std::vector<RunReport>>> reports;
  for (const std::string& strategy : strategies) reports[strategy].resize(percents.size());
  for (int run = 1; run <= cx.runs(); ++run) {
    for (size_t i = 0; i < percents.size(); ++i) {
      for (const std::string& strategy : strategies) {
        const double p = percents[i];
        cx.progress(strategy + " at " + csvNumber(p) + " %: run " + std::to_string(run) + " of " +
                    std::to_string(cx.runs()));
        const double serialSeconds = serial.seconds();
        const RunReport r =
            runReal(scene, settings, optionsFor(strategy, p), serialSeconds, masterIndex);
        runs.addRow({strategy, csvNumber(p), std::to_string(run), csvNumber(serialSeconds, 5),
                     csvNumber(r.elapsedSeconds, 5), csvNumber(r.speedup.value_or(0), 4),
                     csvNumber(r.efficiency, 4), csvNumber(r.asu.value_or(0), 4)});
        reports[strategy][i].push_back(r);
      }
    }
  }

  Chart speedup, efficiency;
  struct Best {
    double speedup = -1, percent = 0;
  };
  std::map<std::string, std::map<std::string, Best>> best;  // [strategy][source]
  for (const std::string& strategy : strategies) {
    ChartSeries realSpeedup{strategy + " (real)", {}, {}, false};
    ChartSeries simSpeedup{strategy + " (simulated)", {}, {}, true};
    ChartSeries realEfficiency = realSpeedup, simEfficiency = simSpeedup;
    for (size_t i = 0; i < percents.size(); ++i) {
      const double p = percents[i];
      const RunSummary real = medianSummary(reports[strategy][i]);
      const RunSummary sim =
          medianSummary({runSimulated(serial.costMap(), optionsFor(strategy, p), masterIndex)});
      for (const auto& [source, s] : {std::pair{"real", real}, std::pair{"simulated", sim}}) {
        table.addRow(summaryRow({strategy, csvNumber(p), source,
                                 source == std::string("real") ? std::to_string(cx.runs()) : "1"},
                                s));
        Best& b = best[strategy][source];
        if (s.speedup > b.speedup) b = {s.speedup, p};
      }
      for (ChartSeries* series : {&realSpeedup, &simSpeedup, &realEfficiency, &simEfficiency}) {
        series->x.push_back(p);
      }
      realSpeedup.y.push_back(real.speedup);
      simSpeedup.y.push_back(sim.speedup);
      realEfficiency.y.push_back(100 * real.efficiency);
      simEfficiency.y.push_back(100 * sim.efficiency);
    }
    speedup.series.push_back(realSpeedup);
    speedup.series.push_back(simSpeedup);
    efficiency.series.push_back(realEfficiency);
    efficiency.series.push_back(simEfficiency);
  }
  cx.write(table, "initial-percent.csv");
  cx.write(runs, "initial-percent-runs.csv");

  const std::string where =
      "case " + testCase + ", " + std::to_string(slowdowns.size()) + " workers";
  speedup.title = "Fig. 18: speed-up against the initial percentage (" + where + ")";
  speedup.xLabel = "initial percentage";
  speedup.yLabel = "speed-up (serial time / parallel time)";
  speedup.yMin = 0;
  speedup.referenceLines = {cx.emulatedMasuLine()};
  cx.draw(speedup, "initial-percent-speedup.png");
  efficiency.title = "Fig. 18: efficiency against the initial percentage (" + where + ")";
  efficiency.xLabel = "initial percentage";
  efficiency.yLabel = "efficiency, %";
  efficiency.yMin = 0;
  efficiency.yMax = 100;
  cx.draw(efficiency, "initial-percent-efficiency.png");

  // The best percentage by real speed-up, per strategy.
  cx.say("The reservoir against its initial percentage on `" + cx.options().scenePath + "`, case " +
         testCase + ", " + std::to_string(scene.image.width) + "x" +
         std::to_string(scene.image.height) +
         ". Rows with source `real` are real runs (median "
         "of " +
         std::to_string(cx.runs()) +
         "); `simulated` rows replay the serial render's "
         "cost map in the simulator with the same worker speeds (no emulation overhead). "
         "Serial time (one thread, measured again whenever the last was a minute old) " +
         serial.describe() + ". " + cx.emulationNote() + "\n\n");
  for (const std::string& strategy : strategies) {
    for (const char* source : {"real", "simulated"}) {
      const Best& b = best[strategy][source];
      cx.say("- " + strategy + ", " + source + ": best speed-up " + csvNumber(b.speedup, 3) +
             " at " + csvNumber(b.percent) + " %\n");
    }
  }
  cx.say("\n" + markdownTable(table, {"strategy", "initial_percent", "source", "elapsed_s",
                                      "speedup", "efficiency", "asu"}));
}

}  // namespace prt
