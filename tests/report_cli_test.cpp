// End-to-end tests of the run's page: --html on prt render and prt simulate, prt report from a
// saved report, the experiments' index.html, and bad input (exit code 2, nothing written).

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <functional>
#include <nlohmann/json.hpp>
#include <string>

#include "core/subprocess.h"
#include "prt_command.h"

namespace prt {
namespace {

namespace fs = std::filesystem;
using e2e::Result;
using e2e::run;
using ReportCliTest = e2e::ScratchDirTest;

const std::string kReportScene = std::string(PRT_SOURCE_DIR) + "/scenes/fig06-primitives.scene";

nlohmann::json embeddedReport(const std::string& html) {
  const std::string open = "<script type=\"application/json\" id=\"prt-run\">";
  const size_t start = html.find(open);
  if (start == std::string::npos) return nullptr;
  return nlohmann::json::parse(
      html.substr(start + open.size(), html.find("</script>", start) - start - open.size()));
}

TEST_F(ReportCliTest, SavedReportDrawsTheSamePageAgain) {
  const Result r =
      run("render " + kReportScene + " --width 48 --height 32 --workers 2 --html " + path("run.html") +
          " --report " + path("run.json") + " -o " + path("run.png") + " -q");
  ASSERT_EQ(r.exitCode, 0) << r.output;
  const std::string page = readWholeFile(path("run.html"));
  const nlohmann::json saved = nlohmann::json::parse(readWholeFile(path("run.json")));
  EXPECT_EQ(embeddedReport(page), saved);
  EXPECT_TRUE(saved.contains("timeline"));
  EXPECT_TRUE(saved.contains("ownership_map"));
  EXPECT_EQ(saved["context"]["outputs"]["image"], path("run.png"));
  EXPECT_NE(saved["context"]["command_line"].get<std::string>().find("--html"), std::string::npos);

  const Result again = run("report " + path("run.json") + " -o " + path("again.html"));
  ASSERT_EQ(again.exitCode, 0) << again.output;
  // The image read back from its PNG encodes to the same bytes: the very same page.
  EXPECT_EQ(readWholeFile(path("again.html")), page);

  // Moved elsewhere with its image, the report still finds it beside itself.
  fs::create_directories(path("moved"));
  fs::copy_file(path("run.json"), path("moved/run.json"));
  fs::copy_file(path("run.png"), path("moved/run.png"));
  fs::remove(path("run.png"));
  const Result moved = run("report " + path("moved/run.json") + " -o " + path("moved.html"));
  ASSERT_EQ(moved.exitCode, 0) << moved.output;
  EXPECT_NE(readWholeFile(path("moved.html")).find("data:image/png;base64,"), std::string::npos);
  // Without it the page says so instead of failing.
  fs::remove(path("moved/run.png"));
  const Result lost = run("report " + path("moved/run.json") + " -o " + path("lost.html"));
  ASSERT_EQ(lost.exitCode, 0) << lost.output;
  EXPECT_NE(readWholeFile(path("lost.html")).find("was not found"), std::string::npos);
}

TEST_F(ReportCliTest, SimulatedRunHasACostPictureAndOwnershipMap) {
  const Result r = run("simulate --workers 8 --width 64 --height 48 --slow-share 0.5 --html " +
                       path("sim.html") + " --report " + path("sim.json") + " -q");
  ASSERT_EQ(r.exitCode, 0) << r.output;
  const std::string page = readWholeFile(path("sim.html"));
  EXPECT_NE(page.find("The cost map the simulator replayed"), std::string::npos);
  const nlohmann::json saved = embeddedReport(page);
  EXPECT_EQ(saved["driver"], "simulated");
  EXPECT_EQ(saved["ownership_map"]["width"], 64);
  const Result again = run("report " + path("sim.json") + " -o " + path("again.html"));
  ASSERT_EQ(again.exitCode, 0) << again.output;
  EXPECT_EQ(readWholeFile(path("again.html")), page);  // the synthetic map is made again
}

TEST_F(ReportCliTest, BadInputIsExitCodeTwoAndWritesNothing) {
  Result r = run("render " + kReportScene + " --width 16 --height 16 --workers 2 --html " +
                 path("page.txt") + " -o " + path("a.png"));
  EXPECT_EQ(r.exitCode, 2);
  EXPECT_NE(r.output.find(".html or .htm"), std::string::npos) << r.output;
  EXPECT_FALSE(fs::exists(path("a.png"))) << "checked before rendering";

  r = run("render " + kReportScene + " --width 16 --height 16 --workers 2 --html " +
          path("nowhere/page.html") + " -o " + path("a.png"));
  EXPECT_EQ(r.exitCode, 2);
  EXPECT_NE(r.output.find("no folder"), std::string::npos) << r.output;
  EXPECT_FALSE(fs::exists(path("a.png"))) << "checked before rendering";

  r = run("render " + kReportScene + " --width 16 --height 16 --html " + path("page.html") + " -o " +
          path("a.png"));
  EXPECT_EQ(r.exitCode, 2);
  EXPECT_NE(r.output.find("describe a parallel run"), std::string::npos) << r.output;

  r = run("report " + path("missing.json") + " -o " + path("page.html"));
  EXPECT_EQ(r.exitCode, 2);
  EXPECT_NE(r.output.find("does not exist"), std::string::npos) << r.output;
  for (const char* special : {"/dev/zero", "/dev/null"}) {
    r = run(std::string("report ") + special + " -o " + path("page.html"));
    EXPECT_EQ(r.exitCode, 2) << r.output;
    EXPECT_NE(r.output.find("is a character device, not a regular file"), std::string::npos)
        << r.output;
  }

  const std::string bad =
      write("bad.json", "{\n  \"strategy\": \"reservoir\",\n  \"elapsed_s\": ,\n}\n");
  r = run("report " + bad + " -o " + path("page.html"));
  EXPECT_EQ(r.exitCode, 2);
  EXPECT_NE(r.output.find("bad.json:3:16: error:"), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("^"), std::string::npos) << r.output;

  const std::string other = write("other.json", "{\"hello\": 1}");
  r = run("report " + other + " -o " + path("page.html"));
  EXPECT_EQ(r.exitCode, 2);
  EXPECT_NE(r.output.find("not a run report"), std::string::npos) << r.output;
  EXPECT_FALSE(fs::exists(path("page.html")));
}

// A saved report that was edited: a field of another type is named, exit 2, no page; a huge
// one gives a page of bounded size that says what it left out.
TEST_F(ReportCliTest, AnEditedReportIsRefusedByItsFieldAndAHugeOneMakesABoundedPage) {
  Result r = run("render " + kReportScene + " --width 24 --height 16 --workers 2 --report " +
                 path("run.json") + " -o " + path("run.png") + " -q");
  ASSERT_EQ(r.exitCode, 0) << r.output;
  const nlohmann::json saved = nlohmann::json::parse(readWholeFile(path("run.json")));
  const auto edited = [&](const std::string& name, const auto& change) {
    nlohmann::json doc = saved;
    change(doc);
    std::ofstream(path(name)) << doc.dump();
    return path(name);
  };
  const struct {
    const char* name;
    std::function<void(nlohmann::json&)> change;
    const char* said;
  } cases[] = {
      {"pixels.json", [](nlohmann::json& d) { d["workers"][1]["pixels"] = "many"; },
       "the field \"workers[1].pixels\" must be a number or null, not a string"},
      {"width.json", [](nlohmann::json& d) { d["width"] = "wide"; },
       "the field \"width\" must be a number, not a string"},
      {"context.json", [](nlohmann::json& d) { d["context"] = 5; },
       "the field \"context\" must be an object, not a number"},
      {"span.json", [](nlohmann::json& d) { d["timeline"]["rows"][0]["rendering"] = {{0.5}}; },
       "the field \"timeline.rows[0].rendering[0]\" must be a pair of numbers"},
  };
  for (const auto& c : cases) {
    r = run("report " + edited(c.name, c.change) + " -o " + path("page.html"));
    EXPECT_EQ(r.exitCode, 2) << c.name << ": " << r.output;
    EXPECT_NE(r.output.find(c.said), std::string::npos) << r.output;
    EXPECT_NE(r.output.find(c.name), std::string::npos) << r.output;
    EXPECT_FALSE(fs::exists(path("page.html")));
  }
  const std::string huge = edited("huge.json", [](nlohmann::json& d) {
    d["notes"] = std::string(size_t{24} << 20, 'x');
    d["workers"][0]["comment"] = std::string(size_t{1} << 20, 'y');
  });
  r = run("report " + huge + " -o " + path("page.html"));
  ASSERT_EQ(r.exitCode, 0) << r.output;
  const std::string page = readWholeFile(path("page.html"));
  EXPECT_LT(page.size(), size_t{20} << 20);
  EXPECT_NE(page.find("left out of this page's copy: notes"), std::string::npos);
  const nlohmann::json embedded = embeddedReport(page);
  EXPECT_EQ(embedded["notes"]["left_out_bytes"], (size_t{24} << 20) + 2);
  EXPECT_TRUE(embedded.contains("ownership_map"));
}

TEST_F(ReportCliTest, ExperimentIndexGathersEverySummaryInTheFolder) {
  fs::create_directories(path("out"));
  // A summary left by an earlier experiment in the same folder.
  write("out/table3.md",
        "# Table III: serial times\n\nSome **bold** text and `code`.\n\n"
        "| case | seconds |\n|---|---|\n| A | 2.5 |\n");
  write("out/table3.csv", "case,seconds\nA,2.5\n");
  const Result r = run("experiment scale --quick --quiet --strategies blocks,self --scene " +
                       std::string(PRT_SOURCE_DIR) + "/scenes/complex.scene --out " + path("out"));
  ASSERT_EQ(r.exitCode, 0) << r.output;
  const std::string index = readWholeFile(path("out/index.html"));
  EXPECT_NE(index.find("<h3>Table III: serial times</h3>"), std::string::npos);
  EXPECT_NE(index.find("<td>2.5</td>"), std::string::npos);
  EXPECT_NE(index.find("<b>bold</b>"), std::string::npos);
  EXPECT_NE(index.find("href=\"table3.csv\""), std::string::npos);
  EXPECT_NE(index.find("id=\"scale\""), std::string::npos);
  EXPECT_NE(index.find("href=\"scale.csv\""), std::string::npos);
  EXPECT_LT(index.find("id=\"table3\""), index.find("id=\"scale\""));  // the experiments' order
  if (!findProgram("gnuplot").empty()) {
    EXPECT_NE(index.find("<img src=\"scale-efficiency-homogeneous.png\""), std::string::npos);
  }
  EXPECT_EQ(index.find("http"), std::string::npos) << "nothing fetched from the network";
}

// The spot checks are a sample: the report and the run's last lines say what they guarantee
// (each pixel checked with at least some probability, and so the chance a worker returning k
// wrong pixels was caught) and how to make them exact.
TEST_F(ReportCliTest, TheReportAndTheEndLinesSayWhatTheSpotChecksGuarantee) {
  const std::string render = "render " + kReportScene + " --width 24 --height 16 --workers 2 ";
  const Result sampled = run(render + "--report " + path("r.json") + " -o " + path("r.png"));
  ASSERT_EQ(sampled.exitCode, 0) << sampled.output;
  const nlohmann::json report = nlohmann::json::parse(readWholeFile(path("r.json")));
  EXPECT_EQ(report.value("verify_lowest_percent", -1.0), 0.5) << report.dump();
  const std::string guarantee = report.value("verify_guarantee", std::string());
  for (const char* words : {"at least 0.5 %", "k wrong pixels", "1 - (1 - 0.005)^k",
                            "39.4 % for k = 100", "--verify 100 checks every pixel"}) {
    EXPECT_NE(guarantee.find(words), std::string::npos) << words << " in: " << guarantee;
    EXPECT_NE(sampled.output.find(words), std::string::npos) << words << " in:\n" << sampled.output;
  }

  const Result exact =
      run(render + "--verify 100 --report " + path("x.json") + " -o " + path("x.png"));
  ASSERT_EQ(exact.exitCode, 0) << exact.output;
  const nlohmann::json all = nlohmann::json::parse(readWholeFile(path("x.json")));
  EXPECT_EQ(all.value("verify_lowest_percent", -1.0), 100.0);
  EXPECT_NE(all.value("verify_guarantee", std::string()).find("any wrong pixel was caught"),
            std::string::npos)
      << all.dump();
  EXPECT_NE(exact.output.find("any wrong pixel was caught"), std::string::npos) << exact.output;

  const Result off = run(render + "--verify 0 --report " + path("o.json") + " -o " + path("o.png"));
  ASSERT_EQ(off.exitCode, 0) << off.output;
  EXPECT_NE(nlohmann::json::parse(readWholeFile(path("o.json")))
                .value("verify_guarantee", std::string())
                .find("would not be noticed"),
            std::string::npos);
}

}  // namespace
}  // namespace prt
