// The port file of `prt render --accept-workers FILE`, through the prt command: a symbolic link
// planted at FILE by whoever can write its folder, and a second render given the FILE of a
// running one.

#include <gtest/gtest.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <filesystem>
#include <fstream>
#include <thread>

#include "core/subprocess.h"
#include "prt_command.h"

namespace prt {
namespace {

class PortFileCliTest : public e2e::ScratchDirTest {
 protected:
  std::string renderWithDoor(const std::string& portFile,
                             const std::string& extra = "--width 16 --height 12") {
    return "render " + std::string(PRT_SOURCE_DIR) +
           "/scenes/fig06-primitives.scene --workers 2 --no-checkpoint --accept-address "
           "127.0.0.1 --accept-workers " +
           portFile + " " + extra + " -o " + path("out.png");
  }
};

TEST_F(PortFileCliTest, ALinkPlantedAtThePortFileIsRefusedAndItsTargetKept) {
  const std::string victim = write("victim.txt", "precious\n");
  std::filesystem::create_directory(path("shared"));
  std::filesystem::create_symlink(victim, path("shared/prt-port"));
  const e2e::Result r = e2e::run(renderWithDoor(path("shared/prt-port")));
  EXPECT_EQ(r.exitCode, 2) << r.output;
  EXPECT_NE(r.output.find("symbolic link"), std::string::npos) << r.output;
  EXPECT_EQ(readWholeFile(victim), "precious\n") << "the file the link names was replaced";
  EXPECT_TRUE(std::filesystem::is_symlink(path("shared/prt-port")));

  // A link to a file that does not exist yet: refused too, and nothing made where it points.
  std::filesystem::create_symlink(path("made-by-root"), path("shared/dangling"));
  const e2e::Result dangling = e2e::run(renderWithDoor(path("shared/dangling")));
  EXPECT_EQ(dangling.exitCode, 2) << dangling.output;
  EXPECT_FALSE(std::filesystem::exists(path("made-by-root")));
  for (const auto& entry : std::filesystem::directory_iterator(path("shared"))) {
    EXPECT_EQ(entry.path().filename().string().find(".tmp-"), std::string::npos)
        << "left behind: " << entry.path();
  }
}

TEST_F(PortFileCliTest, ASecondRenderDoesNotTakeTheRunningOnesPortFile) {
  const std::string port = path("prt-port");
  const std::string errors = path("first.err");
  // The first render lasts a few seconds (400 times slower), its door open all along.
  const pid_t first = e2e::spawnShellGroup(
      "exec " + e2e::prtBinary() + " " +
      renderWithDoor(port, "--slowdown 400,400 --spp 4 --width 48 --height 36") + " >/dev/null 2>" +
      errors);
  ASSERT_GE(first, 0);
  std::string before;
  for (int i = 0; i < 400 && before.find("secret ") == std::string::npos; ++i) {
    std::this_thread::sleep_for(std::chrono::milliseconds(25));
    if (std::filesystem::exists(port)) before = readWholeFile(port);
  }
  if (before.find("secret ") == std::string::npos) kill(-first, SIGKILL);
  ASSERT_NE(before.find("secret "), std::string::npos) << readWholeFile(errors);

  const e2e::Result second = e2e::run(renderWithDoor(port));
  int status = 0;
  const bool firstStillRunning = waitpid(first, &status, WNOHANG) == 0;
  EXPECT_EQ(second.exitCode, 2) << second.output;
  EXPECT_NE(second.output.find("belongs to a render that is running"), std::string::npos)
      << second.output;
  if (firstStillRunning) {
    EXPECT_TRUE(std::filesystem::exists(port)) << "the running render's port file was removed";
    if (std::filesystem::exists(port)) {
      EXPECT_EQ(readWholeFile(port), before) << "the running render's secret was replaced";
    }
  }
  if (firstStillRunning) waitpid(first, &status, 0);
  EXPECT_TRUE(WIFEXITED(status) && WEXITSTATUS(status) == 0) << readWholeFile(errors);
  EXPECT_FALSE(std::filesystem::exists(port)) << "the render left its port file";

  // A port file left by a render that is gone (nobody holds it) is taken over.
  { std::ofstream(port) << "\nsecret " << std::string(64, 'a') << "\ntcp 127.0.0.1:9\n"; }
  const e2e::Result stale = e2e::run(renderWithDoor(port));
  EXPECT_EQ(stale.exitCode, 0) << stale.output;
  // Any other file there is kept, not replaced.
  { std::ofstream(port) << "notes\n"; }
  const e2e::Result other = e2e::run(renderWithDoor(port));
  EXPECT_EQ(other.exitCode, 2) << other.output;
  EXPECT_EQ(readWholeFile(port), "notes\n");
}

}  // namespace
}  // namespace prt
