#include "core/stop_signals.h"

#include <csignal>
#include <ctime>
#include <initializer_list>

#include "core/subprocess.h"

namespace prt {
namespace {

volatile std::sig_atomic_t stopSignal = 0;
struct timespec firstSignalAt {};  // CLOCK_MONOTONIC, when stopSignal was set

double secondsSince(const struct timespec& t) {
  struct timespec now {};
  clock_gettime(CLOCK_MONOTONIC, &now);  // async-signal-safe
  return static_cast<double>(now.tv_sec - t.tv_sec) +
         static_cast<double>(now.tv_nsec - t.tv_nsec) * 1e-9;
}

// The handlers installStopSignals replaced (those that remove temporary files and end the
// process, when main installed them), indexed by signal number.
constexpr int kSignals = 65;
struct sigaction replaced[kSignals];

extern "C" void onStopSignal(int sig) {
  if (stopSignal == 0) {
    clock_gettime(CLOCK_MONOTONIC, &firstSignalAt);
    stopSignal = sig;
    return;
  }
  // The same request delivered twice (see the header): not yet a second one.
  if (secondsSince(firstSignalAt) < kRepeatedSignalSeconds) return;
  // Asked twice: stop now, ending any program this process runs, through the handler that was
  // there before (which removes the temporary files being written), else as if none were.
  killRunningPrograms();
  const struct sigaction& before = replaced[sig];
  if ((before.sa_flags & SA_SIGINFO) == 0 && before.sa_handler != SIG_DFL &&
      before.sa_handler != SIG_IGN && before.sa_handler != onStopSignal) {
    before.sa_handler(sig);
  }
  std::signal(sig, SIG_DFL);
  std::raise(sig);
}

}  // namespace

void installStopSignals() {
  struct sigaction action {};
  action.sa_handler = onStopSignal;
  sigemptyset(&action.sa_mask);
  action.sa_flags = SA_RESTART;
  for (int sig : {SIGINT, SIGTERM, SIGHUP}) {
    struct sigaction before {};
    sigaction(sig, &action, &before);
    if (sig < kSignals && before.sa_handler != onStopSignal) replaced[sig] = before;
  }
}

int pendingStopSignal() {
  return stopSignal;
}

}  // namespace prt
