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

#include "balance/strategy.h"
#include "core/speed_index.h"
#include "lab/measure.h"
#include "scene/scene_file.h"

namespace prt {
namespace {

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
  double bestError = INFINITY;
  double real = 0, simulated = 0;
  for (int attempt = 0; attempt < 8 && bestError > 0.10; ++attempt) {
    const double masterIndex = measureSpeedIndexSeconds(options.speedIndexDiscs, 5);
    const RunReport r =
        runReal(*scene_, *paperTestCase("A"), options, serial_->medianSeconds, masterIndex);
    double compute = 0;
    std::vector<double> speedIndices;
    for (const WorkerReport& w : r.workers) {
      compute += w.busySeconds / w.slowdown;
      speedIndices.push_back(w.speedIndexSeconds);
    }
    const RunReport s =
        runSimulated(serial_->costMap->scaledTo(compute), options, masterIndex, speedIndices);
    const double error = std::abs(s.elapsedSeconds / r.elapsedSeconds - 1);
    if (error < bestError) {
      bestError = error;
      real = r.elapsedSeconds;
      simulated = s.elapsedSeconds;
    }
  }
  EXPECT_LT(bestError, 0.10) << GetParam() << ": real " << real << " s, simulated " << simulated
                             << " s";
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
