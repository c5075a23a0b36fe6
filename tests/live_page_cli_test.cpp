// The live page of `prt render --serve` against hostile clients and names, through the prt
// command: slow clients over loopback while the page is probed, and a name whose text looks
// like loopback but resolves elsewhere (in a mount and network namespace of the test's own,
// skipped without the privilege to make one).

#include <gtest/gtest.h>
#include <httplib.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <filesystem>
#include <memory>
#include <regex>
#include <thread>
#include <vector>

#include "core/subprocess.h"
#include "live/slow_http_client.h"
#include "prt_command.h"

namespace prt {
namespace {

using LivePageClock = std::chrono::steady_clock;

double livePageSecondsSince(LivePageClock::time_point start) {
  return std::chrono::duration<double>(LivePageClock::now() - start).count();
}

class LivePageCliTest : public e2e::ScratchDirTest {};

// Two "slowloris" clients (a header line a second, never ending the headers) connect while the
// render runs. Every probe of the page must be answered, and the process must end within the
// documented 3 s of writing its image (with a margin for a loaded machine), not when the slow
// clients give up (40 s here).
TEST_F(LivePageCliTest, SlowClientsHoldNeitherThePageNorTheExit) {
  const std::string errors = path("render.err");
  const std::string image = path("live.png");
  const std::string command =
      "exec " + e2e::prtBinary() + " render " + std::string(PRT_SOURCE_DIR) +
      "/scenes/fig08-basic-features.scene --width 48 --height 36 --spp 4 --workers 2 "
      "--slowdown 400,400 --no-checkpoint --serve 127.0.0.1:0 -o " +
      image + " >/dev/null 2>" + errors;
  const pid_t child = e2e::spawnShellGroup(command);
  ASSERT_GE(child, 0);
  int port = 0;
  const std::regex address("live page at http://127\\.0\\.0\\.1:([0-9]+)/");
  for (int i = 0; i < 400 && port == 0; ++i) {
    std::smatch m;
    const std::string text = readWholeFile(errors);
    if (std::regex_search(text, m, address)) port = std::stoi(m[1]);
    if (port == 0) std::this_thread::sleep_for(std::chrono::milliseconds(25));
  }
  if (port == 0) kill(-child, SIGKILL);
  ASSERT_GT(port, 0) << readWholeFile(errors);

  std::vector<std::unique_ptr<test_clients::SlowHttpClient>> slow;
  for (int i = 0; i < 2; ++i) {
    slow.push_back(std::make_unique<test_clients::SlowHttpClient>(port, "127.0.0.1", 1.0, 40.0));
    EXPECT_TRUE(slow.back()->connected());
  }
  // Probe the page until the image is written, and on until the process ends (a page that
  // polls is what finish() waits for, at most 3 s).
  int probes = 0, answered = 0;
  std::optional<LivePageClock::time_point> imageAt;
  int status = 0;
  const auto start = LivePageClock::now();
  for (;;) {
    if (waitpid(child, &status, WNOHANG) == child) break;
    if (!imageAt && std::filesystem::exists(image)) imageAt = LivePageClock::now();
    if (livePageSecondsSince(start) > 60) {
      kill(-child, SIGKILL);
      waitpid(child, &status, 0);
      FAIL() << "the render did not end within 60 s";
    }
    if (!imageAt) {
      httplib::Client client("127.0.0.1", port);
      client.set_connection_timeout(2);
      client.set_read_timeout(2);
      const auto r = client.Get("/status.json");
      ++probes;
      if (r && r->status == 200) ++answered;
    }
    std::this_thread::sleep_for(std::chrono::milliseconds(200));
  }
  const double afterImage = imageAt ? livePageSecondsSince(*imageAt) : -1;
  EXPECT_TRUE(WIFEXITED(status) && WEXITSTATUS(status) == 0) << readWholeFile(errors);
  ASSERT_TRUE(imageAt.has_value()) << readWholeFile(errors);
  EXPECT_GT(probes, 0);
  EXPECT_EQ(answered, probes) << "page probes went unanswered while slow clients were connected";
  EXPECT_LT(afterImage, 6.0) << "the process ended " << afterImage
                             << " s after writing its image (the docs say at most 3 s)";
}

// `--serve NAME:PORT` skips the token only when NAME resolves to loopback addresses alone,
// whatever its text says: "127.example.test" mapped to 0.0.0.0 must get a token. The name is
// mapped by an /etc/hosts of the test's own, bind-mounted in a mount namespace of its own
// (this machine's /etc/hosts is never touched), and the render listens in a network namespace
// of its own with only its loopback (0.0.0.0 there reaches nothing else).
TEST_F(LivePageCliTest, ANameSkipsTheTokenOnlyWhenItResolvesToLoopback) {
  if (geteuid() != 0) GTEST_SKIP() << "making mount and network namespaces needs root";
  if (findProgram("unshare").empty() || findProgram("ip").empty()) {
    GTEST_SKIP() << "no unshare (util-linux) or ip (iproute2)";
  }
  const std::string hosts = write("hosts",
                                  "127.0.0.1 localhost\n"
                                  "0.0.0.0 127.example.test\n"
                                  "127.0.0.5 loop.example.test\n");
  const auto serve = [&](const std::string& name) {
    return e2e::runShell("unshare --mount --net sh -c 'ip link set lo up && mount --bind " + hosts +
                         " /etc/hosts && exec " + e2e::prtBinary() + " render " +
                         std::string(PRT_SOURCE_DIR) +
                         "/scenes/fig06-primitives.scene --width 16 --height 12 "
                         "--no-checkpoint --serve " +
                         name + ":0 -o " + path("out.png") + "'");
  };
  const e2e::Result probe = serve("localhost");
  if (probe.output.find("live page at") == std::string::npos) {
    GTEST_SKIP() << "cannot make the namespaces here: " << lastLines(probe.output, 4);
  }
  EXPECT_EQ(probe.exitCode, 0) << probe.output;
  EXPECT_NE(probe.output.find("live page at http://localhost:"), std::string::npos);
  EXPECT_EQ(probe.output.find("?token="), std::string::npos) << probe.output;

  const e2e::Result loop = serve("loop.example.test");
  EXPECT_EQ(loop.exitCode, 0) << loop.output;
  EXPECT_EQ(loop.output.find("?token="), std::string::npos)
      << "a name resolving to 127.0.0.5 needs no token:\n"
      << loop.output;

  const e2e::Result everywhere = serve("127.example.test");
  EXPECT_EQ(everywhere.exitCode, 0) << everywhere.output;
  EXPECT_NE(everywhere.output.find("live page at http://127.example.test:"), std::string::npos)
      << everywhere.output;
  EXPECT_NE(everywhere.output.find("?token="), std::string::npos)
      << "'127.example.test' resolves to 0.0.0.0 (every interface) but got no token:\n"
      << everywhere.output;
}

}  // namespace
}  // namespace prt
