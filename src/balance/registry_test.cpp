#include <gtest/gtest.h>

#include <limits>

#include "balance/strategy.h"
#include "core/input_error.h"

namespace prt {
namespace {

TEST(StrategyRegistryTest, EveryNameMakesThatStrategy) {
  const std::vector<std::string> names = strategyNames();
  EXPECT_EQ(names, (std::vector<std::string>{"scatter", "scatter-weighted", "hybrid",
                                             "hybrid-weighted", "reservoir", "reservoir-scatter",
                                             "adaptive", "blocks", "frames", "self", "guided", "factoring",
                                             "awf-b", "awf-c", "af", "stealing"}));
  for (const std::string& name : names) EXPECT_EQ(makeStrategy(name, {})->name(), name);
}

TEST(StrategyRegistryTest, UnknownNameListsTheValidOnes) {
  try {
    makeStrategy("diffusion", {});
    FAIL() << "expected InputError";
  } catch (const InputError& e) {
    const std::string message = e.what();
    EXPECT_NE(message.find("diffusion"), std::string::npos);
    for (const std::string& name : strategyNames()) {
      EXPECT_NE(message.find(name), std::string::npos) << name;
    }
  }
}

TEST(StrategyRegistryTest, InvalidOptionsAreRejected) {
  for (double percent : {0.0, -1.0, 100.01, std::numeric_limits<double>::quiet_NaN()}) {
    EXPECT_THROW(makeStrategy("reservoir", {.initialPercent = percent}), InputError) << percent;
  }
  EXPECT_THROW(makeStrategy("self", {.chunk = 0}), InputError);
  EXPECT_THROW(makeStrategy("scatter", {.chunk = 0}), InputError);  // bad whatever the user
  EXPECT_NO_THROW(makeStrategy("reservoir", {.initialPercent = 100}));
  EXPECT_NO_THROW(makeStrategy("self", {.chunk = 1}));
  EXPECT_THROW(makeStrategy("adaptive", {.minChunk = 0}), InputError);
  EXPECT_THROW(makeStrategy("adaptive", {.firstPercent = 0}), InputError);
  EXPECT_THROW(makeStrategy("adaptive", {.reservePercent = 100}), InputError);
  EXPECT_NO_THROW(makeStrategy("adaptive", {.reservePercent = 0}));
  try {
    makeStrategy("adaptive", {.reservePercent = 100});
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("--reserve-percent 100 is out of range; it must be in [0, 100)"),
              std::string::npos)
        << e.what();
  }
}

TEST(StrategyRegistryTest, OptionsReachTheStrategy) {
  auto self = makeStrategy("self", {.chunk = 3});
  EXPECT_EQ(self->start(StartInfo{10, {1}}), (Decisions{Assign{0, TaskSet::range(0, 3)}}));
  auto reservoir = makeStrategy("reservoir", {.initialPercent = 50});
  EXPECT_EQ(reservoir->start(StartInfo{10, {1}}), (Decisions{Assign{0, TaskSet::range(0, 5)}}));
}

}  // namespace
}  // namespace prt
