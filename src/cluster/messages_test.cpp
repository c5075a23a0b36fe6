#include "cluster/messages.h"

#include <gtest/gtest.h>

namespace prt {
namespace {

TEST(MessagesTest, EveryTypeRoundTrips) {
  TaskSet tasks = TaskSet::range(10, 100);
  tasks.append(TaskSet::strided(500, 7, 3));
  const std::vector<Message> messages = {
      SceneMsg{"camera { }\n", 8, 2, {}},
      SceneMsg{"camera { }\n", 8, 2, {1, 2, 3, 250}},
      SpeedIndexMsg{0.123456789},
      TasksMsg{tasks},
      ResultsMsg{TaskSet::range(3, 2), {0.1f, 0.2f, 0.3f, 1.5f, 2.5f, -0.0f}},
      RequestMsg{},
      QueryQueueMsg{},
      QueueLengthMsg{1ull << 40},
      TransferOrderMsg{3, 77},
      TransferNoticeMsg{2, tasks},
      StopMsg{},
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

}  // namespace
}  // namespace prt
