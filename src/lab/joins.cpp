// joins: machines that come free while a render runs. One slow worker starts alone and two
// faster ones join later; every strategy against the ideal for that schedule (a perfect
// balance of the serial work over the workers, each from its arrival). Simulated from the
// serial render's cost map for arrival times from the start to twice the serial time, and
// real runs (local driver, emulated speeds) with the joiners at a third of the serial time.

#include <map>

#include "balance/registry.h"
#include "lab/context.h"
#include "lab/experiments.h"
#include "lab/measure.h"

namespace prt {
namespace {

// The schedule's ideal: the first worker of `slowdowns` from 0, the others from `joinAt`,
// sharing `serialSeconds` of work perfectly.
double scheduleIdeal(const std::vector<double>& slowdowns, double joinAt, double serialSeconds) {
  std::vector<double> speeds, arrivals;
  for (size_t i = 0; i < slowdowns.size(); ++i) {
    speeds.push_back(1.0 / slowdowns[i]);
    arrivals.push_back(i == 0 ? 0.0 : joinAt);
  }
  return balancedFinishSeconds(speeds, arrivals, serialSeconds).value_or(0.0);
}

}  // namespace

void runJoins(ExperimentContext& cx) {
  const Scene scene = cx.scene(200, 150, 640, 480);
  const std::string testCase = cx.testCase("A");
  const RenderSettings settings = cx.settings(testCase);
  // The first worker starts; the others join. Default: one 4x slower, two 2x slower (1.25
  // cores' worth, which fits a 2-core machine beside the master).
  const std::vector<double> slowdowns =
      cx.options().slowdowns.empty() ? std::vector<double>{4, 2, 2} : cx.options().slowdowns;
  if (slowdowns.size() < 2) {
    throw InputError("joins: --slowdown needs at least two workers (the first starts, the "
                     "others join)");
  }
  std::vector<std::string> strategies = cx.options().strategies;
  if (strategies.empty()) {
    strategies = cx.quick() ? std::vector<std::string>{"adaptive", "self", "hybrid", "reservoir",
                                                       "scatter"}
                            : strategyNames();
  }
  const int joiners = static_cast<int>(slowdowns.size()) - 1;

  cx.progress("serial time and cost map, case " + testCase);
  SerialReference serial(scene, settings);
  const double serialSeconds = serial.seconds();
  const double masterIndex = cx.masterSpeedIndex(scene);
  auto optionsFor = [&](const std::string& strategy, double joinAt) {
    ParallelOptions o = parallelOptions(strategy, slowdowns);
    // The workers that would run a speed index report their slowdown instead (the oracle):
    // what is compared is how the work is shared, not how well a short benchmark measures.
    if (o.speedIndexKind != SpeedIndexKind::None) o.speedIndexKind = SpeedIndexKind::Slowdown;
    o.workers = 1;
    o.joins = {JoinWave{joinAt, joiners}};
    return o;
  };

  // Simulated: arrival times as fractions of the serial time.
  const std::vector<double> fractions =
      cx.quick() ? std::vector<double>{0, 0.33, 1}
                 : std::vector<double>{0, 0.1, 0.2, 0.33, 0.5, 0.75, 1, 1.5, 2};
  const double serialWork = serial.costMap().totalSeconds();
  CsvTable table({"strategy", "source", "join_at_s", "join_at_fraction", "elapsed_s", "ideal_s",
                  "elapsed_over_ideal", "own_ideal_s", "joiner_pixels", "runs"});
  std::map<std::string, std::vector<double>> simulatedRatio;
  for (const std::string& strategy : strategies) {
    cx.progress("simulated: " + strategy);
    for (double f : fractions) {
      const double joinAt = f * serialWork;
      const RunReport r = runSimulated(serial.costMap(), optionsFor(strategy, joinAt), masterIndex);
      const double ideal = scheduleIdeal(slowdowns, joinAt, serialWork);
      uint64_t joinerPixels = 0;
      for (size_t w = 1; w < r.workers.size(); ++w) joinerPixels += r.workers[w].pixels;
      simulatedRatio[strategy].push_back(r.elapsedSeconds / ideal);
      table.addRow({strategy, "simulated", csvNumber(joinAt, 4), csvNumber(f, 3),
                    csvNumber(r.elapsedSeconds, 4), csvNumber(ideal, 4),
                    csvNumber(r.elapsedSeconds / ideal, 4),
                    csvNumber(r.idealSeconds.value_or(0), 4), std::to_string(joinerPixels), "1"});
    }
  }

  // Real: the joiners at a third of the serial time, round-robin over the strategies.
  std::map<std::string, std::vector<RunReport>> real;
  std::map<std::string, std::vector<double>> realIdeals, realJoinAt;
  for (int run = 1; run <= cx.runs(); ++run) {
    for (const std::string& strategy : strategies) {
      cx.progress("real: " + strategy + ", run " + std::to_string(run) + " of " +
                  std::to_string(cx.runs()));
      const double s = serial.seconds();
      const double joinAt = s / 3;
      real[strategy].push_back(runReal(scene, settings, optionsFor(strategy, joinAt), s, masterIndex));
      realIdeals[strategy].push_back(scheduleIdeal(slowdowns, joinAt, s));
      realJoinAt[strategy].push_back(joinAt);
    }
  }
  for (const std::string& strategy : strategies) {
    std::vector<double> elapsed, ratio, own;
    uint64_t joinerPixels = 0;
    const std::vector<RunReport>& reports = real[strategy];
    for (size_t i = 0; i < reports.size(); ++i) {
      elapsed.push_back(reports[i].elapsedSeconds);
      ratio.push_back(reports[i].elapsedSeconds / realIdeals[strategy][i]);
      own.push_back(reports[i].idealSeconds.value_or(0));
      for (size_t w = 1; w < reports[i].workers.size(); ++w) {
        joinerPixels += reports[i].workers[w].pixels;
      }
    }
    table.addRow({strategy, "real", csvNumber(median(realJoinAt[strategy]), 4),
                  csvNumber(1.0 / 3, 3), csvNumber(median(elapsed), 4),
                  csvNumber(median(realIdeals[strategy]), 4), csvNumber(median(ratio), 4),
                  csvNumber(median(own), 4),
                  std::to_string(joinerPixels / std::max<size_t>(1, reports.size())),
                  std::to_string(reports.size())});
  }
  cx.write(table, "joins.csv");

  Chart chart;
  chart.title = "Simulated: elapsed over the schedule's ideal, by when the joiners arrive";
  chart.xLabel = "joiners arrive at (fraction of the serial time)";
  chart.yLabel = "elapsed / ideal";
  chart.yMin = 1;
  for (const std::string& strategy : strategies) {
    ChartSeries series{strategy, fractions, simulatedRatio[strategy],
                       strategyRow(strategy).kind == StrategyKind::Static};
    chart.series.push_back(series);
  }
  cx.draw(chart, "joins-simulated.png");

  Chart bars;
  bars.kind = Chart::Kind::Bars;
  bars.title = "Real runs: elapsed over the schedule's ideal, joiners at a third of the serial time";
  bars.yLabel = "elapsed / ideal";
  bars.yMin = 0;
  ChartSeries realSeries{"real (median)", {}, {}, false};
  for (const std::string& strategy : strategies) {
    bars.categories.push_back(strategy);
    std::vector<double> ratio;
    for (size_t i = 0; i < real[strategy].size(); ++i) {
      ratio.push_back(real[strategy][i].elapsedSeconds / realIdeals[strategy][i]);
    }
    realSeries.y.push_back(median(ratio));
  }
  bars.series.push_back(realSeries);
  bars.referenceLines.push_back({"ideal", 1.0});
  cx.draw(bars, "joins-real.png");

  std::string workers = csvNumber(slowdowns[0]);
  std::string joining;
  for (size_t i = 1; i < slowdowns.size(); ++i) {
    joining += (i > 1 ? "," : "") + csvNumber(slowdowns[i]);
  }
  cx.say("One worker (--slowdown " + workers + ") starts alone; " + std::to_string(joiners) +
         " more (--slowdown " + joining + ") join later (--join-at). The yardstick is the "
         "schedule's ideal: the serial work (" + csvNumber(serialSeconds, 4) + " s here, case " +
         testCase + " of `" + cx.options().scenePath + "` at " +
         std::to_string(scene.image.width) + "x" + std::to_string(scene.image.height) +
         ") perfectly shared, each worker from its arrival. `own_ideal_s` is the run's own "
         "`ideal_s`, from the work it did (a pixel order that costs more per pixel is measured "
         "against its own cost there). Workers that would run a speed index report their "
         "slowdown instead (the oracle), so what is compared is how the work is shared.\n\n"
         "Simulated runs replay the serial render's cost map, joiners arriving from the start "
         "to twice the serial time (joins-simulated.png). Real runs (local driver, " +
         std::to_string(cx.runs()) + " per strategy, round-robin, medians) have the joiners at "
         "a third of the serial time (joins-real.png). " +
         cx.emulationNote(slowdowns) + "\n\n");
  CsvTable realOnly(
      {"strategy", "elapsed_s", "ideal_s", "elapsed_over_ideal", "elapsed_over_own_ideal"});
  for (const std::string& strategy : strategies) {
    std::vector<double> elapsed, ratio, own;
    for (size_t i = 0; i < real[strategy].size(); ++i) {
      elapsed.push_back(real[strategy][i].elapsedSeconds);
      ratio.push_back(real[strategy][i].elapsedSeconds / realIdeals[strategy][i]);
      own.push_back(real[strategy][i].elapsedSeconds /
                    real[strategy][i].idealSeconds.value_or(real[strategy][i].elapsedSeconds));
    }
    realOnly.addRow({strategy, csvNumber(median(elapsed), 4),
                     csvNumber(median(realIdeals[strategy]), 4), csvNumber(median(ratio), 3),
                     csvNumber(median(own), 3)});
  }
  cx.say("Real runs, joiners at a third of the serial time:\n\n" + markdownTable(realOnly) +
         "\n");
}

}  // namespace prt
