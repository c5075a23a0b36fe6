#include "core/stop_signals.h"

#include <gtest/gtest.h>

#include <sys/wait.h>
#include <unistd.h>

#include <csignal>
#include <ctime>

namespace prt {
namespace {

// Runs `body` in a child process (signals and their handlers are the process's own); the
// child's wait status.
template <typename F>
int inChild(F body) {
  const pid_t pid = fork();
  if (pid == 0) {
    body();
    _exit(0);
  }
  int status = 0;
  waitpid(pid, &status, 0);
  return status;
}

void sleepSeconds(double s) {
  struct timespec t {};
  t.tv_sec = static_cast<time_t>(s);
  t.tv_nsec = static_cast<long>((s - static_cast<double>(t.tv_sec)) * 1e9);
  while (nanosleep(&t, &t) != 0) {
  }
}

// One request, as a launcher delivers it twice (GNU timeout signals the process and then its
// group): the run is asked to stop once, and lives to save its work.
TEST(StopSignals, TheSameSignalTwiceAtOnceIsOneRequest) {
  const int status = inChild([] {
    installStopSignals();
    std::raise(SIGTERM);
    std::raise(SIGTERM);
    if (pendingStopSignal() != SIGTERM) _exit(3);
  });
  ASSERT_TRUE(WIFEXITED(status)) << "killed by signal " << WTERMSIG(status);
  EXPECT_EQ(WEXITSTATUS(status), 0);
}

// Asked again later, the process stops at once, by the signal.
TEST(StopSignals, ASecondRequestLaterEndsTheProcess) {
  const int status = inChild([] {
    installStopSignals();
    std::raise(SIGINT);
    sleepSeconds(kRepeatedSignalSeconds + 0.2);
    std::raise(SIGINT);
    _exit(4);  // not reached
  });
  ASSERT_TRUE(WIFSIGNALED(status)) << "exit " << WEXITSTATUS(status);
  EXPECT_EQ(WTERMSIG(status), SIGINT);
}

}  // namespace
}  // namespace prt
