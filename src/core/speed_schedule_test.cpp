#include "core/speed_schedule.h"

#include <gtest/gtest.h>

#include "core/input_error.h"

namespace prt {
namespace {

TEST(SpeedScheduleTest, ParsesAndLooksUp) {
  const std::vector<SpeedChange> changes =
      parseSpeedChanges("0:2.5:8,1:0:2,0:1:4", "--slowdown-at", 4, 1);
  EXPECT_EQ(changes.size(), 3u);
  const std::vector<SpeedChange> zero = changesOf(changes, 0);
  ASSERT_EQ(zero.size(), 2u);
  EXPECT_EQ(zero[0], (SpeedChange{0, 1, 4}));
  EXPECT_EQ(valueAt(zero, 2, 0.5), 2);
  EXPECT_EQ(valueAt(zero, 2, 1), 4);
  EXPECT_EQ(valueAt(zero, 2, 100), 8);
  EXPECT_TRUE(changesOf(changes, 3).empty());
}

TEST(SpeedScheduleTest, BadItemsAreInputErrors) {
  for (const char* text : {"", "0:1", "0:1:2:3", "4:1:2", "-1:1:2", "0.5:1:2", "0:-1:2",
                           "0:x:2", "0:1:0.5", "0:1:nan", "0:1:2,"}) {
    EXPECT_THROW(parseSpeedChanges(text, "--slowdown-at", 4, 1), InputError) << text;
  }
  EXPECT_THROW(parseSpeedChanges("0:1:0", "--speed-at", 4, 0), InputError);
  EXPECT_NO_THROW(parseSpeedChanges("0:1:0.25", "--speed-at", 4, 0));
  try {
    parseSpeedChanges("7:1:2", "--slowdown-at", 4, 1);
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("--slowdown-at: '7:1:2' names no worker"),
              std::string::npos)
        << e.what();
  }
}

}  // namespace
}  // namespace prt
