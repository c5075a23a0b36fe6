#include "report/run_page.h"

#include <gtest/gtest.h>

#include <regex>

#include "report/ownership_map.h"
#include "report/report_document.h"

namespace prt {
namespace {

using nlohmann::json;

std::string unescape(std::string s) {
  const std::pair<const char*, const char*> entities[] = {
      {"&quot;", "\""}, {"&lt;", "<"}, {"&gt;", ">"}, {"&#39;", "'"}, {"&amp;", "&"}};
  for (const auto& [from, to] : entities) {
    for (size_t at = s.find(from); at != std::string::npos; at = s.find(from, at + 1)) {
      s.replace(at, std::string(from).size(), to);
    }
  }
  return s;
}

// The data-value of the first element with data-key="key" at or after `from`.
json valueOf(const std::string& html, const std::string& key, size_t from = 0) {
  const std::string anchor = "data-key=\"" + key + "\" data-value=\"";
  const size_t at = html.find(anchor, from);
  if (at == std::string::npos) return "missing";
  const size_t start = at + anchor.size();
  return json::parse(unescape(html.substr(start, html.find('"', start) - start)));
}

json embedded(const std::string& html, const std::string& id) {
  const std::string open = "<script type=\"application/json\" id=\"" + id + "\">";
  const size_t start = html.find(open);
  if (start == std::string::npos) return nullptr;
  const size_t end = html.find("</script>", start);
  return json::parse(html.substr(start + open.size(), end - start - open.size()));
}

// Four workers on an 8x4 image: worker w renders row w, the slow ones for longer.
struct SampleRun {
  RunReport report;
  std::vector<Event> events;
  std::vector<int32_t> owner;
};

SampleRun fourWorkers() {
  RunInfo info;
  info.driver = "local";
  info.strategy = "reservoir";
  info.width = 8;
  info.height = 4;
  info.masterSpeedIndexSeconds = 0.05;
  info.workerSpeedIndexSeconds = {0.1, 0.1, 0.2, 0.2};
  info.slowdowns = {2, 2, 4, 4};
  info.tasksReceived = {2, 2, 1, 1};
  info.serialSeconds = 3.0;
  SampleRun run;
  for (int w = 0; w < 4; ++w) {
    run.events.push_back({EventKind::Setup, w, 0, 0.1 * (w + 1), 0, 0, 0, ""});
    run.events.push_back({EventKind::Compute, w, 0.5, 1.5 + 0.1 * w, 8, 0, 0, ""});
    run.events.push_back(
        {EventKind::MessageSent, w, 1.5 + 0.1 * w, 1.5 + 0.1 * w, 0, 120, -1, "Results"});
    for (int x = 0; x < 8; ++x) run.owner.push_back(w);
  }
  run.report = makeReport(info, run.events, 2.0);
  return run;
}

RunContext context() {
  RunContext c;
  c.commandLine = "prt render scenes/complex.scene --workers 4 --html run.html";
  c.scene = "scenes/complex.scene";
  c.machine = "a test machine";
  c.dateUtc = "2026-12-01 20:00 UTC";
  c.parameters = {{"initial_percent", "80"}, {"batch_pixels", "128"}};
  c.outputs = {{"image", "out.png"}};
  return c;
}

TEST(RunPage, EmbedsTheReportItWasDrawnFrom) {
  const SampleRun run = fourWorkers();
  const json doc = reportDocument(run.report, context(), run.events, run.owner);
  const std::string html = runPageHtml(doc, {});
  EXPECT_EQ(embedded(html, "prt-run"), doc);
  EXPECT_EQ(decodeOwnership(embedded(html, "prt-run")["ownership_map"]), run.owner);
  EXPECT_EQ(embedded(html, "prt-page")["colours"].size(), 4u);
}

TEST(RunPage, MeasuresOnThePageMatchTheJsonReport) {
  const SampleRun run = fourWorkers();
  const json saved = json::parse(run.report.toJson());
  const std::string html =
      runPageHtml(reportDocument(run.report, context(), run.events, run.owner), {});
  for (const char* key :
       {"elapsed_s", "speedup", "efficiency", "masu", "asu", "messages", "bytes"}) {
    EXPECT_EQ(valueOf(html, key), saved[key]) << key;
  }
  // What a reader sees: 3.0 s serial over 2.0 s is a speed-up of 1.50; MASU 0.5+0.5+0.25+0.25.
  EXPECT_NE(html.find(">1.50 ×<"), std::string::npos);
  EXPECT_NE(html.find(">1.50</div><div class=\"label\">MASU"), std::string::npos);
  EXPECT_NE(html.find(">100.0 %</div><div class=\"label\">ASU"), std::string::npos);
  EXPECT_NE(html.find(">2.00 s</div><div class=\"label\">elapsed"), std::string::npos);
  // The worker table, row by row.
  size_t row = 0;
  for (const json& w : saved["workers"]) {
    row = html.find("<tr class=\"worker", row + 1);
    ASSERT_NE(row, std::string::npos);
    for (const char* key :
         {"worker", "speed_index_s", "slowdown", "tasks", "pixels", "busy_s", "idle_s", "lost"}) {
      EXPECT_EQ(valueOf(html, key, row), w[key]) << key;
    }
    EXPECT_EQ(valueOf(html, "messages", row),
              w["messages_sent"].get<int>() + w["messages_received"].get<int>());
  }
}

TEST(RunPage, EstimatesWhatBalancingBought) {
  // Busy 1.0, 1.1, 1.2 and 1.3 s for 8 pixels each: an equal share keeps the slowest busy
  // 1.3 s; finishing together, 32 / (8/1.0 + 8/1.1 + 8/1.2 + 8/1.3) = 1.139 s.
  const SampleRun run = fourWorkers();
  const std::string html =
      runPageHtml(reportDocument(run.report, context(), run.events, run.owner), {});
  EXPECT_NE(html.find("rendering about <b>1.30 s</b>"), std::string::npos);
  EXPECT_NE(html.find("finishing together it would take about <b>1.14 s</b>"), std::string::npos);
  EXPECT_NE(html.find("rendered for at most <b>1.30 s</b>"), std::string::npos);
}

TEST(RunPage, ShowsTheContextAndFetchesNothing) {
  const SampleRun run = fourWorkers();
  const std::string html = runPageHtml(reportDocument(run.report, context(), run.events, run.owner),
                                       PagePicture{"\x89PNG fake", "the image", true, ""});
  for (const char* text :
       {"prt render scenes/complex.scene --workers 4 --html run.html", "a test machine",
        "initial_percent", "<b>reservoir</b>", "data:image/png;base64,", "<svg id=\"timeline\""}) {
    EXPECT_NE(html.find(text), std::string::npos) << text;
  }
  EXPECT_FALSE(std::regex_search(html, std::regex("(src|href)=\"(https?:)?//")));
  EXPECT_EQ(html.find("<link"), std::string::npos);
  EXPECT_EQ(html.find("@import"), std::string::npos);
}

TEST(RunPage, ShowsFaultKeysAndUnknownKeysGenerically) {
  const SampleRun run = fourWorkers();
  json doc = reportDocument(run.report, context(), run.events, run.owner);
  doc["lost_workers"] = json::array({2});
  doc["reissued_tasks"] = 5;
  doc["resumed_pixels"] = 0;
  doc["future_measure"] = 1.25;
  doc["workers"][2]["lost"] = true;
  doc["workers"][0]["heartbeats"] = 7;
  const std::string html = runPageHtml(doc, {});
  EXPECT_EQ(valueOf(html, "lost_workers"), json::array({2}));
  EXPECT_EQ(valueOf(html, "reissued_tasks"), 5);
  EXPECT_EQ(valueOf(html, "future_measure"), 1.25);
  EXPECT_NE(html.find("card fault\" data-key=\"reissued_tasks\""), std::string::npos);
  EXPECT_NE(html.find("card\" data-key=\"resumed_pixels\""), std::string::npos);  // 0: no alarm
  EXPECT_NE(html.find("<th>heartbeats</th>"), std::string::npos);
  EXPECT_EQ(valueOf(html, "heartbeats", html.find("<tr class=\"worker")), 7);
  EXPECT_NE(html.find("lost-row"), std::string::npos);
  EXPECT_NE(html.find("Worker 2 was lost</b>"), std::string::npos);
}

// Samples not finite: no card and no column while there are none (the page's layout stays),
// a fault card and the workers' column once there are.
TEST(RunPage, NonFiniteSamplesShowOnlyWhenThereAreSome) {
  const SampleRun run = fourWorkers();
  json doc = reportDocument(run.report, context(), run.events, run.owner);
  doc["non_finite_samples"] = 0;
  for (json& w : doc["workers"]) w["non_finite_samples"] = 0;
  const std::string none = runPageHtml(doc, {});
  EXPECT_EQ(none.find("data-key=\"non_finite_samples\" data-value"), std::string::npos);
  EXPECT_EQ(none.find("<th>non finite samples</th>"), std::string::npos);
  doc["non_finite_samples"] = 3;
  doc["workers"][1]["non_finite_samples"] = 3;
  const std::string some = runPageHtml(doc, {});
  EXPECT_NE(some.find("card fault\" data-key=\"non_finite_samples\""), std::string::npos);
  EXPECT_NE(some.find("<th>non finite samples</th>"), std::string::npos);
}

TEST(RunPage, SaysWhenAWorkerWasLost) {
  SampleRun run = fourWorkers();
  run.events.push_back({EventKind::WorkerLost, 3, 1.25, 1.25, 0, 0, 0, ""});
  const RunReport report = makeReport(run.report.info, run.events, 2.0);
  const std::string html =
      runPageHtml(reportDocument(report, context(), run.events, run.owner), {});
  EXPECT_NE(html.find("Worker 3 (at 1.25 s) was lost</b>"), std::string::npos);
  EXPECT_NE(html.find("class=\"lost\"><title>worker 3 lost at 1.25 s</title>"), std::string::npos);
}

TEST(RunPage, SaysWhoJoinedWhenAndAgainstWhichIdeal) {
  SampleRun run = fourWorkers();
  run.report.info.joinedAt = {std::nullopt, std::nullopt, std::nullopt, 0.5};
  run.events.push_back({EventKind::WorkerJoined, 3, 0.5, 0.5, 0, 0, -1, ""});
  const RunReport report = makeReport(run.report.info, run.events, 2.0);
  ASSERT_TRUE(report.idealSeconds.has_value());
  const std::string html =
      runPageHtml(reportDocument(report, context(), run.events, run.owner), {});
  EXPECT_NE(html.find("Worker 3 (at 500 ms)"), std::string::npos);
  EXPECT_NE(html.find("joined the running render"), std::string::npos);
  EXPECT_NE(html.find("A perfect balance of the same work"), std::string::npos);
  EXPECT_NE(html.find("class=\"absent\"><title>worker 3 joined at 500 ms"), std::string::npos);
  EXPECT_NE(html.find("card\" data-key=\"joined_workers\""), std::string::npos);  // no alarm
  EXPECT_NE(html.find("worker 3 at 500 ms"), std::string::npos);
  EXPECT_NE(html.find("data-key=\"ideal_s\""), std::string::npos);
}

TEST(RunPage, OldReportsWithoutTimelineOrMapStillDraw) {
  const SampleRun run = fourWorkers();
  const json old = json::parse(run.report.toJson());
  const std::string html = runPageHtml(old, {"", "", true, "no image here"});
  EXPECT_NE(html.find("has no timeline"), std::string::npos);
  EXPECT_NE(html.find("has no ownership map"), std::string::npos);
  EXPECT_NE(html.find("no image here"), std::string::npos);
}

TEST(RunPage, LargeRunsAreAggregatedAndSaySo) {
  RunInfo info;
  info.driver = "simulated";
  info.strategy = "reservoir";
  info.width = 64;
  info.height = 64;
  info.masterSpeedIndexSeconds = 0.08;
  std::vector<Event> events;
  for (int w = 0; w < 1024; ++w) {
    info.workerSpeedIndexSeconds.push_back(w % 2 ? 0.08 : 0.32);
    info.slowdowns.push_back(w % 2 ? 1 : 4);
    events.push_back({EventKind::Compute, w, 0.1, w % 2 ? 1.0 : 0.9, 4, 0, 0, ""});
  }
  const RunReport report = makeReport(info, events, 1.0);
  const std::string html = runPageHtml(reportDocument(report, context(), events, {}), {});
  EXPECT_NE(html.find("too many to draw one by one"), std::string::npos);
  EXPECT_NE(html.find("each row stands for 16 consecutive workers"), std::string::npos);
  EXPECT_NE(html.find("<table class=\"classes\">"), std::string::npos);
  EXPECT_NE(html.find("<details><summary>All 1,024 workers"), std::string::npos);
  EXPECT_LT(html.size(), 2'000'000u);
}

TEST(RunPage, WorkerColoursAreDistinct) {
  const auto few = workerColours(4);
  EXPECT_EQ(few[0], "#1f78b5");
  const auto many = workerColours(64);
  for (size_t i = 1; i < many.size(); ++i) {
    EXPECT_NE(many[i], many[i - 1]);
    EXPECT_TRUE(std::regex_match(many[i], std::regex("#[0-9a-f]{6}"))) << many[i];
  }
}

}  // namespace
}  // namespace prt
