#include "loops/worker_reactor.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <stdexcept>

namespace prt {
namespace {

WorkerReactorOptions plain() {
  WorkerReactorOptions o;
  o.batchPixels = 4;
  o.heartbeatSeconds = 1;
  o.masterTimeoutSeconds = 5;
  return o;
}

// Scene, setup, tasks: the reactor ready to render its first batch at `now`.
void setUp(WorkerReactor& r, double now) {
  r.begin(now);
  r.onMessage(kMaster, SceneMsg{"s", 1, 1}, 10, now);
  ASSERT_EQ(r.next(now), WorkerStep::Setup);
  r.onSetupDone(now, 0.1, std::nullopt, {});
  r.takeOutbox();
  r.onMessage(kMaster, TasksMsg{TaskSet::range(0, 8)}, 10, now);
}

TEST(WorkerReactorTest, MailWaitsWhileTheWorkerComputesAndIsReadBeforeTheNextBatch) {
  WorkerReactor r(0, plain());
  setUp(r, 0);
  ASSERT_EQ(r.next(0), WorkerStep::Batch);
  EXPECT_EQ(r.batch().size(), 4u);
  EXPECT_TRUE(r.computing());
  EXPECT_EQ(r.next(0), WorkerStep::Wait) << "one computation at a time";
  r.onMessage(kMaster, StopMsg{}, 4, 0.5);
  EXPECT_FALSE(r.worker().stopped()) << "read only once the batch is done";
  r.onBatchDone(1, std::vector<float>(12, 0.f), 1, 100);
  EXPECT_TRUE(r.worker().stopped());
  EXPECT_EQ(r.next(1), WorkerStep::Stop);
  const WorkerSummary s = r.summary(1, 1);
  EXPECT_EQ(s.rays, 100u);
  int computes = 0;
  for (const Event& e : s.events) computes += e.kind == EventKind::Compute;
  EXPECT_EQ(computes, 1);
}

TEST(WorkerReactorTest, AHeartbeatFollowsASilenceTowardsTheMasterAndItsSilenceIsNoticed) {
  WorkerReactor r(0, plain());
  r.begin(0);
  EXPECT_TRUE(r.takeHeartbeat()) << "the first goes out at once";
  EXPECT_FALSE(r.takeHeartbeat());
  r.onDeadline(0.5);
  EXPECT_FALSE(r.takeHeartbeat());
  r.onDeadline(1.0);
  EXPECT_TRUE(r.takeHeartbeat());
  EXPECT_DOUBLE_EQ(r.nextDeadline(), 2.0);
  EXPECT_FALSE(r.masterSilent(4.9));
  r.onMessage(kMaster, HeartbeatMsg{}, 2, 4.9);
  EXPECT_FALSE(r.masterSilent(9.8));
  EXPECT_TRUE(r.masterSilent(10));
}

TEST(WorkerReactorTest, WithoutHeartbeatsNoneIsDueAndTheMasterIsNeverSilent) {
  WorkerReactorOptions o = plain();
  o.heartbeatSeconds = std::numeric_limits<double>::infinity();
  o.masterTimeoutSeconds = std::numeric_limits<double>::infinity();
  WorkerReactor r(0, o);
  r.begin(0);
  r.onDeadline(1e9);
  EXPECT_FALSE(r.takeHeartbeat());
  EXPECT_FALSE(r.masterSilent(1e9));
  EXPECT_FALSE(std::isfinite(r.nextDeadline()));
}

TEST(WorkerReactorTest, AnInjectedFaultComesBeforeTheBatchAfterItsPixels) {
  for (const auto kind : {FaultInjection::Kind::Crash, FaultInjection::Kind::Hang}) {
    WorkerReactorOptions o = plain();
    o.fault = FaultInjection{0, 4, kind};
    WorkerReactor r(0, o);
    setUp(r, 0);
    ASSERT_EQ(r.next(0), WorkerStep::Batch);
    r.onBatchDone(1, std::vector<float>(12, 0.f), 1, 0);
    EXPECT_EQ(r.next(1),
              kind == FaultInjection::Kind::Crash ? WorkerStep::Crash : WorkerStep::Hang);
  }
}

TEST(WorkerReactorTest, ABadMessageFromAPeerIsCountedAndFromTheMasterEndsTheWorker) {
  WorkerReactor r(0, plain());
  r.begin(0);
  r.onMalformed(3, "garbage");
  EXPECT_THROW(r.onMalformed(kMaster, "garbage"), std::runtime_error);
}

TEST(WorkerReactorTest, ASimulatedBatchComesBackWithoutColours) {
  WorkerReactorOptions o = plain();
  o.colours = false;
  WorkerReactor r(0, o);
  setUp(r, 0);
  ASSERT_EQ(r.next(0), WorkerStep::Batch);
  r.onBatchDone(2, {}, 2, 0);
  const Outbox out = r.takeOutbox();
  ASSERT_FALSE(out.empty());
  const auto* results = std::get_if<ResultsMsg>(&out[0].message);
  ASSERT_NE(results, nullptr);
  EXPECT_EQ(results->tasks.size(), 4u);
  EXPECT_TRUE(results->rgb.empty());
  EXPECT_DOUBLE_EQ(results->computeSeconds, 2);
}

}  // namespace
}  // namespace prt
