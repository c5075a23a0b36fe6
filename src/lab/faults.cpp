// faults: what machines that fail cost a large farm, and what lease (--worker-timeout) to
// choose. Simulated only: 1,024 workers, half of them four times slower, a 3840x2160 image of
// the complex scene's shape (the synthetic cost map, sim/synthetic_cost.h) with an hour of
// ideal job time. Each machine fails at exponentially distributed times of mean MTBF (none,
// 100 h, 10 h, 1 h) and comes back ten minutes later as a worker joining the run; the lease
// runs from 1 s to 3 minutes. Job time against the lease for each MTBF and strategy, with the
// ideal beside it: the work perfectly balanced over the machines while they were part of the
// run (until last heard from). The failure times are drawn from the seed alone, so every strategy
// and lease meets the same failures; each failing configuration runs with three seeds, and the
// medians are given.

#include <algorithm>
#include <chrono>
#include <cmath>
#include <map>

#include "balance/registry.h"
#include "cluster/leases.h"
#include "cluster/worker.h"
#include "lab/context.h"
#include "lab/experiments.h"
#include "lab/measure.h"
#include "sim/simulator.h"
#include "sim/synthetic_cost.h"
#include "sim/worker_speeds.h"

namespace prt {
namespace {

constexpr double kRepairSeconds = 600;

struct Point {
  double elapsed = 0, ideal = 0, lost = 0, reissued = 0, duplicates = 0, masterShare = 0,
         messages = 0;
};

Point medianPoint(const std::vector<RunReport>& reports) {
  auto med = [&](auto field) { return medianOf(reports, field); };
  Point p;
  p.elapsed = med([](const RunReport& r) { return r.elapsedSeconds; });
  p.ideal = med([](const RunReport& r) { return r.idealSeconds.value_or(NAN); });
  p.lost = med([](const RunReport& r) { return double(r.info.faults.lostWorkers.size()); });
  p.reissued = med([](const RunReport& r) { return double(r.info.faults.reissuedTasks); });
  p.duplicates = med([](const RunReport& r) { return double(r.info.faults.duplicatePixels); });
  p.masterShare = med([](const RunReport& r) { return r.masterBusyShare().value_or(NAN); });
  p.messages = med([](const RunReport& r) { return double(r.messages); });
  return p;
}

std::string mtbfLabel(double hours) {
  return hours > 0 ? csvNumber(hours) + " h" : std::string("none");
}

}  // namespace

void runFaults(ExperimentContext& cx) {
  const int workers = cx.quick() ? 64 : 1024;
  const int width = cx.options().width.value_or(cx.quick() ? 640 : 3840);
  const int height = cx.options().height.value_or(cx.quick() ? 360 : 2160);
  if (static_cast<uint64_t>(width) * static_cast<uint64_t>(height) <
      static_cast<uint64_t>(workers)) {
    throw InputError(
        "faults: the image has fewer pixels than workers; use a larger --width "
        "and --height");
  }
  std::vector<std::string> strategies = cx.options().strategies;
  if (strategies.empty())
    strategies = {kDefaultStrategy, "reservoir-scatter", "hybrid", "stealing"};
  const std::vector<double> leases =
      cx.quick() ? std::vector<double>{2, 15, 60} : std::vector<double>{1, 2, 5, 15, 60, 180};
  const std::vector<double> mtbfHours =
      cx.quick() ? std::vector<double>{0, 1} : std::vector<double>{0, 100, 10, 1};
  const std::vector<uint64_t> seeds =
      cx.quick() ? std::vector<uint64_t>{1} : std::vector<uint64_t>{1, 2, 3};

  const std::vector<double> speeds = slowShareSpeeds(workers, 0.5, 4, 1);
  double capacity = 0;
  for (double v : speeds) capacity += v;
  // An hour of job time when perfectly balanced (quick: ten minutes).
  const double jobSeconds = cx.quick() ? 600 : 3600;
  const double serialSeconds = cx.options().serialSeconds.value_or(capacity * jobSeconds);
  cx.progress("cost map: synthetic complex scene, " + std::to_string(width) + "x" +
              std::to_string(height) + ", " + csvNumber(serialSeconds) + " s of serial work");
  const CostMap costs = complexSceneCostMap(width, height, serialSeconds);

  CsvTable table({"mtbf_h", "lease_s", "strategy", "source", "seeds", "elapsed_s", "ideal_s",
                  "elapsed_over_ideal", "over_no_failures", "lost_workers", "reissued_tasks",
                  "duplicate_pixels", "master_busy_share", "messages", "simulation_wall_s"});
  // points[mtbf][strategy][lease]
  std::map<double, std::map<std::string, std::map<double, Point>>> points;
  for (double mtbf : mtbfHours) {
    for (const std::string& strategy : strategies) {
      cx.progress("MTBF " + mtbfLabel(mtbf) + ", " + strategy);
      for (double lease : leases) {
        SimulationOptions sim;
        sim.strategy = strategy;
        sim.speeds = speeds;
        sim.speedIndexRun = runsSpeedIndexByDefault(strategy);
        sim.oracleSpeedIndex = true;  // the sharing is compared, not a short benchmark
        sim.workerTimeoutSeconds = lease;
        if (mtbf > 0) {
          sim.mtbfSeconds = mtbf * 3600;
          sim.repairSeconds = kRepairSeconds;
        }
        std::vector<RunReport> reports;
        const auto start = std::chrono::steady_clock::now();
        for (uint64_t seed : mtbf > 0 ? seeds : std::vector<uint64_t>{1}) {
          sim.seed = seed;
          reports.push_back(simulate(costs, sim).report);
        }
        const double wall =
            std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count() /
            static_cast<double>(reports.size());
        const Point p = medianPoint(reports);
        points[mtbf][strategy][lease] = p;
        const double base = points[0][strategy][lease].elapsed;
        table.addRow({csvNumber(mtbf), csvNumber(lease), strategy, "simulated",
                      std::to_string(reports.size()), csvNumber(p.elapsed, 6),
                      csvNumber(p.ideal, 6), csvNumber(p.elapsed / p.ideal, 4),
                      csvNumber(p.elapsed / base, 4), csvNumber(p.lost), csvNumber(p.reissued),
                      csvNumber(p.duplicates), csvNumber(p.masterShare, 4), csvNumber(p.messages),
                      csvNumber(wall, 3)});
      }
    }
  }
  cx.write(table, "faults.csv");

  // Job time against the lease, one chart per MTBF, the ideal of the default strategy's runs
  // beside the strategies (the ideals of the others differ only by their duplicate work).
  for (double mtbf : mtbfHours) {
    Chart chart;
    chart.title = "Simulated job time against the lease, MTBF " + mtbfLabel(mtbf) + ", " +
                  std::to_string(workers) + " workers";
    chart.xLabel = "lease (--worker-timeout), s";
    chart.yLabel = "job time, min";
    chart.logX = true;
    chart.yMin = 0;
    for (const std::string& strategy : strategies) {
      ChartSeries series{strategy, {}, {}, false};
      for (double lease : leases) {
        series.x.push_back(lease);
        series.y.push_back(points[mtbf][strategy][lease].elapsed / 60);
      }
      chart.series.push_back(series);
    }
    ChartSeries ideal{"ideal", {}, {}, true};
    for (double lease : leases) {
      ideal.x.push_back(lease);
      ideal.y.push_back(points[mtbf][strategies.front()][lease].ideal / 60);
    }
    chart.series.push_back(ideal);
    cx.draw(chart, "faults-time-mtbf-" + (mtbf > 0 ? csvNumber(mtbf) + "h" : "none") + ".png");
  }
  {
    Chart chart;
    chart.title = "Simulated cost of failures for " + strategies.front() +
                  ": job time over the same job without failures";
    chart.xLabel = "lease (--worker-timeout), s";
    chart.yLabel = "extra job time, %";
    chart.logX = true;
    for (double mtbf : mtbfHours) {
      if (mtbf == 0) continue;
      ChartSeries series{"MTBF " + mtbfLabel(mtbf), {}, {}, false};
      for (double lease : leases) {
        series.x.push_back(lease);
        series.y.push_back(100 * (points[mtbf][strategies.front()][lease].elapsed /
                                      points[0][strategies.front()][lease].elapsed -
                                  1));
      }
      chart.series.push_back(series);
    }
    cx.draw(chart, "faults-cost.png");
  }

  cx.say("Simulated runs only: " + std::to_string(workers) +
         " workers, half of them (picked at random, seed 1) four times slower, a " +
         std::to_string(width) + "x" + std::to_string(height) +
         " image of the complex scene's cost shape (the synthetic map, fitted to a real render), " +
         csvNumber(serialSeconds) + " s of serial work: " + csvNumber(jobSeconds / 60) +
         " minutes of job time when perfectly balanced. Every machine fails at exponentially "
         "distributed times of mean MTBF (`--mtbf`) and comes back " +
         csvNumber(kRepairSeconds / 60) +
         " minutes later as a worker that joins the run (`--repair`); a failed machine goes "
         "silent, mid-batch too, and is lost a lease after it was last heard from (its "
         "heartbeats come every lease / " +
         csvNumber(kBeatsPerLease) +
         "). The failures are drawn from the seed alone, so "
         "every strategy and lease meets the same ones; configurations with failures ran with " +
         std::to_string(seeds.size()) + " seeds, and the figures are medians. Batches of " +
         std::to_string(WorkerOptions::kDefaultBatchPixels) +
         " pixels; the workers report their true speed index. The ideal is the work perfectly "
         "balanced over the machines while they were part of the run, each until it was last "
         "heard from: a lower bound, which pays nothing for the lease nor for the work a "
         "machine takes with it.\n\n");

  // The strategies side by side at the default lease.
  const double shownLease =
      std::find(leases.begin(), leases.end(), kDefaultLeaseSeconds) != leases.end()
          ? kDefaultLeaseSeconds
          : leases.front();
  // What lease to choose: a longer lease survives longer pauses of a machine that is still
  // there (a swap storm, a network hiccup), which the simulator does not model; it costs the
  // wait for a machine that is gone. So: the longest lease that costs little.
  const std::string lead = strategies.front();
  cx.say(
      "**What lease to choose.** A lease too short takes a machine that only paused (a swap "
      "storm, a long network hiccup) for lost and throws its work away; the simulator has no "
      "such pauses, so it shows only the other side: what waiting for a machine that is "
      "gone costs. The longest lease that costs little is the one to choose:\n\n"
      "| MTBF per machine | machines lost (lease " +
      csvNumber(shownLease) + " s) | " + lead + ": job time, lease " + csvNumber(shownLease) +
      " s | best lease | longest lease within 1 % of the best |\n"
      "|---|---|---|---|---|\n");
  for (double mtbf : mtbfHours) {
    const auto& byLease = points[mtbf][lead];
    double bestLease = leases.front(), best = byLease.at(bestLease).elapsed;
    for (double lease : leases) {
      if (byLease.at(lease).elapsed < best) {
        best = byLease.at(lease).elapsed;
        bestLease = lease;
      }
    }
    double longest = bestLease;
    for (double lease : leases) {
      if (byLease.at(lease).elapsed <= 1.01 * best) longest = std::max(longest, lease);
    }
    const Point& at5 = byLease.at(shownLease);
    cx.say("| " + mtbfLabel(mtbf) + " | " + csvNumber(at5.lost) + " | " +
           csvNumber(at5.elapsed / 60, 4) + " min | " + csvNumber(bestLease) + " s | " +
           csvNumber(longest) + " s |\n");
  }
  cx.say("\n");
  cx.say("Job time over the ideal at a lease of " + csvNumber(shownLease) + " s:\n\n| strategy |");
  for (double mtbf : mtbfHours) cx.say(" MTBF " + mtbfLabel(mtbf) + " |");
  cx.say("\n|---|");
  for (size_t i = 0; i < mtbfHours.size(); ++i) cx.say("---|");
  cx.say("\n");
  for (const std::string& strategy : strategies) {
    cx.say("| " + strategy + " |");
    for (double mtbf : mtbfHours) {
      const Point& p = points[mtbf][strategy][shownLease];
      cx.say(" " + csvNumber(p.elapsed / p.ideal, 4) + " |");
    }
    cx.say("\n");
  }
  cx.say("\n" + markdownTable(table, {"mtbf_h", "lease_s", "strategy", "elapsed_s", "ideal_s",
                                      "elapsed_over_ideal", "lost_workers", "reissued_tasks",
                                      "master_busy_share"}));
}

}  // namespace prt
