// compare: the paper's Figs. 19-21. Speed-up, efficiency and ASU of every strategy on test
// cases A-D, real runs on emulated slow workers and the same configurations simulated from
// each case's serial cost map; and the paper's headline claims (reservoir up to 87 % better
// speed-up than scatter, 36 % than hybrid; 28 % better efficiency than scatter; 25 % and
// 10 % better ASU) recomputed from our figures. One more case, the first case "-slowing",
// studies speeds that change mid-render: worker 0 becomes four times slower than its
// --slowdown at a third of the ideal parallel time.

#include <algorithm>
#include <map>

#include "balance/registry.h"
#include "lab/context.h"
#include "lab/experiments.h"
#include "lab/measure.h"

namespace prt {
namespace {

struct Claim {
  const char* measure;  // speedup, efficiency, asu
  const char* other;    // scatter, hybrid
  double paper;         // the paper's "at most X % better"
};
constexpr Claim kClaims[] = {{"speedup", "scatter", 87},
                             {"speedup", "hybrid", 36},
                             {"efficiency", "scatter", 28},
                             {"asu", "scatter", 25},
                             {"asu", "hybrid", 10}};

double field(const RunSummary& s, const std::string& measure) {
  if (measure == "speedup") return s.speedup;
  if (measure == "efficiency") return s.efficiency;
  return s.asu;
}

}  // namespace

void runCompare(ExperimentContext& cx) {
  std::vector<std::string> cases = cx.options().cases;
  if (cases.empty())
    cases = cx.quick() ? std::vector<std::string>{"A", "C"}
                       : std::vector<std::string>{"A", "B", "C", "D"};
  std::vector<std::string> strategies = cx.options().strategies;
  if (strategies.empty()) strategies = strategyNames();
  const Scene scene = cx.scene(64, 48);
  const std::vector<double> slowdowns = cx.slowdowns();
  const double masterIndex = cx.masterSpeedIndex(scene);

  // The changing-speed case: the first case again, worker 0 slowing down part-way.
  const std::string slowing = cases.front() + "-slowing";
  cases.push_back(slowing);
  double capacity = 0;  // the emulated cluster in serial machines
  for (double k : slowdowns) capacity += 1 / k;
  auto optionsFor = [&](const std::string& strategy, const std::string& c, double serialSeconds) {
    ParallelOptions o = parallelOptions(strategy, slowdowns);
    if (c == slowing) {
      o.slowdownChanges = {SpeedChange{0, serialSeconds / capacity / 3, 4 * slowdowns.front()}};
    }
    return o;
  };
  auto baseCase = [&](const std::string& c) { return c == slowing ? cases.front() : c; };

  CsvTable table(summaryColumns({"case", "strategy", "source", "runs"}));
  CsvTable runs({"case", "strategy", "run", "serial_s", "elapsed_s", "speedup", "efficiency",
                 "masu", "asu", "messages", "bytes"});
  // results[source][case][strategy]
  std::map<std::string, std::map<std::string, std::map<std::string, RunSummary>>> results;
  std::string serialTimes;
  for (const std::string& c : cases) {
    const RenderSettings settings = cx.settings(baseCase(c));
    cx.progress("case " + c + ": serial time and cost map");
    SerialReference serial(scene, settings);
    // Round-robin over the strategies, so that a noisy spell on the machine hits them alike.
    std::map<std::string, std::vector<RunReport>> reports;
    for (int run = 1; run <= cx.runs(); ++run) {
      for (const std::string& strategy : strategies) {
        cx.progress("case " + c + ", " + strategy + ": run " + std::to_string(run) + " of " +
                    std::to_string(cx.runs()));
        const double serialSeconds = serial.seconds();
        const RunReport r = runReal(scene, settings, optionsFor(strategy, c, serialSeconds),
                                    serialSeconds, masterIndex);
        runs.addRow({c, strategy, std::to_string(run), csvNumber(serialSeconds, 5),
                     csvNumber(r.elapsedSeconds, 5), csvNumber(r.speedup.value_or(0), 4),
                     csvNumber(r.efficiency, 4), csvNumber(r.masu, 4),
                     csvNumber(r.asu.value_or(0), 4), std::to_string(r.messages),
                     std::to_string(r.bytes)});
        reports[strategy].push_back(r);
      }
    }
    serialTimes += (serialTimes.empty() ? "" : "; ") + c + " " + serial.describe();
    for (const std::string& strategy : strategies) {
      results["real"][c][strategy] = medianSummary(reports[strategy]);
      results["simulated"][c][strategy] = medianSummary({runSimulated(
          serial.costMap(), optionsFor(strategy, c, serial.seconds()), masterIndex)});
      for (const char* source : {"real", "simulated"}) {
        table.addRow(summaryRow(
            {c, strategy, source, std::string(source) == "real" ? std::to_string(cx.runs()) : "1"},
            results[source][c][strategy]));
      }
    }
  }
  cx.write(table, "compare.csv");
  cx.write(runs, "compare-runs.csv");

  struct Figure {
    const char* file;
    const char* measure;
    const char* title;
    const char* label;
    double scale;
  };
  const Figure figures[] = {
      {"compare-speedup.png", "speedup", "Fig. 19: speed-up", "speed-up", 1},
      {"compare-efficiency.png", "efficiency", "Fig. 20: efficiency", "efficiency, %", 100},
      {"compare-asu.png", "asu", "Fig. 21: achieved speed-up (ASU)", "ASU, %", 100}};
  for (const Figure& f : figures) {
    Chart chart;
    chart.kind = Chart::Kind::Bars;
    chart.title = std::string(f.title) + " of every strategy, real runs, " +
                  std::to_string(slowdowns.size()) + " emulated workers";
    chart.yLabel = f.label;
    for (const std::string& c : cases) chart.categories.push_back("case " + c);
    for (const std::string& strategy : strategies) {
      ChartSeries series{strategy, {}, {}, false};
      for (const std::string& c : cases) {
        series.y.push_back(f.scale * field(results["real"][c][strategy], f.measure));
      }
      chart.series.push_back(series);
    }
    cx.draw(chart, f.file);
  }

  cx.say("Every strategy on `" + cx.options().scenePath + "` at " +
         std::to_string(scene.image.width) + "x" + std::to_string(scene.image.height) +
         ". `real` rows: the local driver, median of " + std::to_string(cx.runs()) +
         " run(s); `simulated` rows: the simulator replaying each case's serial cost map with "
         "the same worker speeds. Serial times (one thread; measured again whenever the last "
         "was a minute old): " +
         serialTimes + ". Case " + slowing + " is case " + cases.front() +
         " with worker 0 becoming four times slower than its --slowdown at a third of the "
         "ideal parallel time (--slowdown-at; the simulator follows the same schedule). "
         "Adaptive strategies run no speed index (MASU and ASU from measured throughput). " +
         cx.emulationNote() + "\n\n");
  cx.say(
      "The paper's claims, recomputed (\"X % better\" = ours / theirs - 1, the largest over "
      "the cases):\n\n| claim | paper | ");
  std::vector<std::string> mine;
  for (const char* m : {"reservoir", "reservoir-scatter", kDefaultStrategy}) {
    for (const std::string& s : strategies) {
      if (s == m) mine.push_back(m);
    }
  }
  for (const std::string& m : mine) cx.say(m + " real | " + m + " simulated | ");
  cx.say("\n|---|---|");
  for (size_t i = 0; i < 2 * mine.size(); ++i) cx.say("---|");
  cx.say("\n");
  auto has = [&](const std::string& s) {
    return std::find(strategies.begin(), strategies.end(), s) != strategies.end();
  };
  for (const Claim& claim : kClaims) {
    if (!has(claim.other)) continue;
    cx.say(std::string("| ") + claim.measure + " vs " + claim.other + " | " +
           csvNumber(claim.paper) + " % | ");
    for (const std::string& m : mine) {
      for (const char* source : {"real", "simulated"}) {
        double best = -1e9;
        std::string where;
        for (const std::string& c : cases) {
          const double ours = field(results[source][c][m], claim.measure);
          const double theirs = field(results[source][c][claim.other], claim.measure);
          const double better = 100 * (ours / theirs - 1);
          if (better > best) {
            best = better;
            where = c;
          }
        }
        cx.say(csvNumber(best, 3) + " % (case " + where + ") | ");
      }
    }
    cx.say("\n");
  }
  cx.say("\n" + markdownTable(table, {"case", "strategy", "source", "elapsed_s", "speedup",
                                      "efficiency", "masu", "asu", "messages"}));
}

}  // namespace prt
