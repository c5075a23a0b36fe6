#include "core/frame_sequence.h"

#include <gtest/gtest.h>

namespace prt {
namespace {

TEST(FrameSequenceTest, RangesStepsAndNegativeFrames) {
  std::string error;
  auto s = parseFrames("1-48", error);
  ASSERT_TRUE(s) << error;
  EXPECT_EQ(s->count(), 48u);
  EXPECT_EQ(s->number(0), 1);
  EXPECT_EQ(s->number(47), 48);
  s = parseFrames("0-10:4", error);
  ASSERT_TRUE(s);
  EXPECT_EQ(s->count(), 3u);
  EXPECT_EQ(s->last, 8);  // the last frame the step reaches
  s = parseFrames("-5--1", error);
  ASSERT_TRUE(s) << error;
  EXPECT_EQ(s->first, -5);
  EXPECT_EQ(s->count(), 5u);
  s = parseFrames("7", error);
  ASSERT_TRUE(s);
  EXPECT_EQ(s->count(), 1u);
  s->fps = 24;
  EXPECT_DOUBLE_EQ(s->seconds(0), 7.0 / 24);
  EXPECT_EQ(FrameSequence{}.seconds(0), 0.0);  // a still is at time 0
}

TEST(FrameSequenceTest, RefusesWhatNoUserMeans) {
  std::string error;
  for (const char* bad : {"", "-", "5-1", "1-x", "1-2:0", "1-2:-1", "+1-3", "1.5-3", "1-3:",
                          "0-99999999999", "0-2000000", " 1-3"}) {
    EXPECT_FALSE(parseFrames(bad, error)) << bad;
    EXPECT_FALSE(error.empty()) << bad;
  }
}

TEST(FrameSequenceTest, PatternsTakeTheFrameNumberZeroPadded) {
  EXPECT_EQ(framePath("out_####.png", 7), "out_0007.png");
  EXPECT_EQ(framePath("out_#.png", 123), "out_123.png");
  EXPECT_EQ(framePath("out_###.png", -4), "out_-04.png");
  EXPECT_EQ(framePath("dir#1/f_##.pfm", 3), "dir#1/f_03.pfm");  // only the file name's run
  EXPECT_TRUE(hasFramePattern("f_####.png"));
  EXPECT_FALSE(hasFramePattern("f.png"));
  EXPECT_FALSE(hasFramePattern("f_#_#.png"));
  EXPECT_FALSE(hasFramePattern("dir#/f.png"));
}

}  // namespace
}  // namespace prt
