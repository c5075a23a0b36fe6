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
  w.batchDone(b, 1e-9);  // absurdly fast: at most 64 times the least
  EXPECT_EQ(w.nextBatch().size(), 100u * WorkerOptions::kMaxBatchGrowth);
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

}  // namespace
}  // namespace prt
