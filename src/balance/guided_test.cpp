#include "balance/guided.h"

#include <gtest/gtest.h>

namespace prt {
namespace {

uint64_t assignedCount(const Decisions& d, int worker) {
  EXPECT_EQ(d.size(), 1u);
  const auto* a = std::get_if<Assign>(&d.front());
  if (a == nullptr || a->worker != worker) {
    ADD_FAILURE() << "expected one Assign to worker " << worker;
    return 0;
  }
  return a->tasks.size();
}

TEST(GuidedTest, ChunkIsRemainingOverWorkersRoundedUp) {
  EXPECT_EQ(guidedChunk(100, 3), 34u);
  EXPECT_EQ(guidedChunk(2, 3), 1u);
  EXPECT_EQ(guidedChunk(0, 3), 0u);
  EXPECT_EQ(guidedChunk(7, 1), 7u);
}

TEST(GuidedTest, ScriptedChunkSizesShrink) {
  // n = 100, c = 3: start 34, 22, 15 (R = 100, 66, 44), then ceil(R / 3) per request.
  GuidedStrategy s;
  const Decisions start = s.start(StartInfo{100, {1, 1, 1}});
  EXPECT_EQ(start, (Decisions{Assign{0, TaskSet::range(0, 34)}, Assign{1, TaskSet::range(34, 22)},
                              Assign{2, TaskSet::range(56, 15)}}));
  std::vector<uint64_t> sizes;
  for (int i = 0;; ++i) {
    const int worker = i % 3;
    const Decisions d = s.onRequest(worker);
    if (d == Decisions{NoMoreWork{worker}}) break;
    sizes.push_back(assignedCount(d, worker));
  }
  EXPECT_EQ(sizes, (std::vector<uint64_t>{10, 7, 4, 3, 2, 1, 1, 1}));
}

TEST(GuidedTest, LostWorkerShrinksTheDivisor) {
  GuidedStrategy s;
  s.start(StartInfo{40, {1, 1, 1, 1}});  // 10, 8, 6, 4: pool 28..39
  EXPECT_TRUE(s.onWorkerLost(3, TaskSet::range(24, 4)).empty());
  // Pool {24..39}, 16 tasks, 3 live workers: ceil(16 / 3) = 6.
  EXPECT_EQ(s.onRequest(0), (Decisions{Assign{0, TaskSet::range(24, 6)}}));
}

}  // namespace
}  // namespace prt
