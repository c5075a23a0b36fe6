#include "metrics/run_report.h"

#include <gtest/gtest.h>

#include <cmath>

#include <nlohmann/json.hpp>

#include "metrics/chrome_trace.h"

namespace prt {
namespace {

// The paper's Table 2: SRT 0.3 s, four workers -> theoretical speed-ups 98.28 %, 46.52 %,
// 99.56 %, 97.43 %, MASU 341.79 %.
TEST(RunReportTest, MasuMatchesThePapersTable2) {
  const std::vector<double> speeds = {0.30525, 0.644833, 0.301333, 0.307917};
  EXPECT_NEAR(0.3 / speeds[1], 0.4652, 5e-5);
  EXPECT_NEAR(maximumAchievableSpeedup(0.3, speeds), 3.4179, 5e-4);
}

RunInfo twoWorkers() {
  RunInfo info;
  info.driver = "local";
  info.strategy = "reservoir";
  info.masterSpeedIndexSeconds = 0.1;
  info.workerSpeedIndexSeconds = {0.1, 0.2};
  info.slowdowns = {1, 2};
  info.tasksReceived = {3, 1};
  info.serialSeconds = 6.0;
  return info;
}

TEST(RunReportTest, WithoutASpeedIndexMasuComesFromMeasuredThroughput) {
  // Serial: 150 pixels in 6 s, 25 pixels/s. Worker 0: 120 pixels in 3.5 s; worker 1: 30 in 2 s.
  RunInfo info = twoWorkers();
  info.speedIndexRun = false;
  std::vector<Event> events;
  events.push_back({EventKind::Compute, 0, 0.0, 3.0, 100, 0, 0, ""});
  events.push_back({EventKind::Compute, 0, 3.5, 4.0, 20, 0, 0, ""});
  events.push_back({EventKind::Compute, 1, 0.0, 2.0, 30, 0, 0, ""});
  const RunReport r = makeReport(info, events, 4.0);
  const double masu = (120 / 3.5 + 30 / 2.0) / 25;
  EXPECT_EQ(r.masuBasis, "measured_throughput");
  EXPECT_FALSE(r.speedIndexMasu.has_value());
  EXPECT_NEAR(*r.measuredMasu, masu, 1e-12);
  EXPECT_NEAR(r.masu, masu, 1e-12);
  EXPECT_NEAR(*r.asu, 1.5 / masu, 1e-12);
  const nlohmann::json j = nlohmann::json::parse(r.toJson());
  EXPECT_EQ(j["masu_basis"], "measured_throughput");
  EXPECT_TRUE(j["speed_index_masu"].is_null());
  EXPECT_TRUE(j["speed_index_asu"].is_null());
  EXPECT_NEAR(j["measured_masu"].get<double>(), masu, 1e-12);
  // With a speed index both kinds are given, the speed index's as masu.
  const RunReport withIndex = makeReport(twoWorkers(), events, 4.0);
  EXPECT_EQ(withIndex.masuBasis, "speed_index");
  EXPECT_NEAR(withIndex.masu, 1.5, 1e-12);
  EXPECT_NEAR(*withIndex.measuredMasu, masu, 1e-12);
}

TEST(RunReportTest, EfficiencySpeedupAndAsuFromEvents) {
  std::vector<Event> events;
  events.push_back({EventKind::Compute, 0, 0.0, 3.0, 100, 0, 0, ""});
  events.push_back({EventKind::Compute, 0, 3.5, 4.0, 20, 0, 0, ""});
  events.push_back({EventKind::Compute, 1, 0.0, 2.0, 30, 0, 0, ""});
  events.push_back({EventKind::MessageSent, 0, 1.0, 1.0, 0, 500, -1, "Results"});
  events.push_back({EventKind::MessageReceived, -1, 1.0, 1.0, 0, 500, 0, "Results"});
  const RunReport r = makeReport(twoWorkers(), events, 4.0);
  EXPECT_DOUBLE_EQ(r.workers[0].busySeconds, 3.5);
  EXPECT_DOUBLE_EQ(r.workers[0].idleSeconds, 0.5);
  EXPECT_EQ(r.workers[0].pixels, 120u);
  EXPECT_DOUBLE_EQ(r.workers[1].idleSeconds, 2.0);
  EXPECT_DOUBLE_EQ(r.efficiency, 5.5 / 8.0);
  EXPECT_DOUBLE_EQ(*r.speedup, 1.5);
  EXPECT_DOUBLE_EQ(r.masu, 1.5);
  EXPECT_DOUBLE_EQ(*r.asu, 1.0);
  EXPECT_EQ(r.messages, 1u);
  EXPECT_EQ(r.bytes, 500u);
  EXPECT_EQ(r.workers[0].messagesSent, 1u);
}

// Samples a worker found not finite: per worker and in all, in the JSON and the table.
TEST(RunReportTest, NonFiniteSamplesAreReportedPerWorkerAndInAll) {
  std::vector<Event> events;
  events.push_back({EventKind::Compute, 0, 0.0, 3.0, 100, 0, 0, ""});
  events.push_back({EventKind::Compute, 1, 0.0, 2.0, 30, 0, 0, ""});
  RunInfo info = twoWorkers();
  const auto clean = nlohmann::json::parse(makeReport(info, events, 4.0).toJson());
  EXPECT_EQ(clean["non_finite_samples"], 0);
  EXPECT_EQ(makeReport(info, events, 4.0).toTable().find("not finite"), std::string::npos);
  info.nonFiniteSamples = {3, 4};
  const RunReport r = makeReport(info, events, 4.0);
  const auto j = nlohmann::json::parse(r.toJson());
  EXPECT_EQ(j["non_finite_samples"], 7);
  EXPECT_EQ(j["workers"][0]["non_finite_samples"], 3);
  EXPECT_EQ(j["workers"][1]["non_finite_samples"], 4);
  EXPECT_NE(r.toTable().find("7 samples were not finite"), std::string::npos) << r.toTable();
}

TEST(RunReportTest, AJoinerCountsFromItsArrivalAndTheIdealFollowsTheSchedule) {
  RunInfo info = twoWorkers();
  info.joinedAt = {std::nullopt, 2.0};  // worker 1 joins at 2 s
  std::vector<Event> events;
  events.push_back({EventKind::Compute, 0, 0.0, 4.0, 100, 0, 0, ""});  // 25 pixels/s
  events.push_back({EventKind::Compute, 1, 2.0, 4.0, 100, 0, 0, ""});  // 50 pixels/s
  const RunReport r = makeReport(info, events, 4.0);
  EXPECT_DOUBLE_EQ(r.workers[1].idleSeconds, 0.0);
  EXPECT_DOUBLE_EQ(r.efficiency, 1.0);  // 6 busy seconds of 4 + 2 present
  // 200 pixels: 50 by 2 s from worker 0 alone, then 75 pixels/s for the other 150: 4 s.
  ASSERT_TRUE(r.idealSeconds.has_value());
  EXPECT_DOUBLE_EQ(*r.idealSeconds, 4.0);
  const auto j = nlohmann::json::parse(r.toJson());
  ASSERT_EQ(j["joined_workers"].size(), 1u);
  EXPECT_EQ(j["joined_workers"][0]["worker"], 1);
  EXPECT_DOUBLE_EQ(j["workers"][1]["joined_at_s"].get<double>(), 2.0);
  EXPECT_TRUE(j["workers"][0]["joined_at_s"].is_null());
  EXPECT_NE(r.toTable().find("worker 1 joined at 2.00 s"), std::string::npos);
}

TEST(RunReportTest, ALostWorkersPixelsAreThoseTheMasterAccepted) {
  RunInfo info = twoWorkers();
  info.acceptedPixels = {90, 30};
  std::vector<Event> events;
  events.push_back({EventKind::Compute, 0, 0.0, 1.0, 100, 0, 0, ""});  // 10 of them copies
  const RunReport r = makeReport(info, events, 1.0);
  EXPECT_EQ(r.workers[0].pixels, 100u);  // what it rendered, from its events
  EXPECT_EQ(r.workers[1].pixels, 30u);   // its events never came
}

TEST(RunReportTest, ALostWorkerIsPartOfTheRunUntilItsLossForEfficiencyAndTheIdeal) {
  // Worker 0 (speed 1) computes 0-4 s; worker 1 (speed 1/2) computes 0-1 s, is last heard from
  // at 2 s and lost at 3 s.
  RunInfo info = twoWorkers();
  info.faults.lostWorkers.push_back({1, 3.0, "silent for 1.0 s", 0, 2.0});
  std::vector<Event> events;
  events.push_back({EventKind::Compute, 0, 0.0, 4.0, 100, 0, 0, ""});
  events.push_back({EventKind::Compute, 1, 0.0, 1.0, 10, 0, 0, ""});
  const RunReport r = makeReport(info, events, 4.0);
  EXPECT_DOUBLE_EQ(r.workers[1].idleSeconds, 1.0);  // not 3: it was gone from 2 s
  EXPECT_DOUBLE_EQ(r.efficiency, 5.0 / 6.0);
  // Work: 4 + 1 * 0.5 = 4.5 full-speed seconds; 1.5 per second until 2 s, then 1.
  ASSERT_TRUE(r.idealSeconds.has_value());
  EXPECT_DOUBLE_EQ(*r.idealSeconds, 3.5);
}

TEST(RunReportTest, BalancedFinishWaterFillsOverArrivals) {
  // One worker at 10/s has done 50 pixels by 5 s, when one at 30/s joins: 40 more take 1 s.
  EXPECT_DOUBLE_EQ(*balancedFinishSeconds({10, 30}, {0, 5}, 90), 6.0);
  EXPECT_DOUBLE_EQ(*balancedFinishSeconds({10, 30}, {0, 5}, 40), 4.0);  // done before it came
  EXPECT_DOUBLE_EQ(*balancedFinishSeconds({10, 0}, {0, 0}, 40), 4.0);   // an absent worker
  EXPECT_FALSE(balancedFinishSeconds({0}, {0}, 40).has_value());
  // Departures: the second worker leaves at 2 s, after rendering 60 pixels with the first.
  EXPECT_DOUBLE_EQ(*balancedFinishSeconds({10, 20}, {0, 0}, 100, {HUGE_VAL, 2}), 6.0);
  // Leaves and another comes: 10/s alone from 2 s to 4 s, then 40/s.
  EXPECT_DOUBLE_EQ(*balancedFinishSeconds({10, 20, 30}, {0, 0, 4}, 120, {HUGE_VAL, 2, HUGE_VAL}),
                   5.0);
  // Everyone gone before the work is done.
  EXPECT_FALSE(balancedFinishSeconds({10}, {0}, 100, {5}).has_value());
}

TEST(RunReportTest, JsonHasThePapersKeysAtTopLevel) {
  const RunReport r = makeReport(twoWorkers(), {}, 2.0);
  const auto j = nlohmann::json::parse(r.toJson());
  for (const char* key : {"elapsed_s", "speedup", "efficiency", "masu", "asu", "messages",
                          "bytes", "workers"}) {
    EXPECT_TRUE(j.contains(key)) << key;
  }
  EXPECT_EQ(j["workers"].size(), 2u);
  EXPECT_DOUBLE_EQ(j["speedup"].get<double>(), 3.0);
}

TEST(RunReportTest, WithoutSerialTimeSpeedupIsNull) {
  RunInfo info = twoWorkers();
  info.serialSeconds.reset();
  const RunReport r = makeReport(info, {}, 2.0);
  EXPECT_FALSE(r.speedup.has_value());
  EXPECT_TRUE(nlohmann::json::parse(r.toJson())["speedup"].is_null());
  EXPECT_NE(r.toTable().find("--measure-serial"), std::string::npos);
}

TEST(ChromeTraceTest, OneTrackPerWorkerWithWaitingSpans) {
  std::vector<Event> events;
  events.push_back({EventKind::Compute, 0, 0.5, 1.0, 10, 0, 0, ""});
  const auto j = nlohmann::json::parse(chromeTraceJson(events, 2, 2.0));
  int rendering = 0, waiting = 0, names = 0;
  for (const auto& e : j["traceEvents"]) {
    if (e["name"] == "rendering") ++rendering;
    if (e["name"] == "waiting") ++waiting;
    if (e["name"] == "thread_name") ++names;
  }
  EXPECT_EQ(rendering, 1);
  EXPECT_EQ(waiting, 3);  // worker 0 before and after its span, worker 1 throughout
  EXPECT_EQ(names, 3);    // master and two workers
}

}  // namespace
}  // namespace prt
