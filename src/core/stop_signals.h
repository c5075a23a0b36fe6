#pragma once
// Stop signals for long runs that can save their work: after installStopSignals(), SIGINT,
// SIGTERM and SIGHUP only set a flag, which the run polls (pendingStopSignal) to write a
// checkpoint and end with exit code 128 + the signal. A second such signal ends the process
// at once: it ends the programs the process runs (killRunningPrograms) and goes to the
// handler installStopSignals replaced (one that removes temporary files and exits), else acts
// as if no handler were installed. A second signal within kRepeatedSignalSeconds of the first
// is the same request, not a second one: launchers send one signal twice (GNU timeout sends
// it to the process and to its process group; a terminal's Ctrl-C reaches every process of
// the group). Async-signal-safe; the flag may be read from any thread.

namespace prt {

inline constexpr double kRepeatedSignalSeconds = 1.0;

void installStopSignals();
int pendingStopSignal();  // 0 while none has arrived

}  // namespace prt
