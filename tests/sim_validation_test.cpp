// The simulator against real runs: for every strategy, a small render of the benchmark scene
// by the local driver on emulated slow workers, and the same run simulated from a cost map
// recorded moments before; the simulated elapsed time must be within 10 % of the real one.
//
// What is validated is the model of the run (setup, the strategy's decisions, batches,
// messages, waiting), not the test machine's steadiness: a busy machine (other tests, a
// compiler) slows every CPU second of the real run, by a third at times, which no cost map
// recorded earlier can know. So the map keeps its shape but is scaled to the compute the real
// run did (the sum over workers of busy time / slowdown), and the setup is simulated from
// the speed indices the real workers measured, as bench/sim/validate.py's "scaled" column
// does at full size.
// The slowdowns are large (8, 8, 16, 16: a third of a core in all), so the emulation stays
// faithful on a busy machine, and each configuration gets up to eight tries, taking the
// closest of them, so a preempted run does not fail the suite; the tests run alone (their
// own binary, RUN_SERIAL in CTest). The image (144×108, about 0.35 s a run) is large enough
// that the costs the model leaves out (thread wake-ups, which a loaded machine stretches) stay
// a few percent: at 96×72 the simulation came out 4-5 % short on an idle machine and 10 % short
// under load.

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "balance/strategy.h"
#include "core/speed_index.h"
#include "lab/measure.h"
#include "scene/scene_file.h"

namespace prt {
namespace {

// A real run of `options`, and the same run simulated from `serial`'s cost map scaled to the
// compute the real run did, with the speed indices its workers measured.
struct Comparison {
  RunReport real, simulated;
  double error = INFINITY;  // |simulated / real elapsed time - 1|
};
Comparison compare(const Scene& scene, const SerialMeasurement& serial,
                   const ParallelOptions& options) {
  const double masterIndex = measureSpeedIndexSeconds(options.speedIndexDiscs, 5);
  Comparison c;
  c.real = runReal(scene, *paperTestCase("A"), options, serial.medianSeconds, masterIndex);
  double compute = 0;
  std::vector<double> speedIndices;
  for (const WorkerReport& w : c.real.workers) {
    compute += w.busySeconds / w.slowdown;
    speedIndices.push_back(w.speedIndexSeconds);
  }
  c.simulated = runSimulated(serial.costMap->scaledTo(compute), options, masterIndex, speedIndices);
  c.error = std::abs(c.simulated.elapsedSeconds / c.real.elapsedSeconds - 1);
  return c;
}

class SimValidationTest : public ::testing::TestWithParam<std::string> {
 protected:
  static void SetUpTestSuite() {
    scene_ = new Scene(loadSceneFile(PRT_SOURCE_DIR "/scenes/complex.scene"));
    scene_->image.width = 144;
    scene_->image.height = 108;
    serial_ = new SerialMeasurement(measureSerial(*scene_, *paperTestCase("A"), 1, true));
  }
  static void TearDownTestSuite() {
    delete serial_;
    delete scene_;
  }
  static Scene* scene_;
  static SerialMeasurement* serial_;
};

Scene* SimValidationTest::scene_ = nullptr;
SerialMeasurement* SimValidationTest::serial_ = nullptr;

TEST_P(SimValidationTest, SimulatedElapsedTimeIsWithinTenPercentOfARealRun) {
  ParallelOptions options = parallelOptions(GetParam(), {8, 8, 16, 16});
  options.batchPixels = 64;
  options.speedIndexDiscs = 20;
  // Every strategy measures a speed index here, the adaptive ones too (they would start
  // without one): the simulated setup replays the measured indices, while a start without
  // one lasts as long as loading the scene, which the simulator does not model.
  options.speedIndexKind = SpeedIndexKind::Hanoi;
  Comparison best;
  for (int attempt = 0; attempt < 8 && best.error > 0.10; ++attempt) {
    Comparison c = compare(*scene_, *serial_, options);
    if (c.error < best.error) best = std::move(c);
  }
  EXPECT_LT(best.error, 0.10) << GetParam() << ": real " << best.real.elapsedSeconds
                              << " s, simulated " << best.simulated.elapsedSeconds << " s";
}

// The same with a worker that fails part-way: crashed (its connection drops, as the thread
// driver's does when its thread ends) or hung (silent: lost after the lease, 1 s here). The
// simulation must lose the same worker, reissue tasks, and end within 15 % of the real run.
TEST(SimValidationFaultTest, AFailedWorkerIsLostAsInARealRun) {
  Scene scene = loadSceneFile(PRT_SOURCE_DIR "/scenes/complex.scene");
  scene.image.width = 144;
  scene.image.height = 108;
  const SerialMeasurement serial = measureSerial(scene, *paperTestCase("A"), 1, true);
  for (const std::string strategy : {"adaptive", "hybrid", "self"}) {
    for (const auto kind : {FaultInjection::Kind::Crash, FaultInjection::Kind::Hang}) {
      ParallelOptions options = parallelOptions(strategy, {8, 8, 16, 16});
      options.batchPixels = 64;
      options.speedIndexDiscs = 20;
      options.speedIndexKind = SpeedIndexKind::Hanoi;
      options.workerTimeoutSeconds = 1.0;
      options.batchSeconds = 0;  // fixed batches: the fault comes 300 pixels in, mid-share
      options.faults = {FaultInjection{1, 300, kind}};
      const char* name = kind == FaultInjection::Kind::Crash ? "crash" : "hang";
      Comparison best;
      for (int attempt = 0; attempt < 8 && best.error > 0.15; ++attempt) {
        Comparison c = compare(scene, serial, options);
        const auto& realLost = c.real.info.faults.lostWorkers;
        const auto& simLost = c.simulated.info.faults.lostWorkers;
        ASSERT_EQ(realLost.size(), 1u) << strategy << ", " << name;
        ASSERT_EQ(simLost.size(), 1u) << strategy << ", " << name << ": worker 1 rendered "
                                      << c.simulated.workers[1].pixels << " px in the simulation, "
                                      << c.real.workers[1].pixels << " in the real run";
        EXPECT_EQ(simLost[0].worker, 1);
        EXPECT_GT(c.simulated.info.faults.reissuedTasks, 0u) << strategy << ", " << name;
        if (c.error < best.error) best = std::move(c);
      }
      const double real = best.real.elapsedSeconds, simulated = best.simulated.elapsedSeconds;
      EXPECT_LT(best.error, 0.15) << strategy << ", " << name << ": real " << real
                                  << " s, simulated " << simulated << " s";
      std::printf("%s, %s: real %.3f s, simulated %.3f s\n", strategy.c_str(), name, real,
                  simulated);
    }
  }
}

// A worker that joins mid-render, and a fast worker that hangs near the end of its share, so
// its loss falls in the run's last stretch, with and without endgame copies: the same worker
// lost, tasks reissued (a hang's unfinished tasks; none are lost in the join run), the joiner
// rendering in both, and the elapsed times within 15 %.
TEST(SimValidationFaultTest, AJoinAndALossInTheEndgameAsInARealRun) {
  Scene scene = loadSceneFile(PRT_SOURCE_DIR "/scenes/complex.scene");
  scene.image.width = 144;
  scene.image.height = 108;
  const SerialMeasurement serial = measureSerial(scene, *paperTestCase("A"), 1, true);
  struct Case {
    const char* name;
    bool join;
    bool endgame;
  };
  for (const Case& k : {Case{"join", true, false}, Case{"endgame loss", false, false},
                        Case{"endgame loss, --endgame", false, true}}) {
    for (const std::string strategy : {"adaptive", "stealing"}) {
      ParallelOptions options = parallelOptions(strategy, {8, 8, 16, 16});
      options.batchPixels = 64;
      options.speedIndexDiscs = 20;
      options.speedIndexKind = SpeedIndexKind::Hanoi;
      options.workerTimeoutSeconds = 1.0;
      options.batchSeconds = 0;
      options.endgame = k.endgame;
      if (k.join) {
        // A fifth worker, as fast as the fastest, joins a third of the way in (the run takes
        // about serial * 8 / 3 / 1.25 seconds without it).
        options.slowdowns.push_back(8);
        options.joins = {JoinWave{serial.medianSeconds * 8 / 3 / 1.25 / 3, 1}};
      } else {
        // Worker 0 renders about a third of the image (its speed over the total, 1/8 of 3/8),
        // 5,184 pixels; it hangs once it has done 4,300 of them. (Its share varies with the
        // machine's load: a real run where it fell short of the fault is tried again.)
        options.faults = {FaultInjection{0, 4300, FaultInjection::Kind::Hang}};
      }
      Comparison best;
      int compared = 0;
      for (int attempt = 0; attempt < 8 && best.error > 0.15; ++attempt) {
        Comparison c = compare(scene, serial, options);
        if (!k.join && c.real.info.faults.lostWorkers.empty()) continue;  // not the scenario
        ++compared;
        for (const RunReport* r : {&c.real, &c.simulated}) {
          const char* which = r == &c.real ? "real" : "simulated";
          const auto& lost = r->info.faults.lostWorkers;
          if (k.join) {
            EXPECT_TRUE(lost.empty()) << strategy << ", " << k.name << ", " << which;
            ASSERT_EQ(r->workers.size(), 5u) << strategy << ", " << which;
            EXPECT_GT(r->workers[4].pixels, 0u) << strategy << ", " << which << ": the joiner";
          } else {
            ASSERT_EQ(lost.size(), 1u) << strategy << ", " << k.name << ", " << which;
            EXPECT_EQ(lost[0].worker, 0) << strategy << ", " << k.name << ", " << which;
            EXPECT_GT(r->info.faults.reissuedTasks, 0u) << strategy << ", " << which;
          }
        }
        if (c.error < best.error) best = std::move(c);
      }
      ASSERT_GT(compared, 0) << strategy << ", " << k.name
                             << ": worker 0 never reached its fault in eight real runs";
      const double real = best.real.elapsedSeconds, simulated = best.simulated.elapsedSeconds;
      EXPECT_LT(best.error, 0.15) << strategy << ", " << k.name << ": real " << real
                                  << " s, simulated " << simulated << " s";
      std::printf("%s, %s: real %.3f s, simulated %.3f s; reissued %llu real, %llu simulated\n",
                  strategy.c_str(), k.name, real, simulated,
                  static_cast<unsigned long long>(best.real.info.faults.reissuedTasks),
                  static_cast<unsigned long long>(best.simulated.info.faults.reissuedTasks));
    }
  }
}

INSTANTIATE_TEST_SUITE_P(AllStrategies, SimValidationTest, ::testing::ValuesIn(strategyNames()),
                         [](const auto& param) {
                           std::string name = param.param;
                           for (char& c : name) {
                             if (c == '-') c = '_';
                           }
                           return name;
                         });

}  // namespace
}  // namespace prt
