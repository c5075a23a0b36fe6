#include "farm/local_driver.h"

#include <gtest/gtest.h>

#include "core/input_error.h"
#include "trace/renderer.h"

namespace prt {
namespace {

Scene smallScene(int width = 20, int height = 14) {
  Scene scene;
  scene.image.width = width;
  scene.image.height = height;
  scene.camera.eye = Vec3(0, 1.5, -5);
  scene.camera.lookAt = Vec3(0, 0.8, 0);
  scene.lights.push_back({SphereLight{{3, 5, -3}, 0.6}, Color(1)});
  Material glass;
  glass.transmissivity = 0.8;
  glass.ior = 1.5;
  glass.diffuse = 0.1;
  Material floor;
  floor.reflectivity = 0.4;
  floor.glossDegrees = 3;
  scene.objects.push_back({SphereShape{{0, 1, 0}, 1}, glass});
  scene.objects.push_back({PlaneShape{{0, 0, 0}, {0, 1, 0}}, floor});
  return scene;
}

LocalRunRequest request(const std::string& strategy, int workers) {
  LocalRunRequest r;
  r.scene = smallScene();
  r.settings = RenderSettings{2, 2};
  r.options.workers = workers;
  r.options.strategy = strategy;
  r.options.batchPixels = 16;
  // Long enough (about half a millisecond) that a worker preempted during it does not measure
  // a hundred times slower than the others, which would leave it no initial block of the
  // reservoir and so no work for a fault to strike.
  r.options.speedIndexDiscs = 18;
  r.options.strategyOptions.chunk = 9;
  return r;
}

Image serialImage(const RenderSettings& settings, int width = 20, int height = 14) {
  const World world(smallScene(width, height));
  return renderImage(Renderer(world, settings), 1);
}

const Image& serialReference() {
  static const Image image = serialImage(RenderSettings{2, 2});
  return image;
}

// The master's own load is measured (CPU time outside its waits, every message in and out),
// and a heartbeat goes only after a silence: with a 60 s lease (12 s between beats) a short
// run has each worker's one at its start and none from the master.
TEST(MasterLoad, IsMeasuredAndHeartbeatsFollowOnlySilence) {
  LocalRunRequest r = request("adaptive", 3);
  r.options.workerTimeoutSeconds = 60;
  const ParallelRun run = renderLocal(r);
  ASSERT_TRUE(run.report.info.master.has_value());
  const MasterLoad& m = *run.report.info.master;
  EXPECT_EQ(m.basis, "measured_cpu");
  EXPECT_GT(m.busySeconds, 0);
  const std::optional<double> share = run.report.masterBusyShare();
  ASSERT_TRUE(share.has_value());
  EXPECT_GT(*share, 0);
  EXPECT_LE(*share, 1.5);  // CPU time over wall time, of one thread (timer granularity aside)
  EXPECT_EQ(m.heartbeatsReceived, 3u) << "one from each worker as it starts, then none";
  EXPECT_EQ(m.heartbeatsSent, 0u);
  uint64_t results = 0;
  for (const Event& e : run.events) {
    if (e.kind == EventKind::MessageReceived && e.worker == kMaster && e.label == "Results") {
      ++results;
    }
  }
  EXPECT_GT(results, 0u);
  EXPECT_GE(m.received, results + m.heartbeatsReceived);
  EXPECT_GT(m.sent, 0u);
  EXPECT_NE(run.report.toJson().find("\"master_busy_share\""), std::string::npos);
  EXPECT_NE(run.report.toTable().find("master: busy"), std::string::npos);
}

class LocalDriverTest : public ::testing::TestWithParam<std::string> {};

TEST_P(LocalDriverTest, ImageIsBitIdenticalToSerialForAnyWorkerCount) {
  for (int workers : {1, 2, 3, 5, 8, 16}) {
    const ParallelRun run = renderLocal(request(GetParam(), workers));
    EXPECT_TRUE(run.image == serialReference()) << workers << " workers";
    uint64_t pixels = 0;
    for (const WorkerReport& w : run.report.workers) pixels += w.pixels;
    EXPECT_EQ(pixels, serialReference().pixelCount()) << "every pixel rendered exactly once";
    for (int16_t owner : run.owner) ASSERT_GE(owner, 0);
  }
}

TEST_P(LocalDriverTest, CrashedWorkerIsReplacedAndImageUnchanged) {
  LocalRunRequest r = request(GetParam(), 3);
  // Crash at its first batch: it then holds tasks no one else has, so the run cannot finish
  // without reassigning them (a later crash can race with the others finishing the image).
  r.options.faults.push_back({1, 0, FaultInjection::Kind::Crash});
  const ParallelRun run = renderLocal(r);
  EXPECT_TRUE(run.image == serialReference());
  // Whole frames to whole workers: a still is one frame, all of it worker 0's.
  if (GetParam() == "frames") return;
  EXPECT_TRUE(run.report.workers[1].lost);
}

// The lost worker held every task and the live ones had been given nothing (a 16x1 image,
// chunks of 64, reservoir shares rounding up): the run used to wait for ever.
TEST_P(LocalDriverTest, WorkerLostHoldingEverythingIsReplaced) {
  LocalRunRequest r = request(GetParam(), 2);
  r.scene = smallScene(16, 1);
  r.options.strategyOptions.chunk = 64;
  r.options.faults.push_back({0, 0, FaultInjection::Kind::Crash});
  const ParallelRun run = renderLocal(r);
  EXPECT_TRUE(run.image == serialImage(r.settings, 16, 1));
  EXPECT_TRUE(run.report.workers[0].lost);
  EXPECT_EQ(run.report.info.faults.lostWorkers.size(), 1u);
}

TEST_P(LocalDriverTest, LostFastWorkerWithSlowOthersIsReplaced) {
  LocalRunRequest r = request(GetParam(), 3);
  r.scene = smallScene(3, 1);
  r.options.slowdowns = {1, 20, 20};
  r.options.faults.push_back({0, 0, FaultInjection::Kind::Crash});
  const ParallelRun run = renderLocal(r);
  EXPECT_TRUE(run.image == serialImage(r.settings, 3, 1));
}

TEST_P(LocalDriverTest, HungWorkerWithATinyInitialShareIsReplaced) {
  LocalRunRequest r = request(GetParam(), 2);
  r.scene = smallScene(16, 12);
  r.options.strategyOptions.initialPercent = 0.01;
  r.options.workerTimeoutSeconds = 1;
  r.options.faults.push_back({0, 0, FaultInjection::Kind::Hang});
  const ParallelRun run = renderLocal(r);
  EXPECT_TRUE(run.image == serialImage(r.settings, 16, 12));
}

// An initial share that rounds to no task at all, and no fault: every worker still asks.
TEST_P(LocalDriverTest, InitialShareOfNothingStillFinishes) {
  LocalRunRequest r = request(GetParam(), 3);
  r.options.strategyOptions.initialPercent = 1e-14;
  const ParallelRun run = renderLocal(r);
  EXPECT_TRUE(run.image == serialReference());
}

TEST_P(LocalDriverTest, EndgameCopiesKeepTheImageAndEveryPixelOnce) {
  LocalRunRequest r = request(GetParam(), 3);
  r.options.endgame = true;
  r.options.slowdowns = {1, 1, 6};
  const ParallelRun run = renderLocal(r);
  EXPECT_TRUE(run.image == serialReference());
  for (int16_t owner : run.owner) ASSERT_GE(owner, 0);
}

// A resumed run renders only what the checkpoint lacks, and the image is the same.
TEST_P(LocalDriverTest, ResumedRunRendersOnlyTheMissingPixels) {
  Checkpoint c;
  c.image = serialReference();
  c.owner.assign(c.image.pixelCount(), 7);
  c.done = TaskSet::range(0, 100);
  c.done.append(TaskSet::strided(150, 20, 3));
  std::vector<bool> isDone(c.image.pixelCount(), false);
  c.done.forEach([&](uint64_t p) { isDone[p] = true; });
  for (uint64_t p = 0; p < c.image.pixelCount(); ++p) {
    if (!isDone[p]) c.image.set(p, Color(0));
  }
  LocalRunRequest r = request(GetParam(), 3);
  r.resumeFrom = c;
  const ParallelRun run = renderLocal(r);
  EXPECT_TRUE(run.image == serialReference());
  uint64_t rendered = 0;
  for (const WorkerReport& w : run.report.workers) rendered += w.pixels;
  EXPECT_EQ(rendered, serialReference().pixelCount() - c.done.size());
  EXPECT_EQ(run.report.info.faults.resumedPixels, c.done.size());
  c.done.forEach([&](uint64_t p) { ASSERT_EQ(run.owner[p], 7); });
}

// Workers of several threads each, as machines of several cores: the same image.
TEST_P(LocalDriverTest, MultiThreadedWorkersKeepTheImage) {
  LocalRunRequest r = request(GetParam(), 2);
  r.options.threads = 2;
  const ParallelRun run = renderLocal(r);
  EXPECT_TRUE(run.image == serialReference());
  for (const WorkerReport& w : run.report.workers) EXPECT_EQ(w.threads, 2);
}

INSTANTIATE_TEST_SUITE_P(AllStrategies, LocalDriverTest, ::testing::ValuesIn(strategyNames()));

TEST_P(LocalDriverTest, WorkersJoiningMidRenderKeepTheImage) {
  LocalRunRequest r = request(GetParam(), 1);
  r.options.slowdowns = {30, 1, 1};
  r.options.joins = {JoinWave{0.02, 2}};
  const ParallelRun run = renderLocal(r);
  EXPECT_TRUE(run.image == serialReference());
  // The joiners are in the report whether or not they came in time to render (a static
  // strategy gives them nothing).
  ASSERT_LE(run.report.workers.size(), 3u);
  for (size_t w = 1; w < run.report.workers.size(); ++w) {
    ASSERT_TRUE(run.report.workers[w].joinedAtSeconds.has_value());
    EXPECT_GE(*run.report.workers[w].joinedAtSeconds, 0.02);
  }
}

TEST(LocalDriverFaultTest, HungWorkerIsDetectedByTimeout) {
  // Scatter gives every worker its share up front. Under the reservoir a worker preempted
  // during its speed index (microseconds here) measures a thousand times slower, gets no
  // initial block, and the others finish the image before it ever has work to hang on.
  LocalRunRequest r = request("scatter", 3);
  r.options.workerTimeoutSeconds = 2.0;  // generous: CI may run other tests alongside
  r.options.faults.push_back({2, 0, FaultInjection::Kind::Hang});
  const ParallelRun run = renderLocal(r);
  EXPECT_TRUE(run.image == serialReference());
  EXPECT_TRUE(run.report.workers[2].lost);
  EXPECT_FALSE(run.report.workers[0].lost);
  ASSERT_EQ(run.report.info.faults.lostWorkers.size(), 1u);
  EXPECT_NE(run.report.info.faults.lostWorkers[0].reason.find("silent"), std::string::npos);
  EXPECT_GT(run.report.info.faults.reissuedTasks, 0u);
}

TEST(LocalDriverFaultTest, EveryWorkerCrashingFailsInsteadOfHanging) {
  LocalRunRequest r = request("self", 2);
  r.options.faults.push_back({0, 0, FaultInjection::Kind::Crash});
  r.options.faults.push_back({1, 0, FaultInjection::Kind::Crash});
  EXPECT_THROW(renderLocal(r), RunFailed);
}

// Every starting worker lost before the workers due to join arrive: the run fails (it does not
// wait for them), and the message says so instead of leaving them unmentioned.
TEST(LocalDriverFaultTest, EveryStartingWorkerLostBeforeTheJoinersSaysTheyWereNotWaitedFor) {
  LocalRunRequest r = request("self", 1);
  r.options.joins = {JoinWave{30, 2}};
  r.options.faults.push_back({0, 0, FaultInjection::Kind::Crash});
  try {
    renderLocal(r);
    FAIL() << "the run cannot finish";
  } catch (const RunFailed& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find("every worker was lost"), std::string::npos) << what;
    EXPECT_NE(what.find("2 workers still due to join (--join-at)"), std::string::npos) << what;
  }
}

TEST(LocalDriverOptionsTest, BadOptionsAreInputErrors) {
  LocalRunRequest r = request("reservoir", 2);
  r.options.slowdowns = {1, 2, 3};
  EXPECT_THROW(renderLocal(r), InputError);
  r.options.slowdowns = {1, 0.5};
  EXPECT_THROW(renderLocal(r), InputError);
  r.options.slowdowns.clear();
  r.options.strategy = "nonesuch";
  EXPECT_THROW(renderLocal(r), InputError);
  r.options.strategy = "reservoir";
  r.options.workers = 20 * 14 + 1;
  EXPECT_THROW(renderLocal(r), InputError);
}

TEST(LocalDriverReportTest, ReportCountsMessagesAndSpeedIndices) {
  LocalRunRequest r = request("reservoir", 2);
  // Both emulated, so both indices are k times the CPU time of the same run (a full-speed
  // worker reports wall time, which a busy machine can stretch past a slow worker's).
  r.options.slowdowns = {2, 6};
  r.options.speedIndexDiscs = 16;
  r.masterSpeedIndexSeconds = 0.01;
  r.serialSeconds = 1.0;
  const ParallelRun run = renderLocal(r);
  EXPECT_GT(run.report.messages, 4u);
  EXPECT_GT(run.report.workers[1].speedIndexSeconds, run.report.workers[0].speedIndexSeconds);
  EXPECT_TRUE(run.report.speedup.has_value());
  EXPECT_GT(run.report.efficiency, 0.0);
  EXPECT_LE(run.report.efficiency, 1.0 + 1e-9);
}

}  // namespace
}  // namespace prt

namespace prt {
namespace {

TEST(LocalDriverSpeedIndexTest, ProbeSpeedIndexRanksSlowWorkersAndKeepsTheImage) {
  LocalRunRequest r = request("reservoir", 2);
  // Six samples a pixel: a probe of a few milliseconds, which a cold cache or a clock's
  // granularity cannot reorder.
  r.settings = RenderSettings{6, 2};
  r.options.speedIndexKind = SpeedIndexKind::RenderProbe;
  r.options.slowdowns = {2, 8};
  const ParallelRun run = renderLocal(r);
  EXPECT_TRUE(run.image == serialImage(r.settings));
  EXPECT_GT(run.report.workers[1].speedIndexSeconds, run.report.workers[0].speedIndexSeconds);
}

}  // namespace
}  // namespace prt
