#include "cluster/worker.h"

#include <gtest/gtest.h>

namespace prt {
namespace {

// A worker with the scene, set up, holding `tasks` tasks.
Worker holding(WorkerOptions options, uint64_t tasks) {
  Worker w(0, options);
  w.onMessage(kMaster, SceneMsg{"scene", 1, 1});
  w.setupDone(1.0);
  w.onMessage(kMaster, TasksMsg{TaskSet::range(0, tasks)});
  return w;
}

TEST(WorkerBatches, FixedWithoutBatchSeconds) {
  Worker w = holding(WorkerOptions{100, 0}, 1000);
  for (int i = 0; i < 3; ++i) {
    const TaskSet b = w.nextBatch();
    EXPECT_EQ(b.size(), 100u);
    w.batchDone(b, 0.0001);  // fast, but batches do not grow
  }
}

TEST(WorkerBatches, GrowToTheSecondsAtTheLastRateWithinTheirBounds) {
  Worker w = holding(WorkerOptions{100, 0.05}, 1'000'000);
  TaskSet b = w.nextBatch();
  EXPECT_EQ(b.size(), 100u) << "no rate yet: the least batch";
  w.batchDone(b, 0.001);  // 100,000 pixels per second: 0.05 s is 5,000 pixels
  b = w.nextBatch();
  EXPECT_EQ(b.size(), 5000u);
  w.batchDone(b, 5.0);  // now 1,000 per second: 50 pixels, below the least
  b = w.nextBatch();
  EXPECT_EQ(b.size(), 100u);
  w.batchDone(b, 1e-9);  // absurdly fast: at most 64 times the least, and proportionally
                        // more for a batch time above the small-scale one (0.05 / 0.03)
  EXPECT_EQ(w.nextBatch().size(),
            static_cast<uint64_t>(100.0 * WorkerOptions::kMaxBatchGrowth * 0.05 / 0.03));
}

TEST(WorkerBatches, AtTheSmallScaleBatchTimeTheGrowthStaysSixtyFourFold) {
  Worker w = holding(WorkerOptions{100, WorkerOptions::kSmallScaleBatchSeconds}, 1'000'000);
  w.batchDone(w.nextBatch(), 1e-9);
  EXPECT_EQ(w.nextBatch().size(), 100u * WorkerOptions::kMaxBatchGrowth);
}

TEST(DefaultBatchSeconds, StaysAtTheSmallScaleValueUntilTheMasterWouldBeAFifthBusy) {
  EXPECT_EQ(defaultBatchSeconds(1), WorkerOptions::kSmallScaleBatchSeconds);
  EXPECT_EQ(defaultBatchSeconds(1000), WorkerOptions::kSmallScaleBatchSeconds);
  // W workers, one result each per batch time, kMasterSecondsPerResult each: a fifth busy.
  for (int w : {4096, 65536}) {
    const double share = w * kMasterSecondsPerResult / defaultBatchSeconds(w);
    EXPECT_NEAR(share, kMasterResultsShare, 1e-12) << w;
  }
  EXPECT_NEAR(defaultBatchSeconds(65536), 1.63840, 1e-9);
}

TEST(WorkerBatches, AnUnmeasuredBatchKeepsTheLastRateAndTheQueueBoundsTheBatch) {
  Worker w = holding(WorkerOptions{10, 0.1}, 200);
  TaskSet b = w.nextBatch();
  w.batchDone(b, 0.01);  // 1,000 per second: 100 pixels
  b = w.nextBatch();
  EXPECT_EQ(b.size(), 100u);
  w.batchDone(b);  // unmeasured (0 s): the rate stays
  EXPECT_EQ(w.nextBatch().size(), 90u) << "what is left";
}

// What only the master may send, sent by a peer (or relayed through one), is dropped and
// counted; so are a second scene, tasks outside the render and a transfer to no one.
TEST(WorkerSenders, OnlyTheMasterStopsQueriesOrdersAndSendsTheScene) {
  Worker w(1, WorkerOptions{10, 0});
  EXPECT_TRUE(w.onMessage(2, SceneMsg{"forged", 1, 1}).empty());
  EXPECT_FALSE(w.needsSetup()) << "a scene from a peer was taken";
  EXPECT_TRUE(w.onMessage(2, TasksMsg{TaskSet::range(0, 5)}).empty());
  EXPECT_EQ(w.queueLength(), 0u) << "tasks from a peer before the worker is set up";
  w.onMessage(kMaster, SceneMsg{"scene", 1, 1});
  EXPECT_TRUE(w.onMessage(kMaster, SceneMsg{"again", 1, 1}).empty());
  EXPECT_EQ(w.scene().sceneText, "scene");
  w.setupDone(1.0);
  w.limitTasks(100);
  w.onMessage(kMaster, TasksMsg{TaskSet::range(0, 20)});
  EXPECT_EQ(w.refusedMessages(), 3u);
  EXPECT_TRUE(w.onMessage(2, StopMsg{}).empty());
  EXPECT_FALSE(w.stopped());
  EXPECT_TRUE(w.onMessage(2, QueryQueueMsg{}).empty());
  EXPECT_TRUE(w.onMessage(2, TransferOrderMsg{3, 5}).empty());
  EXPECT_TRUE(w.onMessage(kMaster, TransferOrderMsg{1, 5}).empty()) << "a transfer to itself";
  EXPECT_TRUE(w.onMessage(kMaster, TransferOrderMsg{kMaster, 5}).empty());
  EXPECT_TRUE(w.onMessage(kMaster, TasksMsg{TaskSet::range(95, 10)}).empty());
  EXPECT_TRUE(w.onMessage(2, CheckMsg{TaskSet::range(0, 2)}).empty()) << "a check from a peer";
  EXPECT_TRUE(w.onMessage(kMaster, CheckMsg{TaskSet::range(99, 2)}).empty());
  EXPECT_EQ(w.queueLength(), 20u);
  EXPECT_EQ(w.refusedMessages(), 11u);
  // A peer's transfer within the render is diffusion, and taken.
  w.onMessage(2, TasksMsg{TaskSet::range(50, 10)});
  EXPECT_EQ(w.queueLength(), 30u);
  EXPECT_FALSE(w.onMessage(kMaster, QueryQueueMsg{}).empty());
  w.onMessage(kMaster, StopMsg{});
  EXPECT_TRUE(w.stopped());
}

// A peer's transfer that cannot be the tail of a queue (2^40 copies of one pixel, more tasks
// than the render has, a queue grown past twice the render) is refused without being walked,
// and so is everything that peer sends after; other peers are still heard.
TEST(WorkerSenders, APeersTransferThatCannotBeAQueuesTailIsRefusedAndSoIsThatPeer) {
  Worker w = holding(WorkerOptions{10, 0}, 20);
  w.limitTasks(100);
  const TaskSet copies = [] {
    TaskSet s;
    s.append(TaskRun{0, uint64_t{1} << 40, 0});
    return s;
  }();
  EXPECT_TRUE(w.onMessage(2, TasksMsg{copies}).empty());
  EXPECT_EQ(w.queueLength(), 20u) << "2^40 copies of pixel 0 were queued";
  EXPECT_EQ(w.refusedMessages(), 1u);
  w.onMessage(2, TasksMsg{TaskSet::range(50, 10)});
  EXPECT_EQ(w.queueLength(), 20u) << "a refused peer is refused from then on";
  EXPECT_EQ(w.refusedMessages(), 2u);
  // Two copies of a pixel in one run (stride 0) are no queue's tail either.
  w.onMessage(3, TasksMsg{TaskSet::strided(7, 2, 0)});
  EXPECT_EQ(w.queueLength(), 20u);
  // Another peer's true transfer is taken; then one more than the render has is not.
  w.onMessage(4, TasksMsg{TaskSet::range(50, 10)});
  EXPECT_EQ(w.queueLength(), 30u);
  w.onMessage(5, TasksMsg{TaskSet::strided(0, 101, 1)});
  EXPECT_EQ(w.queueLength(), 30u) << "more tasks than the render has";
  // Within the bounds, a queue at most twice the render.
  w.onMessage(6, TasksMsg{TaskSet::range(0, 100)});
  w.onMessage(6, TasksMsg{TaskSet::range(0, 70)});
  EXPECT_EQ(w.queueLength(), 200u);
  w.onMessage(7, TasksMsg{TaskSet::range(0, 1)});
  EXPECT_EQ(w.queueLength(), 200u) << "a queue longer than twice the render";
  EXPECT_EQ(w.refusedMessages(), 5u);
}

// A spot check is rendered before the next batch of the worker's own tasks, and goes back as
// check results, not as results: it is not the worker's task, and asks for nothing.
TEST(WorkerChecks, AreRenderedFirstAndReturnedApart) {
  Worker w = holding(WorkerOptions{10, 0}, 30);
  EXPECT_TRUE(w.onMessage(kMaster, CheckMsg{TaskSet::strided(40, 2, 5)}).empty());
  EXPECT_EQ(w.queueLength(), 30u) << "checks are not queued with its tasks";
  const TaskSet check = w.nextBatch();
  EXPECT_EQ(check, TaskSet::strided(40, 2, 5));
  const Outbox back = w.batchDone(check, {1, 2, 3, 4, 5, 6});
  ASSERT_EQ(back.size(), 1u);
  const auto* r = std::get_if<CheckResultsMsg>(&back[0].message);
  ASSERT_NE(r, nullptr);
  EXPECT_EQ(r->tasks, check);
  EXPECT_EQ(r->rgb, (std::vector<float>{1, 2, 3, 4, 5, 6}));
  EXPECT_EQ(w.nextBatch(), TaskSet::range(0, 10)) << "then its own tasks";
  // A worker with nothing of its own still renders a check.
  Worker idle = holding(WorkerOptions{10, 0}, 0);
  EXPECT_FALSE(idle.hasWork());
  idle.onMessage(kMaster, CheckMsg{TaskSet::range(3, 1)});
  EXPECT_TRUE(idle.hasWork());
}

}  // namespace
}  // namespace prt
