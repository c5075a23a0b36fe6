#include "report/timeline.h"

#include "report/timeline_svg.h"

#include <gtest/gtest.h>

#include <string>

namespace prt {
namespace {

using nlohmann::json;

std::vector<Event> twoWorkerEvents() {
  std::vector<Event> e;
  e.push_back({EventKind::Setup, 0, 0.0, 1.0, 0, 0, 0, ""});
  e.push_back({EventKind::Setup, 1, 0.0, 1.0, 0, 0, 0, ""});
  e.push_back({EventKind::Compute, 0, 1.0, 5.0, 400, 0, 0, ""});
  e.push_back({EventKind::Compute, 0, 5.001, 10.0, 500, 0, 0, ""});  // merges with the first
  e.push_back({EventKind::Compute, 1, 1.0, 4.0, 100, 0, 0, ""});
  e.push_back({EventKind::MessageSent, 1, 4.0, 4.0, 0, 64, -1, "Results"});
  e.push_back({EventKind::MessageReceived, -1, 4.0, 4.0, 0, 64, 1, "Results"});
  e.push_back({EventKind::WorkerLost, 1, 6.0, 6.0, 0, 0, 0, ""});
  return e;
}

TEST(Timeline, SpansInTicksMergedAndMarked) {
  const json t = timelineJson(twoWorkerEvents(), 2, 10.0, {100, 64, 100, 100});
  EXPECT_FALSE(t["aggregated"].get<bool>());
  EXPECT_EQ(t["ticks"], 100);
  ASSERT_EQ(t["rows"].size(), 2u);
  const json& w0 = t["rows"][0];
  EXPECT_EQ(w0["setup"], json::parse("[[0,10]]"));
  EXPECT_EQ(w0["rendering"], json::parse("[[10,100]]"));  // 5.0 and 5.001 are one tick
  EXPECT_DOUBLE_EQ(w0["finished_s"].get<double>(), 10.0);
  const json& w1 = t["rows"][1];
  EXPECT_EQ(w1["rendering"], json::parse("[[10,40]]"));
  EXPECT_EQ(w1["messages"], json::parse("[40]"));
  ASSERT_EQ(w1["marks"].size(), 1u);
  EXPECT_EQ(w1["marks"][0]["kind"], "worker_lost");
  EXPECT_EQ(w1["marks"][0]["label"], "worker 1 lost");
  EXPECT_DOUBLE_EQ(w1["marks"][0]["t_s"].get<double>(), 6.0);
  // Rendering share: both workers render from 1 to 4 s, then only worker 0.
  EXPECT_DOUBLE_EQ(t["rendering_share"][20].get<double>(), 1.0);
  EXPECT_DOUBLE_EQ(t["rendering_share"][60].get<double>(), 0.5);
  EXPECT_DOUBLE_EQ(t["rendering_share"][5].get<double>(), 0.0);
}

TEST(Timeline, ManyWorkersAreGroupedWithShares) {
  std::vector<Event> e;
  const int n = 1024;
  for (int w = 0; w < n; ++w) {
    // Worker w renders from 0 until (w % 2 ? 5 : 10) seconds.
    e.push_back({EventKind::Compute, w, 0.0, w % 2 ? 5.0 : 10.0, 10, 0, 0, ""});
    e.push_back({EventKind::MessageSent, w, 0.5, 0.5, 0, 10, -1, "Results"});
  }
  const json t = timelineJson(e, n, 10.0, {1000, 64, 100, 200});
  EXPECT_TRUE(t["aggregated"].get<bool>());
  EXPECT_EQ(t["workers_per_row"], 16);
  ASSERT_EQ(t["rows"].size(), 64u);
  const json& row = t["rows"][3];
  EXPECT_EQ(row["first"], 48);
  EXPECT_EQ(row["last"], 63);
  EXPECT_FALSE(row.contains("rendering"));  // no spans one by one
  EXPECT_FALSE(row.contains("messages"));
  EXPECT_DOUBLE_EQ(row["rendering_share"][10].get<double>(), 1.0);
  EXPECT_DOUBLE_EQ(row["rendering_share"][150].get<double>(), 0.5);
  EXPECT_EQ(t["rendering_share"].size(), 200u);
  EXPECT_LT(t.dump().size(), 150000u);  // bounded, whatever the number of events
}

TEST(Timeline, MarksPerRowAreCapped) {
  std::vector<Event> e;
  for (int i = 0; i < 250; ++i)
    e.push_back({EventKind::WorkerLost, 0, 0.01 * i, 0.01 * i, 0, 0, 0, ""});
  const json t = timelineJson(e, 1, 3.0, {100, 64, 100});
  EXPECT_EQ(t["rows"][0]["marks"].size(), 100u);
  EXPECT_EQ(t["marks_dropped"], 150);
}

size_t countOf(const std::string& text, const std::string& what) {
  size_t n = 0;
  for (size_t at = text.find(what); at != std::string::npos; at = text.find(what, at + 1)) ++n;
  return n;
}

TEST(TimelineSvg, FrameBoundariesAreDrawnEachAndLabelledWhereTheyFit) {
  const json t = timelineJson(twoWorkerEvents(), 2, 10.0, {100, 64, 100, 100});
  EXPECT_EQ(countOf(timelineSvg(t, {"#ff0000", "#00ff00"}), "frame-line"), 0u) << "a still";
  // 100 frames in 10 s: a line for each, far fewer labels (the plot is 900 px wide).
  json frames = json::array();
  for (int f = 0; f < 100; ++f) {
    frames.push_back({{"frame", f + 1}, {"pixels", 10}, {"completed_s", 0.1 * (f + 1)}});
  }
  frames.push_back({{"frame", 999}, {"completed_s", "not a number"}});  // skipped, no throw
  const std::string svg = timelineSvg(t, {"#ff0000", "#00ff00"}, frames);
  EXPECT_EQ(countOf(svg, "class=\"frame-line\""), 100u);
  const size_t labels = countOf(svg, "class=\"frame-label\"");
  EXPECT_GE(labels, 10u);
  EXPECT_LE(labels, 25u);
  EXPECT_NE(svg.find("frame 1 complete at"), std::string::npos);
  EXPECT_NE(svg.find(">1</text>"), std::string::npos) << "the first frame is labelled";
}

}  // namespace
}  // namespace prt
