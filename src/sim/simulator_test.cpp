// The simulator against answers known analytically, and every strategy's invariants: every
// pixel rendered exactly once, the same report for the same inputs.

#include "sim/simulator.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <numeric>
#include <string>

#include <nlohmann/json.hpp>

#include "core/input_error.h"
#include "metrics/chrome_trace.h"
#include "sim/synthetic_cost.h"
#include "sim/worker_speeds.h"

namespace prt {
namespace {

SimulationOptions optionsFor(const std::string& strategy, std::vector<double> speeds,
                             uint64_t batch = 128) {
  SimulationOptions o;
  o.strategy = strategy;
  o.speeds = std::move(speeds);
  o.batchPixels = batch;
  return o;
}

// The bytes of the first (or last) message sent with this label.
uint64_t bytesOf(const SimulatedRun& run, const std::string& label, bool last = false) {
  uint64_t bytes = 0;
  for (const Event& e : run.events) {
    if (e.kind == EventKind::MessageSent && e.label == label) {
      bytes = e.bytes;
      if (!last) break;
    }
  }
  EXPECT_GT(bytes, 0u) << label;
  return bytes;
}

uint64_t renderedPixels(const SimulatedRun& run) {
  uint64_t pixels = 0;
  for (const Event& e : run.events) {
    if (e.kind == EventKind::Compute) pixels += e.pixels;
  }
  return pixels;
}

// The master's modelled load: a service per message taken, half of one per heartbeat, and
// heartbeats only in silences: one worker rendering the whole image in one 10 s batch says
// nothing for 10 s, and neither does the master.
TEST(SimulatorTest, TheMastersLoadCountsServicesAndTheHeartbeatsOfSilences) {
  const CostMap map = uniformCostMap(64, 64, 10.0);
  for (const double beat : {1.0, 100.0}) {
    SimulationOptions o = optionsFor("blocks", {1.0}, 64 * 64);
    o.workerTimeoutSeconds = kBeatsPerLease * beat;  // heartbeats every `beat` seconds
    const SimulatedRun run = simulate(map, o);
    ASSERT_TRUE(run.report.info.master.has_value());
    const MasterLoad& m = *run.report.info.master;
    EXPECT_EQ(m.basis, "modelled_service");
    const uint64_t expected = beat == 1.0 ? 10 : 0;
    EXPECT_NEAR(static_cast<double>(m.heartbeatsReceived), static_cast<double>(expected), 1.0);
    EXPECT_NEAR(static_cast<double>(m.heartbeatsSent), static_cast<double>(expected), 1.0);
    uint64_t taken = 0, sent = 0;
    for (const Event& e : run.events) {
      if (e.worker != kMaster) continue;
      if (e.kind == EventKind::MessageReceived) ++taken;
      if (e.kind == EventKind::MessageSent) ++sent;
    }
    EXPECT_EQ(m.received, taken + m.heartbeatsReceived);
    EXPECT_EQ(m.sent, sent + m.heartbeatsSent);
    const double s = o.network.masterServiceSeconds;
    EXPECT_NEAR(m.busySeconds,
                static_cast<double>(taken) * s +
                    0.5 * s * static_cast<double>(m.heartbeatsReceived + m.heartbeatsSent),
                1e-12);
    ASSERT_TRUE(run.report.masterBusyShare().has_value());
    EXPECT_NEAR(*run.report.masterBusyShare(), m.busySeconds / run.report.elapsedSeconds, 1e-15);
  }
}

// A master that cannot keep up: a service longer than the workers' batches makes it the
// bottleneck, its busy share near 1, and the run as long as its services.
TEST(SimulatorTest, ASaturatedMasterIsBusyAllTheTime) {
  const CostMap map = uniformCostMap(64, 64, 0.4);
  SimulationOptions o = optionsFor("self", std::vector<double>(16, 1.0), 8);
  o.strategyOptions.chunk = 8;
  o.network.masterServiceSeconds = 0.01;  // 512 batches of 8 pixels: over 5 s of services
  const SimulatedRun run = simulate(map, o);
  ASSERT_TRUE(run.report.masterBusyShare().has_value());
  EXPECT_GT(*run.report.masterBusyShare(), 0.95);
  EXPECT_GT(run.report.elapsedSeconds, 5.0);
}

TEST(SimulatorTest, OneWorkerIsSetupPlusCostPlusTheMessageChain) {
  const CostMap map = uniformCostMap(64, 64, 1.0);
  for (const double speed : {1.0, 0.25}) {
    const SimulationOptions o = optionsFor("blocks", {speed});
    const SimulatedRun run = simulate(map, o);
    const NetworkOptions& n = o.network;
    auto hop = [&](uint64_t bytes) {
      return n.latencySeconds + static_cast<double>(bytes) / n.bandwidthBytesPerSecond;
    };
    const double expected = hop(bytesOf(run, "Scene")) + o.baseSpeedIndexSeconds / speed +
                            hop(bytesOf(run, "SpeedIndex")) + n.masterServiceSeconds +
                            hop(bytesOf(run, "Tasks")) + 1.0 / speed +
                            hop(bytesOf(run, "Results", true)) + n.masterServiceSeconds;
    EXPECT_NEAR(run.report.elapsedSeconds, expected, 1e-9) << "speed " << speed;
    EXPECT_NEAR(*run.report.speedup, 1.0 / expected, 1e-9);
    EXPECT_NEAR(run.report.workers[0].busySeconds, 1.0 / speed, 1e-9);
    EXPECT_NEAR(run.report.workers[0].speedIndexSeconds, 0.08 / speed, 1e-12);
    EXPECT_NEAR(run.report.masu, speed, 1e-12);
  }
}

TEST(SimulatorTest, BatchOverheadIsPaidPerBatchAtTheWorkersSpeed) {
  const CostMap map = uniformCostMap(64, 64, 1.0);  // 32 batches of 128 pixels
  SimulationOptions o = optionsFor("blocks", {0.5});
  const double plain = simulate(map, o).report.elapsedSeconds;
  o.batchOverheadSeconds = 1e-3;
  const SimulatedRun run = simulate(map, o);
  EXPECT_NEAR(run.report.elapsedSeconds - plain, 32 * 1e-3 / 0.5, 1e-9);
  EXPECT_NEAR(run.report.workers[0].busySeconds, (1.0 + 32e-3) / 0.5, 1e-9);
}

TEST(SimulatorTest, ScatterOnFourEqualWorkersTakesAQuarter) {
  const CostMap map = uniformCostMap(128, 128, 2.0);
  const SimulatedRun run = simulate(map, optionsFor("scatter", {1, 1, 1, 1}));
  const double ideal = 0.08 + 2.0 / 4;
  EXPECT_GE(run.report.elapsedSeconds, ideal);
  EXPECT_LT(run.report.elapsedSeconds, ideal + 1e-3);  // a few messages of latency
  for (const WorkerReport& w : run.report.workers) {
    EXPECT_EQ(w.pixels, 128u * 128 / 4);
    EXPECT_NEAR(w.busySeconds, 0.5, 1e-9);
  }
}

TEST(SimulatorTest, ReservoirDividesTheWorkBySpeed) {
  // Speeds 1 and 0.5: speed indices 0.08 and 0.16 s, divisions 2/3 and 1/3, so both finish
  // together after the slower setup plus 1 s / 1.5.
  const CostMap map = uniformCostMap(256, 256, 1.0);
  const SimulatedRun run = simulate(map, optionsFor("reservoir", {1, 0.5}, 64));
  const double ideal = 0.16 + 1.0 / 1.5;
  EXPECT_NEAR(run.report.elapsedSeconds, ideal, 0.01 * ideal);
  EXPECT_NEAR(static_cast<double>(run.report.workers[0].pixels) / (256 * 256), 2.0 / 3, 0.01);
  // Scatter gives them equal shares: the slow one takes 0.5 s / 0.5.
  const SimulatedRun scatter = simulate(map, optionsFor("scatter", {1, 0.5}, 64));
  EXPECT_NEAR(scatter.report.elapsedSeconds, 0.16 + 1.0, 0.01);
}

TEST(SimulatorTest, WorkDoneAtFollowsTheSpeedSchedule) {
  // 3 s of full-speed work from t = 1 at speed 1, halved from t = 2, doubled from t = 3: 1 s
  // of work by 2, 0.5 more by 3, the last 1.5 at speed 2 -> done at 3.75.
  const std::vector<SpeedChange> changes = {{0, 2, 0.5}, {0, 3, 2}};
  EXPECT_DOUBLE_EQ(workDoneAt(1, 3, 1, changes), 3.75);
  EXPECT_DOUBLE_EQ(workDoneAt(1, 0.5, 1, changes), 1.5);  // done before the first change
  // Starting at 2.5, at speed 0.5 already: 0.25 by 3, the other 0.75 at speed 2.
  EXPECT_DOUBLE_EQ(workDoneAt(2.5, 1, 1, changes), 3.375);
  EXPECT_DOUBLE_EQ(workDoneAt(0, 2, 0.25, {}), 8);
}

TEST(SimulatorTest, ASpeedChangeSlowsTheWorkerFromThenOn) {
  // One worker, 1 s of work: at half speed from 0.5 s after the start of rendering it needs
  // about another 0.5 s.
  const CostMap map = uniformCostMap(64, 64, 1.0);
  SimulationOptions o = optionsFor("blocks", {1.0});
  const double plain = simulate(map, o).report.elapsedSeconds;
  o.speedChanges = {SpeedChange{0, 0.08 + 0.5, 0.5}};  // the setup lasts 0.08 s
  const double slowed = simulate(map, o).report.elapsedSeconds;
  EXPECT_NEAR(slowed - plain, 0.5, 0.01);
  o.speedChanges = {SpeedChange{1, 0.5, 0.5}};
  EXPECT_THROW(simulate(map, o), InputError);  // no worker 1
}

TEST(SimulatorTest, WithoutASpeedIndexWorkersStartAtOnceAndMasuIsMeasured) {
  const CostMap map = uniformCostMap(64, 64, 1.0);
  SimulationOptions o = optionsFor("adaptive", {1.0, 0.5});
  o.speedIndexRun = false;
  const SimulatedRun run = simulate(map, o);
  EXPECT_LT(run.report.elapsedSeconds, 1.0 / 1.5 + 0.02);  // no 0.16 s speed-index wait
  EXPECT_EQ(run.report.masuBasis, "measured_throughput");
  EXPECT_FALSE(run.report.speedIndexMasu.has_value());
  ASSERT_TRUE(run.report.measuredMasu.has_value());
  EXPECT_NEAR(*run.report.measuredMasu, 1.5, 0.02);  // the workers' true speeds, 1 + 0.5
}

class SimulatorStrategyTest : public ::testing::TestWithParam<std::string> {};

TEST_P(SimulatorStrategyTest, EveryPixelExactlyOnceAndNoFasterThanPossible) {
  const CostMap map = complexSceneCostMap(97, 61, 3.0);
  const std::vector<double> speeds = {1, 0.5, 0.25, 1, 0.7};
  const SimulatedRun run = simulate(map, optionsFor(GetParam(), speeds, 16));
  // The master holds every pixel (the run ended); as many were rendered as exist, so none
  // twice.
  EXPECT_EQ(renderedPixels(run), map.pixelCount());
  uint64_t reported = 0;
  for (const WorkerReport& w : run.report.workers) reported += w.pixels;
  EXPECT_EQ(reported, map.pixelCount());
  EXPECT_EQ(run.report.info.driver, "simulated");
  EXPECT_EQ(run.report.info.strategy, GetParam());
  EXPECT_GE(run.report.elapsedSeconds, 3.0 / std::accumulate(speeds.begin(), speeds.end(), 0.0));
  EXPECT_LE(run.report.efficiency, 1.0);
  EXPECT_NEAR(run.report.masu, 3.45, 1e-9);
  EXPECT_NE(chromeTraceJson(run.events, 5, run.report.elapsedSeconds).find("rendering"),
            std::string::npos);
}

TEST_P(SimulatorStrategyTest, SameInputsSameReport) {
  const CostMap map = complexSceneCostMap(80, 60, 2.0);
  const SimulationOptions o = optionsFor(GetParam(), {1, 0.3, 0.6, 0.9, 0.5, 1}, 32);
  const SimulatedRun a = simulate(map, o);
  const SimulatedRun b = simulate(map, o);
  EXPECT_EQ(a.report.toJson(), b.report.toJson());
  ASSERT_EQ(a.events.size(), b.events.size());
  for (size_t i = 0; i < a.events.size(); ++i) {
    EXPECT_EQ(a.events[i].start, b.events[i].start) << i;
    EXPECT_EQ(a.events[i].label, b.events[i].label) << i;
  }
}

// One slow worker, two fast ones joining at a third of the image's time: every pixel once,
// never before the ideal for that schedule, and the joiners' arrival in the report.
TEST_P(SimulatorStrategyTest, WorkersJoiningMidRunAreAdmitted) {
  const CostMap map = complexSceneCostMap(97, 61, 3.0);
  SimulationOptions o = optionsFor(GetParam(), {0.25, 1, 1}, 16);
  o.joins = {JoinWave{1.0, 2}};
  const SimulatedRun run = simulate(map, o);
  EXPECT_EQ(renderedPixels(run), map.pixelCount());
  ASSERT_EQ(run.report.workers.size(), 3u);
  EXPECT_FALSE(run.report.workers[0].joinedAtSeconds.has_value());
  EXPECT_EQ(run.report.workers[1].joinedAtSeconds, 1.0);
  EXPECT_EQ(run.report.workers[2].joinedAtSeconds, 1.0);
  // The ideal: 0.25 s of work a second alone until 1 s, then 2.25 a second.
  ASSERT_TRUE(run.report.idealSeconds.has_value());
  EXPECT_GE(run.report.elapsedSeconds, 1.0 + (3.0 - 0.25) / 2.25);
  EXPECT_GE(run.report.elapsedSeconds, *run.report.idealSeconds * (1 - 1e-9));
}

// Failures, as a real run has them: a crash is lost at once (its connection drops), a hang
// a lease after the master last heard from it, a machine that fails mid-batch loses the batch
// with it; every strategy gets every pixel rendered by the workers left, the lost workers'
// unfinished tasks reissued and reported.
TEST_P(SimulatorStrategyTest, FailedWorkersAreLostAndTheirTasksRenderedByTheOthers) {
  const CostMap map = complexSceneCostMap(97, 61, 3.0);
  SimulationOptions o = optionsFor(GetParam(), {1, 0.5, 0.25, 1, 0.7}, 16);
  o.workerTimeoutSeconds = 0.5;
  o.faults = {FaultInjection{1, 40, FaultInjection::Kind::Crash},
              FaultInjection{3, 40, FaultInjection::Kind::Hang}};
  o.failShare = 0.2;  // one of five, mid-run
  o.failAtSeconds = 0.3;
  o.seed = 7;
  const SimulatedRun run = simulate(map, o);
  const FaultInfo& f = run.report.info.faults;
  ASSERT_GE(f.lostWorkers.size(), 1u);
  for (const LostWorkerInfo& l : f.lostWorkers) {
    // A worker whose share was under 40 pixels never reaches its fault; one that does is
    // lost, the hang only after a lease of silence.
    if (l.worker == 3) {
      EXPECT_GE(l.atSeconds, o.workerTimeoutSeconds);
    }
    if (l.worker == 1) {
      EXPECT_EQ(l.reason, "connection dropped");
    }
  }
  for (const WorkerReport& w : run.report.workers) {
    if (w.worker == 1 || w.worker == 3) {
      const bool lost = std::any_of(f.lostWorkers.begin(), f.lostWorkers.end(),
                                    [&](const LostWorkerInfo& l) { return l.worker == w.worker; });
      EXPECT_TRUE(lost || w.pixels < 40) << GetParam() << ", worker " << w.worker;
    }
  }
  EXPECT_EQ(f.workerTimeoutSeconds, 0.5);
  // Every pixel is in the image, from a worker that was not lost before it delivered it.
  for (int32_t owner : run.owner) ASSERT_GE(owner, 0);
  EXPECT_GE(renderedPixels(run), map.pixelCount());
  uint64_t unfinished = 0;
  for (const LostWorkerInfo& l : f.lostWorkers) unfinished += l.unfinished;
  EXPECT_EQ(f.reissuedTasks, unfinished);
}

TEST(SimulatorTest, ACrashIsLostAtOnceAndAHangAfterTheLease) {
  const CostMap map = uniformCostMap(64, 64, 8.0);
  for (const auto kind : {FaultInjection::Kind::Crash, FaultInjection::Kind::Hang}) {
    SimulationOptions o = optionsFor("self", {1, 1}, 64);
    o.workerTimeoutSeconds = 2.0;
      o.speedIndexRun = false;
    o.faults = {FaultInjection{1, 64, kind}};  // after its first batch
    const SimulatedRun run = simulate(map, o);
    const auto& lost = run.report.info.faults.lostWorkers;
    ASSERT_EQ(lost.size(), 1u);
    // Its first batch (64 px of 4,096 over 8 s: 0.125 s) then the failure; the hang is found
    // a lease after its last result (no heartbeat fell in between).
    const double failed = 0.125;
    if (kind == FaultInjection::Kind::Crash) {
      EXPECT_NEAR(lost[0].atSeconds, failed, 0.01);
      EXPECT_EQ(lost[0].reason, "connection dropped");
    } else {
      EXPECT_NEAR(lost[0].atSeconds, failed + 2.0, 0.01);
    }
  }
}

TEST(SimulatorTest, EveryWorkerLostIsAFailure) {
  const CostMap map = uniformCostMap(32, 32, 4.0);
  SimulationOptions o = optionsFor("adaptive", {1, 1, 1});
  o.failShare = 1.0;
  o.failAtSeconds = 0.5;
  EXPECT_THROW(simulate(map, o), std::runtime_error);
  o.failShare = 0;
  o.faults = {FaultInjection{0, 0, FaultInjection::Kind::Corrupt}};
  EXPECT_THROW(simulate(map, o), InputError);
  o.faults = {FaultInjection{3, 0, FaultInjection::Kind::Crash}};
  EXPECT_THROW(simulate(map, o), InputError);
}

// A thousand machines with a mean time between failures of a few times the run: the lost
// ones cost the run about a lease each, and the report counts them.
TEST(SimulatorTest, MachinesFailingAtRandomAreLostAndTheRunFinishes) {
  const CostMap map = complexSceneCostMap(320, 240, 1000.0);
  SimulationOptions o = optionsFor("adaptive", std::vector<double>(1000, 1.0), 16);
  o.mtbfSeconds = 10.0;
  o.seed = 3;
  o.workerTimeoutSeconds = 0.5;
  const SimulatedRun run = simulate(map, o);
  const size_t lost = run.report.info.faults.lostWorkers.size();
  // About 1 - exp(-T / 10) of them fail within the run's T of about a second.
  EXPECT_GT(lost, 30u);
  EXPECT_LT(lost, 300u);
  for (int32_t owner : run.owner) ASSERT_GE(owner, 0);
}

// Repaired machines come back as new workers, numbered after the others, and may fail again.
TEST(SimulatorTest, RepairedMachinesComeBackAsNewWorkers) {
  const CostMap map = complexSceneCostMap(160, 120, 400.0);
  SimulationOptions o = optionsFor("adaptive", std::vector<double>(100, 1.0), 16);
  o.mtbfSeconds = 4.0;
  o.repairSeconds = 0.5;
  o.workerTimeoutSeconds = 0.5;
  const SimulatedRun run = simulate(map, o);
  const FaultInfo& f = run.report.info.faults;
  ASSERT_GT(f.lostWorkers.size(), 20u);
  // Every loss of a machine that went silent brings a worker back half a second later,
  // unless the run ended first.
  const size_t back = run.report.workers.size() - 100;
  EXPECT_GT(back, 10u);
  EXPECT_LE(back, f.lostWorkers.size());
  for (size_t w = 100; w < run.report.workers.size(); ++w) {
    ASSERT_TRUE(run.report.workers[w].joinedAtSeconds.has_value()) << w;
  }
  for (int32_t owner : run.owner) ASSERT_GE(owner, 0);
  o.joins = {JoinWave{1.0, 1}};
  EXPECT_THROW(simulate(map, o), InputError);  // with --join-at: refused
}

TEST(SimulatorTest, DynamicStrategiesComeCloseToTheJoinSchedulesIdeal) {
  const CostMap map = complexSceneCostMap(160, 120, 12.0);
  for (const std::string name : {"adaptive", "stealing", "self"}) {
    SimulationOptions o = optionsFor(name, {0.25, 1, 1}, 32);
    o.joins = {JoinWave{4.0, 2}};
    const SimulatedRun run = simulate(map, o);
    // Ideal: 1 s of work done by 4 s, then 11 s at 2.25: 8.89 s.
    EXPECT_LT(run.report.elapsedSeconds, 1.1 * (4.0 + 11.0 / 2.25)) << name;
  }
  SimulationOptions scatter = optionsFor("scatter", {0.25, 1, 1}, 32);
  scatter.joins = {JoinWave{4.0, 2}};
  EXPECT_GT(simulate(map, scatter).report.elapsedSeconds, 40.0);  // the slow one does it all
}

TEST(SimulatorTest, AnOracleSpeedIndexCostsNoSetupAndGivesTheTrueIndices) {
  const CostMap map = uniformCostMap(64, 64, 1.0);
  SimulationOptions o = optionsFor("reservoir", {1, 0.5}, 64);
  o.oracleSpeedIndex = true;
  const SimulatedRun run = simulate(map, o);
  EXPECT_NEAR(run.report.elapsedSeconds, 1.0 / 1.5, 0.01);  // no 0.16 s of setup first
  EXPECT_DOUBLE_EQ(run.report.workers[1].speedIndexSeconds,
                   2 * run.report.workers[0].speedIndexSeconds);
}

// More joiners than pixels, as the thread driver takes them: only the starting workers must
// not outnumber the pixels; the joiners that find nothing left get nothing, for every strategy.
TEST_P(SimulatorStrategyTest, MoreJoinersThanPixels) {
  const CostMap map = uniformCostMap(4, 3, 1.0);
  SimulationOptions o = optionsFor(GetParam(), std::vector<double>(21, 1.0));
  o.joins = {JoinWave{0.0, 10}, JoinWave{0.5, 10}};
  const SimulatedRun run = simulate(map, o);
  EXPECT_EQ(renderedPixels(run), map.pixelCount());
}

TEST(SimulatorTest, JoinersMustLeaveAStartingWorker) {
  const CostMap map = uniformCostMap(8, 8, 1.0);
  SimulationOptions o = optionsFor("self", {1, 1});
  o.joins = {JoinWave{1.0, 2}};
  EXPECT_THROW(simulate(map, o), InputError);
}

INSTANTIATE_TEST_SUITE_P(AllStrategies, SimulatorStrategyTest,
                         ::testing::ValuesIn(strategyNames()));

TEST(SimulatorTest, HybridDiffusesFromSlowToFastWorkers) {
  const CostMap map = uniformCostMap(128, 128, 1.0);
  const SimulatedRun run = simulate(map, optionsFor("hybrid", {1, 1, 0.25, 0.25}, 32));
  uint64_t orders = 0, peerTasks = 0;
  for (const Event& e : run.events) {
    if (e.kind != EventKind::MessageSent) continue;
    if (e.label == "TransferOrder") ++orders;
    if (e.label == "Tasks" && e.worker >= 0) ++peerTasks;
  }
  EXPECT_GT(orders, 0u);
  EXPECT_GT(peerTasks, 0u);
  // Much better than scatter's 0.08 / 0.25 + 0.25 / 0.25 = 1.32 s.
  EXPECT_LT(run.report.elapsedSeconds, 0.9);
}

TEST(SimulatorTest, TheMasterLinkLimitsManyWorkers) {
  // 12 bytes a pixel of results through the master's 1 Gbit/s link: 4 M pixels need 0.4 s
  // however many workers share 1 s of rendering.
  const CostMap map = uniformCostMap(2048, 2048, 1.0);
  const SimulatedRun run = simulate(map, optionsFor("blocks", std::vector<double>(64, 1.0), 4096));
  EXPECT_GT(run.report.elapsedSeconds, 2048.0 * 2048 * 12 / 125e6);
  EXPECT_GT(run.report.bytes, 2048u * 2048 * 12);
}

TEST(SimulatorTest, BadOptionsAreInputErrors) {
  const CostMap map = uniformCostMap(8, 8, 1.0);
  auto message = [&](const SimulationOptions& o) {
    try {
      simulate(map, o);
    } catch (const InputError& e) {
      return std::string(e.what());
    }
    return std::string("no error");
  };
  EXPECT_NE(message(optionsFor("nope", {1})).find("valid strategies: scatter"), std::string::npos);
  EXPECT_NE(message(optionsFor("scatter", {})).find("at least 1"), std::string::npos);
  EXPECT_NE(message(optionsFor("scatter", {1, 0})).find("positive"), std::string::npos);
  EXPECT_NE(message(optionsFor("scatter", {1}, 0)).find("--batch"), std::string::npos);
  EXPECT_NE(message(optionsFor("scatter", std::vector<double>(65, 1.0))).find("more workers"),
            std::string::npos);
  SimulationOptions o = optionsFor("scatter", {1});
  o.network.bandwidthBytesPerSecond = 0;
  EXPECT_NE(message(o).find("bandwidth"), std::string::npos);
}

}  // namespace
}  // namespace prt

namespace prt {
namespace {

// --checkpoint-every: the master writes a checkpoint every interval and takes no message
// meanwhile, for a time proportional to the pixels done; with many workers that wait on it,
// the run takes longer, and the report counts the checkpoints and their time.
TEST(SimulatorTest, CheckpointsStopTheMasterForTheirModelledTime) {
  const CostMap map = uniformCostMap(256, 256, 60.0);
  SimulationOptions o = optionsFor("self", std::vector<double>(16, 1.0), 16);
  const SimulatedRun plain = simulate(map, o);
  o.checkpointEverySeconds = 0.5;
  o.checkpointSecondsPerPixel = 0;  // free: the same run
  const SimulatedRun free = simulate(map, o);
  EXPECT_DOUBLE_EQ(free.report.elapsedSeconds, plain.report.elapsedSeconds);
  o.checkpointSecondsPerPixel = 4e-6;  // up to 0.26 s for the whole image
  const SimulatedRun costly = simulate(map, o);
  const MasterLoad& m = *costly.report.info.master;
  const double elapsed = costly.report.elapsedSeconds;
  EXPECT_GT(elapsed, plain.report.elapsedSeconds * 1.05);  // self-scheduling waits on each
  // One per interval plus the write, none after the end.
  EXPECT_GE(static_cast<double>(m.checkpoints), elapsed / (0.5 + 0.27) - 1);
  EXPECT_LE(static_cast<double>(m.checkpoints), elapsed / 0.5);
  EXPECT_GT(m.checkpointSeconds, 0.0);
  EXPECT_LE(m.checkpointSeconds, static_cast<double>(m.checkpoints) * 4e-6 * 256 * 256);
  const nlohmann::json j = nlohmann::json::parse(costly.report.toJson());
  EXPECT_EQ(j["master"]["checkpoints"].get<uint64_t>(), m.checkpoints);
  EXPECT_EQ(renderedPixels(costly), 256u * 256u);
}

}  // namespace
}  // namespace prt
