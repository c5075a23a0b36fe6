#include "lab/experiment.h"

#include <gtest/gtest.h>

#include "core/input_error.h"

namespace prt {
namespace {

TEST(Experiment, NamesAreThePapersExperiments) {
  EXPECT_EQ(experimentNames(), (std::vector<std::string>{"table3", "speed-index", "initial-percent",
                                                         "compare", "scale", "joins",
                                                         "faults"}));
}

TEST(Experiment, UnknownNameListsTheValidOnes) {
  try {
    ExperimentOptions o;
    o.outDir = "/tmp";
    runExperiment("fig99", o);
    FAIL();
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("table3, speed-index"), std::string::npos) << e.what();
  }
}

TEST(Experiment, BadOptionsAreInputErrors) {
  ExperimentOptions o;
  o.scenePath = PRT_SOURCE_DIR "/scenes/complex.scene";
  EXPECT_THROW(runExperiment("table3", o), InputError) << "no --out";
  o.outDir = "/tmp/prt-experiment-test-never-written";
  o.runs = -1;
  EXPECT_THROW(runExperiment("table3", o), InputError);
  o.runs = 1;
  o.slowdowns = {2, 0.5};
  EXPECT_THROW(runExperiment("compare", o), InputError);
  o.slowdowns = {};
  o.serialSeconds = -1;
  EXPECT_THROW(runExperiment("scale", o), InputError);
  o.serialSeconds.reset();
  o.scenePath = "/nonexistent.scene";
  EXPECT_THROW(runExperiment("table3", o), InputError);
}

}  // namespace
}  // namespace prt
