#include "farm/run_progress.h"

#include <gtest/gtest.h>

namespace prt {
namespace {

TEST(RunProgress, PublishesTheSnapshotAndOnlyFinishedPixelsOfTheFrameInProgress) {
  ProgressBoard board;
  board.watch();                         // a live page reads the image
  RunProgress progress(board, 4, 2, 2);  // two frames of 4x2
  Image image(4, 4);                     // both frames stacked
  for (size_t p = 0; p < image.pixelCount(); ++p) image.set(p, Color(1, 0.5, 0.25));
  progress.measured(TaskSet::range(0, 8), 0.8, 10.0);  // frame 0 whole
  progress.finished(TaskSet::range(0, 8));
  progress.measured(TaskSet::range(8, 2), 0.2, 11.0);  // two pixels of frame 1
  progress.finished(TaskSet::range(8, 2));
  progress.tick(11.0, image, nullptr, true);
  const ProgressSnapshot s = board.snapshot();
  EXPECT_EQ(s.version, 1u);
  EXPECT_EQ(s.phase, ProgressSnapshot::Phase::Rendering);
  EXPECT_EQ(s.pixelsDone, 10u);
  EXPECT_EQ(s.pixelsTotal, 16u);
  ASSERT_TRUE(s.etaSeconds);
  EXPECT_GT(*s.etaSeconds, 0);
  const auto partial = board.image();
  ASSERT_TRUE(partial);
  EXPECT_EQ(partial->frame, 1u);  // the earliest frame not finished
  EXPECT_EQ(partial->done, (std::vector<uint8_t>{1, 1, 0, 0, 0, 0, 0, 0}));
  EXPECT_EQ(partial->image.at(size_t{1}).x, 1.0);
  EXPECT_EQ(partial->image.at(size_t{2}).x, 0.0);  // not finished: never read
  // Ticks closer together than kPublishSeconds publish nothing.
  progress.tick(11.1, image, nullptr);
  EXPECT_EQ(board.snapshot().version, 1u);
  progress.end(12.0, image, nullptr, true, "written to x.png");
  EXPECT_EQ(board.snapshot().phase, ProgressSnapshot::Phase::Finished);
  EXPECT_EQ(board.snapshot().message, "written to x.png");
  EXPECT_EQ(*board.snapshot().etaSeconds, 0.0);
}

// With no reader of the image attached (no live page), the render never copies it.
TEST(RunProgress, NoImageIsCopiedWithoutAReader) {
  ProgressBoard board;
  RunProgress progress(board, 4, 2, 1);
  Image image(4, 2);
  progress.finished(TaskSet::range(0, 8));
  progress.tick(1.0, image, nullptr, true);
  progress.end(2.0, image, nullptr, true, "written");
  EXPECT_FALSE(board.imageWanted());
  EXPECT_EQ(board.snapshot().phase, ProgressSnapshot::Phase::Finished);
  board.watch();
  EXPECT_EQ(board.image(), nullptr) << "nothing was copied";
}

}  // namespace
}  // namespace prt
