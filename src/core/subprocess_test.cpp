#include "core/subprocess.h"

#include <gtest/gtest.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <atomic>
#include <chrono>
#include <filesystem>
#include <fstream>
#include <string>
#include <thread>

namespace prt {
namespace {

namespace fs = std::filesystem;

class SubprocessTest : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::temp_directory_path() / ("prt-subprocess-" + std::to_string(::getpid()));
    fs::create_directories(dir_);
  }
  void TearDown() override { fs::remove_all(dir_); }

  // Runs `script` with sh under `watch`; the seconds it took, and what it threw (or "").
  std::string runWatched(const std::string& script, const ProgramWatch& watch, double& seconds,
                         int& signal) {
    const auto start = std::chrono::steady_clock::now();
    std::string thrown;
    try {
      const int status = runProgram("/bin/sh", {"-c", script}, dir_, dir_ / "log", {}, watch);
      EXPECT_EQ(describeExit(status), "");
    } catch (const ProgramEnded& e) {
      thrown = e.what();
      signal = e.signal();
    }
    seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    return thrown;
  }

  // A watch that ends the child once its log has not grown for `stallSeconds`.
  ProgramWatch watchingTheLog(double stallSeconds) const {
    ProgramWatch watch;
    watch.stallSeconds = stallSeconds;
    watch.progressFiles = {dir_ / "log"};
    return watch;
  }

  // The pid the script wrote to `name`, once it is gone (a zombie counts as gone).
  bool childGone(const std::string& name) {
    std::ifstream in(dir_ / name);
    long pid = 0;
    if (!(in >> pid) || pid <= 0) return false;
    for (int i = 0; i < 100; ++i) {
      std::ifstream stat("/proc/" + std::to_string(pid) + "/stat");
      std::string text;
      if (!std::getline(stat, text)) return true;
      const size_t close = text.rfind(')');
      if (close != std::string::npos && close + 2 < text.size() && text[close + 2] == 'Z') {
        return true;
      }
      std::this_thread::sleep_for(std::chrono::milliseconds(20));
    }
    ::kill(static_cast<pid_t>(pid), SIGKILL);
    return false;
  }

  fs::path dir_;
};

// A child that makes no progress is ended at its deadline, with what it started.
TEST_F(SubprocessTest, AStalledChildIsEndedWithItsGroupAtTheDeadline) {
  const ProgramWatch watch = watchingTheLog(0.5);
  double seconds = 0;
  int signal = -1;
  const std::string thrown =
      runWatched("sleep 60 & echo $! > child.pid; wait", watch, seconds, signal);
  EXPECT_NE(thrown.find("made no progress for 0.5 s"), std::string::npos) << thrown;
  EXPECT_EQ(signal, 0);
  EXPECT_LT(seconds, 20) << "ended at a 0.5 s deadline, generously";
  EXPECT_TRUE(childGone("child.pid")) << "what the stalled child started outlived it";
}

// Progress (its log growing) keeps a child going past the deadline until it ends itself.
TEST_F(SubprocessTest, AChildThatMakesProgressIsNotEnded) {
  const ProgramWatch watch = watchingTheLog(0.6);
  double seconds = 0;
  int signal = -1;
  const std::string thrown = runWatched(
      "for i in 1 2 3 4 5 6 7 8; do echo $i; sleep 0.15; done", watch, seconds, signal);
  EXPECT_EQ(thrown, "");
  EXPECT_GT(seconds, 0.6) << "ran past the deadline while it made progress";
}

// A pending stop signal ends the child at once; killRunningPrograms ends it from anywhere.
TEST_F(SubprocessTest, AStopSignalOrKillRunningProgramsEndsTheChild) {
  std::atomic<int> pending{0};
  ProgramWatch watch;
  watch.stopSignal = [&] { return pending.load(); };
  std::thread stopper([&] {
    std::this_thread::sleep_for(std::chrono::milliseconds(300));
    pending = SIGTERM;
  });
  double seconds = 0;
  int signal = -1;
  std::string thrown = runWatched("sleep 60 & echo $! > a.pid; wait", watch, seconds, signal);
  stopper.join();
  EXPECT_NE(thrown.find("stopped by signal 15"), std::string::npos) << thrown;
  EXPECT_EQ(signal, SIGTERM);
  EXPECT_LT(seconds, 20);
  EXPECT_TRUE(childGone("a.pid"));

  std::thread killer([] {
    std::this_thread::sleep_for(std::chrono::milliseconds(300));
    killRunningPrograms();
  });
  const auto start = std::chrono::steady_clock::now();
  const int status = runProgram("/bin/sh", {"-c", "sleep 60 & echo $! > b.pid; wait"}, dir_,
                                dir_ / "log");
  killer.join();
  EXPECT_LT(std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count(), 20);
  EXPECT_TRUE(WIFSIGNALED(status) && WTERMSIG(status) == SIGKILL) << describeExit(status);
  EXPECT_TRUE(childGone("b.pid"));
}

}  // namespace
}  // namespace prt
