// The run page in a real browser: headless Chromium (Debian's chromium, installed by
// scripts/install-deps.sh) opens pages made by prt render --html, prt simulate --html and
// prt report, runs their script, and takes a screenshot. The tests check that the script ran
// to the end without logging anything (a script error is logged as a console message), that
// picking a worker from the address (#worker=N) highlighted it, and that the screenshot shows
// a drawn page, not a blank one. Skipped, saying why, where Chromium is missing or cannot
// start.

#include <gtest/gtest.h>
#include <httplib.h>
#include <nlohmann/json.hpp>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <regex>
#include <sstream>
#include <thread>

#include "core/subprocess.h"
#include "image/image_io.h"
#include "image/srgb.h"
#include "prt_command.h"

namespace prt {
namespace {

class BrowserPageTest : public e2e::ScratchDirTest {
 protected:
  // Skips the test (skip_ says why) unless Chromium is installed and opens a trivial page.
  void SetUp() override {
    ScratchDirTest::SetUp();
    if (findProgram("chromium").empty()) {
      skip_ =
          "chromium is not installed (scripts/install-deps.sh installs it); the page was "
          "not opened in a browser";
      return;
    }
    const std::string probe = write("probe.html", "<p>probe</p>");
    int status = 0;
    const std::string dom = chromium(probe, "--dump-dom", &status);
    if (!describeExit(status).empty() || dom.find("<p>probe</p>") == std::string::npos) {
      skip_ = "chromium cannot start here (" +
              (describeExit(status).empty() ? "no page" : describeExit(status)) +
              "): " + lastLines(dom, 4);
    }
  }

  // Runs Chromium on `page` with `mode` (--dump-dom, or --screenshot=FILE); returns what it
  // printed (the DOM and its log). A failure past the probe fails the test.
  std::string chromium(const std::string& page, const std::string& mode, int* status = nullptr) {
    std::vector<std::string> args = {"60",
                                     findProgram("chromium"),
                                     "--headless",
                                     "--no-sandbox",
                                     "--disable-gpu",
                                     "--no-first-run",
                                     "--hide-scrollbars",
                                     "--user-data-dir=" + path("chromium-profile"),
                                     "--window-size=1280,2200",
                                     "--virtual-time-budget=3000",
                                     "--enable-logging=stderr",
                                     "--v=0",
                                     mode,
                                     page.rfind("http", 0) == 0 ? page : "file://" + page};
    const std::string log = path("chromium.log");
    const int exit = runProgram(findProgram("timeout"), args, path(""), log);
    if (status) {
      *status = exit;
    } else {
      EXPECT_EQ(describeExit(exit), "") << "chromium on " << page;
    }
    return readWholeFile(log);
  }

  // Console messages the page logged: none is expected, an error above all.
  static std::vector<std::string> consoleLines(const std::string& log) {
    std::vector<std::string> lines;
    std::istringstream in(log);
    for (std::string line; std::getline(in, line);) {
      if (line.find(":CONSOLE") != std::string::npos) lines.push_back(line);
    }
    return lines;
  }

  std::string skip_;
};

#define SKIP_IF_NO_BROWSER()                   \
  do {                                         \
    if (!skip_.empty()) GTEST_SKIP() << skip_; \
  } while (0)

TEST_F(BrowserPageTest, RenderedRunPageDrawsAndHighlightsAWorker) {
  SKIP_IF_NO_BROWSER();
  const auto render = e2e::run("render " + std::string(PRT_SOURCE_DIR) +
                               "/scenes/fig06-primitives.scene --width 96 --height 72 --workers 3 "
                               "--strategy reservoir --serial-seconds 1 --html " +
                               path("run.html") + " --report " + path("run.json") + " -o " +
                               path("run.png") + " -q");
  ASSERT_EQ(render.exitCode, 0) << render.output;

  const std::string dom = chromium(path("run.html") + "#worker=1", "--dump-dom");
  EXPECT_EQ(consoleLines(dom), std::vector<std::string>{}) << "the page logged messages";
  EXPECT_NE(dom.find("data-page-ready=\"yes\""), std::string::npos)
      << "the script did not run to its end:\n"
      << lastLines(dom, 20);
  EXPECT_NE(dom.find("<tr class=\"worker sel\" data-first=\"1\""), std::string::npos)
      << "worker 1 was not highlighted in the table";
  EXPECT_NE(dom.find("picked"), std::string::npos);
  EXPECT_NE(dom.find("worker 1: "), std::string::npos) << "no description of the picked worker";

  const std::string shot = path("shot.png");
  const std::string log = chromium(path("run.html") + "#worker=1", "--screenshot=" + shot);
  EXPECT_EQ(consoleLines(log), std::vector<std::string>{});
  const Image image = readImage(shot);
  ASSERT_GT(image.width(), 600);
  // A drawn page: much besides the light background, and colour from the image, the map and
  // the timeline (a page whose canvas stayed empty has almost none).
  double inked = 0, coloured = 0;
  for (size_t p = 0; p < image.pixelCount(); ++p) {
    const Color c = image.at(p);
    const int r = linearToSrgb8(c.x), g = linearToSrgb8(c.y), b = linearToSrgb8(c.z);
    if (std::min({r, g, b}) < 200) ++inked;
    if (std::max({r, g, b}) - std::min({r, g, b}) > 80) ++coloured;
  }
  const double n = static_cast<double>(image.pixelCount());
  EXPECT_GT(inked / n, 0.08) << "the screenshot is almost blank";
  EXPECT_GT(coloured / n, 0.02) << "the screenshot has almost no colour";
}

TEST_F(BrowserPageTest, LargeSimulatedRunAndItsSavedReportOpen) {
  SKIP_IF_NO_BROWSER();
  const auto sim = e2e::run(
      "simulate --workers 1024 --width 320 --height 180 --slow-share 0.5 "
      "--html " +
      path("sim.html") + " --report " + path("sim.json") + " -q");
  ASSERT_EQ(sim.exitCode, 0) << sim.output;
  const auto again = e2e::run("report " + path("sim.json") + " -o " + path("again.html"));
  ASSERT_EQ(again.exitCode, 0) << again.output;
  for (const char* page : {"sim.html", "again.html"}) {
    const std::string dom = chromium(path(page) + "#worker=700", "--dump-dom");
    EXPECT_EQ(consoleLines(dom), std::vector<std::string>{}) << page;
    EXPECT_NE(dom.find("data-page-ready=\"yes\""), std::string::npos) << page;
    EXPECT_NE(dom.find("too many to draw one by one"), std::string::npos) << page;
    // The group row holding worker 700 (rows of 16: 688-703) is highlighted.
    EXPECT_NE(dom.find("class=\"row sel\" data-first=\"688\""), std::string::npos) << page;
  }
}

// The live page of a running render (--serve): Chromium loads it while the render runs, its
// script polls the status and draws a row per worker; then Ctrl-C ends the render.
TEST_F(BrowserPageTest, LivePageOfARunningRenderUpdatesAndShowsTheWorkers) {
  SKIP_IF_NO_BROWSER();
  const std::string errors = path("render.err");
  const std::string command = "exec " + e2e::prtBinary() + " render " +
                              std::string(PRT_SOURCE_DIR) +
                              "/scenes/complex.scene --case D --width 160 --height 120 "
                              "--workers 2 --slowdown 80,80 --no-checkpoint --serve 127.0.0.1:0 -o " +
                              path("live.png") + " >/dev/null 2>" + errors;
  const pid_t child = e2e::spawnShellGroup(command);
  ASSERT_GE(child, 0);
  std::string url;
  const std::regex address("live page at (http://127\\.0\\.0\\.1:[0-9]+/)");
  for (int i = 0; i < 400 && url.empty(); ++i) {
    std::smatch m;
    const std::string text = readWholeFile(errors);
    if (std::regex_search(text, m, address)) url = m[1];
    if (url.empty()) std::this_thread::sleep_for(std::chrono::milliseconds(25));
  }
  if (url.empty()) kill(-child, SIGKILL);
  ASSERT_FALSE(url.empty()) << readWholeFile(errors);
  // Chromium gets 3 s of virtual time: it comes once the first pixels are in, so that under
  // the load of the whole suite the page does not see only the start (the scene prepared and
  // sent, at 80 times slower).
  const std::smatch port = [&] {
    std::smatch p;
    std::regex_search(url, p, std::regex(":([0-9]+)/"));
    return p;
  }();
  httplib::Client client("127.0.0.1", std::stoi(port[1]));
  bool rendering = false;
  for (int i = 0; i < 600 && !rendering; ++i) {
    if (const auto status = client.Get("/status.json"); status && status->status == 200) {
      const auto s = nlohmann::json::parse(status->body, nullptr, false);
      rendering = s.is_object() && s.value("phase", "") == "rendering" &&
                  s.value("pixels_done", 0.0) > 0;
    }
    if (!rendering) std::this_thread::sleep_for(std::chrono::milliseconds(50));
  }
  if (!rendering) kill(-child, SIGKILL);
  ASSERT_TRUE(rendering) << "no pixels in 30 s: " << readWholeFile(errors);

  const std::string dom = chromium(url, "--dump-dom");
  // The render (about 25 s) is still running: Ctrl-C ends it as it would a user's.
  kill(-child, SIGINT);
  int status = 0;
  waitpid(child, &status, 0);
  EXPECT_TRUE(WIFEXITED(status) && WEXITSTATUS(status) == 128 + SIGINT) << readWholeFile(errors);
  EXPECT_EQ(consoleLines(dom), std::vector<std::string>{}) << "the page logged messages";
  std::smatch m;
  ASSERT_TRUE(std::regex_search(dom, m, std::regex("data-updates=\"([0-9]+)\""))) << dom;
  // Loaded, then updated at least once more (under load Chromium's 3 s of virtual time may
  // hold only two polls).
  EXPECT_GE(std::stoi(m[1]), 2) << "the page did not keep updating:\n" << lastLines(dom, 30);
  EXPECT_NE(dom.find("data-phase=\"rendering\""), std::string::npos) << lastLines(dom, 30);
  for (const char* row : {"<tr class=\"worker working\"><td><span class=\"swatch\"",
                          "</span>0</td>", "</span>1</td>"}) {
    EXPECT_NE(dom.find(row), std::string::npos) << row << "\n" << lastLines(dom, 30);
  }
  EXPECT_NE(dom.find("of 19,200 px"), std::string::npos) << lastLines(dom, 30);
  EXPECT_NE(dom.find("/image.png?v="), std::string::npos) << "the image was not loaded";
}

}  // namespace
}  // namespace prt
