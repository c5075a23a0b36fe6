#include "loops/worker_summary.h"

#include <gtest/gtest.h>

#include <stdexcept>

namespace prt {
namespace {

bool sameEvent(const Event& a, const Event& b) {
  return a.kind == b.kind && a.worker == b.worker && a.start == b.start && a.end == b.end &&
         a.pixels == b.pixels && a.bytes == b.bytes && a.peer == b.peer && a.label == b.label;
}

WorkerSummary sample() {
  WorkerSummary s;
  s.rays = 123456789012ull;
  s.tasksReceived = 7;
  s.framesBuilt = 3;
  s.nonFiniteSamples = 5;
  s.events.push_back({EventKind::MessageReceived, 2, 0.0, 0.0, 0, 4096, kMaster, "Scene"});
  s.events.push_back({EventKind::Setup, 2, 0.001, 0.25, 0, 0, 0, ""});
  s.events.push_back({EventKind::MessageSent, 2, 0.25, 0.25, 0, 9, kMaster, "SpeedIndex"});
  s.events.push_back({EventKind::Compute, 2, 0.3, 0.4125, 128, 0, 0, ""});
  s.events.push_back({EventKind::MessageSent, 2, 0.5, 0.5, 0, 77, 1, "Tasks"});
  return s;
}

TEST(WorkerSummaryTest, RoundTripsEveryField) {
  const WorkerSummary s = sample();
  const WorkerSummary back = decodeSummary(encodeSummary(s));
  EXPECT_EQ(back.rays, s.rays);
  EXPECT_EQ(back.tasksReceived, s.tasksReceived);
  EXPECT_EQ(back.framesBuilt, s.framesBuilt);
  EXPECT_EQ(back.nonFiniteSamples, s.nonFiniteSamples);
  ASSERT_EQ(back.events.size(), s.events.size());
  for (size_t i = 0; i < s.events.size(); ++i) {
    EXPECT_TRUE(sameEvent(back.events[i], s.events[i])) << i;
  }
}

TEST(WorkerSummaryTest, MalformedBuffersThrow) {
  const Bytes good = encodeSummary(sample());
  for (size_t n = 0; n < good.size(); n += 5) {
    EXPECT_THROW(decodeSummary(good.data(), n), std::runtime_error) << n;
  }
  Bytes trailing = good;
  trailing.push_back(0);
  EXPECT_THROW(decodeSummary(trailing), std::runtime_error);
  Bytes badVersion = good;
  badVersion[0] = 99;
  EXPECT_THROW(decodeSummary(badVersion), std::runtime_error);
}

TEST(WorkerClockOffsetTest, SplitsTheRoundTripEvenly) {
  // The master sends the scene at 1.0 and hears the speed index at 1.6; the worker replied
  // 0.4 s after the scene reached it, so each leg took 0.1 s.
  const std::vector<Event> master = {
      {EventKind::MessageSent, kMaster, 1.0, 1.0, 0, 100, 2, "Scene"},
      {EventKind::MessageReceived, kMaster, 1.6, 1.6, 0, 9, 2, "SpeedIndex"}};
  const std::vector<Event> worker = {
      {EventKind::MessageReceived, 2, 0.0, 0.0, 0, 100, kMaster, "Scene"},
      {EventKind::MessageSent, 2, 0.4, 0.4, 0, 9, kMaster, "SpeedIndex"}};
  EXPECT_DOUBLE_EQ(workerClockOffset(master, worker, 2), 1.1);
  // Another worker's messages do not count; without a reply the scene send is the offset.
  EXPECT_DOUBLE_EQ(workerClockOffset(master, {}, 2), 1.0);
  EXPECT_DOUBLE_EQ(workerClockOffset(master, worker, 3), 0.0);
  // A worker whose clock started 5 s before the scene reached it: the same placement.
  const std::vector<Event> late = {
      {EventKind::MessageReceived, 2, 5.0, 5.0, 0, 100, kMaster, "Scene"},
      {EventKind::MessageSent, 2, 5.4, 5.4, 0, 9, kMaster, "SpeedIndex"}};
  EXPECT_DOUBLE_EQ(workerClockOffset(master, late, 2) + 5.0, 1.1);
}

TEST(WorkerClockOffsetTest, NeverPlacesTheReceiptBeforeTheSend) {
  // Timer granularity can make the worker's interval look longer than the master's.
  const std::vector<Event> master = {
      {EventKind::MessageSent, kMaster, 2.0, 2.0, 0, 100, 0, "Scene"},
      {EventKind::MessageReceived, kMaster, 2.3, 2.3, 0, 9, 0, "SpeedIndex"}};
  const std::vector<Event> worker = {
      {EventKind::MessageSent, 0, 0.31, 0.31, 0, 9, kMaster, "SpeedIndex"}};
  EXPECT_DOUBLE_EQ(workerClockOffset(master, worker, 0), 2.0);
}

}  // namespace
}  // namespace prt
