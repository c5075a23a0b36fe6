#include "live/progress_text.h"

#include <gtest/gtest.h>

namespace prt {
namespace {

TEST(ProgressText, Durations) {
  EXPECT_EQ(formatDuration(0.42), "0.4 s");
  EXPECT_EQ(formatDuration(12.4), "12 s");
  EXPECT_EQ(formatDuration(185), "3 min 05 s");
  EXPECT_EQ(formatDuration(7440), "2 h 04 min");
  EXPECT_EQ(formatDuration(-1), "?");
  EXPECT_EQ(groupDigits(1234567), "1,234,567");
  EXPECT_EQ(groupDigits(12), "12");
}

TEST(ProgressText, RowsPerWorkerOrASummaryPastTheLimit) {
  ProgressSnapshot s;
  s.phase = ProgressSnapshot::Phase::Rendering;
  s.pixelsDone = 250;
  s.pixelsTotal = 1000;
  s.elapsedSeconds = 5;
  EXPECT_EQ(progressSummary(s), "25.0% of 1,000 px, 5.0 s, ETA estimating");
  s.etaSeconds = 15;
  EXPECT_EQ(progressSummary(s), "25.0% of 1,000 px, 5.0 s, ETA 15 s");
  for (int i = 0; i < 3; ++i) {
    WorkerProgress w;
    w.state = i == 2 ? WorkerProgress::State::Lost : WorkerProgress::State::Working;
    w.pixels = 100;
    s.workers.push_back(w);
  }
  EXPECT_EQ(workerSummary(s), "3 workers: 2 working, 1 lost");
  const auto rows = progressLines(s, 16, 10);
  ASSERT_EQ(rows.size(), 5u);  // header, 3 workers, bar
  EXPECT_NE(rows[3].find("lost"), std::string::npos);
  EXPECT_EQ(rows[4].substr(0, 12), "[##--------]");
  const auto summary = progressLines(s, 2, 10);
  ASSERT_EQ(summary.size(), 2u);
  EXPECT_EQ(summary[0], "3 workers: 2 working, 1 lost");
}

}  // namespace
}  // namespace prt
