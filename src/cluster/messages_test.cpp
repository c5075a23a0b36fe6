#include "cluster/messages.h"

#include <gtest/gtest.h>

#include <cstring>
#include <stdexcept>

namespace prt {
namespace {

TEST(MessagesTest, EveryTypeRoundTrips) {
  TaskSet tasks = TaskSet::range(10, 100);
  tasks.append(TaskSet::strided(500, 7, 3));
  const std::vector<Message> messages = {
      SceneMsg{"camera { }\n", 8, 2, {}},
      SceneMsg{"camera { }\n", 8, 2, {1, 2, 3, 250}},
      SpeedIndexMsg{0.123456789},
      SpeedIndexMsg{0.5, {"prt 0.1.0 (trace kernels: baseline)", "node-7"}},
      TasksMsg{tasks},
      ResultsMsg{TaskSet::range(3, 2), {0.1f, 0.2f, 0.3f, 1.5f, 2.5f, -0.0f}, 0.125},
      RequestMsg{},
      QueryQueueMsg{},
      QueueLengthMsg{1ull << 40},
      TransferOrderMsg{3, 77},
      TransferNoticeMsg{2, tasks},
      StopMsg{},
      HeartbeatMsg{},
      CheckMsg{tasks},
      CheckResultsMsg{TaskSet::strided(4, 2, 9), {0.5f, 0.25f, 1e-40f, 3.0f, 0.0f, 7.0f}},
  };
  for (const Message& m : messages) {
    const Bytes bytes = encode(m);
    EXPECT_EQ(decode(bytes), m) << messageName(m);
  }
}

TEST(MessagesTest, TaskSetsTravelCompactly) {
  // A strided share of a 4K image is one run: a few dozen bytes, not 8 MB.
  const Bytes bytes = encode(TasksMsg{TaskSet::strided(1, 3840 * 2160 / 4, 4)});
  EXPECT_LT(bytes.size(), 64u);
}

TEST(MessagesTest, MalformedBuffersAreRejected) {
  Bytes bytes = encode(TasksMsg{TaskSet::range(0, 5)});
  bytes.pop_back();
  EXPECT_THROW(decode(bytes), std::runtime_error);
  EXPECT_THROW(decode(Bytes{200}), std::runtime_error);
  Bytes extra = encode(StopMsg{});
  extra.push_back(0);
  EXPECT_THROW(decode(extra), std::runtime_error);
}

// Found by the message fuzzer (tests/fuzz): counts whose byte size overflows, and task runs
// whose indices or total overflow the task set's arithmetic, are refused.
TEST(MessagesTest, CorruptCountsAreRejectedNotTrusted) {
  const auto withWord = [](Bytes bytes, size_t at, uint64_t value) {
    std::memcpy(bytes.data() + at, &value, sizeof value);
    return bytes;
  };
  // Results: tag, 1 run (first, count, stride), then the float count.
  const Bytes results = encode(ResultsMsg{TaskSet::range(10, 1), {1, 2, 3}});
  // 2^62 floats are 2^64 bytes: "need" of the wrapped product would have passed.
  EXPECT_THROW(decode(withWord(results, 1 + 8 + 24, uint64_t{1} << 62)), std::runtime_error);
  EXPECT_THROW(decode(withWord(results, 1, uint64_t{1} << 62)), std::runtime_error);  // runs
  const Bytes tasks = encode(TasksMsg{TaskSet::range(5, 3)});
  EXPECT_THROW(decode(withWord(tasks, 1 + 8, ~uint64_t{0})), std::runtime_error);       // first
  EXPECT_THROW(decode(withWord(tasks, 1 + 16, ~uint64_t{0})), std::runtime_error);      // count
  EXPECT_THROW(decode(withWord(tasks, 1 + 24, uint64_t{1} << 40)), std::runtime_error);  // stride
  // Check results: the colours must match the tasks too.
  const Bytes checked = encode(CheckResultsMsg{TaskSet::range(10, 1), {1, 2, 3}});
  EXPECT_THROW(decode(withWord(checked, 1 + 8 + 24, 6)), std::runtime_error);
  EXPECT_THROW(decode(withWord(checked, 1 + 8 + 24, uint64_t{1} << 62)), std::runtime_error);
  // An empty result (no tasks, no colours) is well formed.
  EXPECT_EQ(decode(encode(ResultsMsg{})), Message(ResultsMsg{}));
}

}  // namespace
}  // namespace prt
