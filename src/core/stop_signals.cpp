#include "core/stop_signals.h"

#include <csignal>
#include <initializer_list>

namespace prt {
namespace {

volatile std::sig_atomic_t stopSignal = 0;

extern "C" void onStopSignal(int sig) {
  if (stopSignal != 0) {
    // Asked twice: stop now.
    std::signal(sig, SIG_DFL);
    std::raise(sig);
    return;
  }
  stopSignal = sig;
}

}  // namespace

void installStopSignals() {
  struct sigaction action {};
  action.sa_handler = onStopSignal;
  sigemptyset(&action.sa_mask);
  action.sa_flags = SA_RESTART;
  for (int sig : {SIGINT, SIGTERM, SIGHUP}) sigaction(sig, &action, nullptr);
}

int pendingStopSignal() {
  return stopSignal;
}

}  // namespace prt
