#include "cluster/run_plan.h"

#include <gtest/gtest.h>

#include <cmath>

#include "core/input_error.h"

namespace prt {
namespace {

std::string refusal(const RunPlan& plan, int workers) {
  try {
    validateRunPlan(plan, workers);
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

TEST(RunPlan, TheDefaultsAreValidAndTheHeartbeatFollowsTheLease) {
  RunPlan plan;
  EXPECT_EQ(refusal(plan, 1), "");
  EXPECT_EQ(plan.strategy, kDefaultStrategy);
  EXPECT_EQ(plan.workerTimeoutSeconds, kDefaultLeaseSeconds);
  EXPECT_EQ(plan.heartbeatSeconds(), heartbeatSecondsFor(kDefaultLeaseSeconds));
  plan.workerTimeoutSeconds = 30;
  EXPECT_DOUBLE_EQ(plan.heartbeatSeconds(), 30 / kBeatsPerLease);
}

TEST(RunPlan, EachValueIsCheckedWithAMessageNamingItsFlag) {
  RunPlan plan;
  plan.strategy = "nonesuch";
  EXPECT_NE(refusal(plan, 2).find("nonesuch"), std::string::npos);
  plan = RunPlan{};
  plan.batchPixels = 0;
  EXPECT_NE(refusal(plan, 2).find("--batch"), std::string::npos);
  for (const double lease : {0.05, 1e6, -1.0, std::nan("")}) {
    plan = RunPlan{};
    plan.workerTimeoutSeconds = lease;
    EXPECT_NE(refusal(plan, 2).find("--worker-timeout"), std::string::npos) << lease;
  }
  plan = RunPlan{};
  plan.faults = {FaultInjection{2, 10, FaultInjection::Kind::Crash}};
  EXPECT_NE(refusal(plan, 2).find("numbered 0 to 1"), std::string::npos) << refusal(plan, 2);
  EXPECT_EQ(refusal(plan, 3), "");  // a joiner may be the one that fails
  plan = RunPlan{};
  plan.joins = {JoinWave{-1, 1}};
  EXPECT_NE(refusal(plan, 2).find("--join-at"), std::string::npos);
}

}  // namespace
}  // namespace prt
