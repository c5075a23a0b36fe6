#pragma once
// The exit status, told to a launcher. Under `mpirun --enable-recovery` mpirun exits with 0
// whatever its ranks exit with (measured with Open MPI 4.1: exit(3), _exit(3) and MPI_Abort
// with 3 all give 0, and MPI_Abort with other ranks waiting hangs), so the documented codes
// cannot reach the shell through it. Rank 0 — the master, or a joining job's first rank —
// also writes its exit code to the file PRT_STATUS_FILE names, when set; scripts/prt-mpirun
// runs mpirun with it and exits with that code (a missing file: the master never ended by
// itself, exit 1). The first code recorded wins; thread-safe, async-signal-unsafe.

#include <string>

namespace prt {

void recordExitStatus(int code);

// Rank 0 of a render with a checkpoint: writes the checkpoint's path to PRT_STATUS_FILE.resume
// (when PRT_STATUS_FILE is set), so that scripts/prt-mpirun can say how to resume when the
// master is killed before its last words (plain mpirun after a lost rank: SIGTERM and SIGKILL
// together, measured with Open MPI 4.1).
void recordCheckpointPath(const std::string& path);

}  // namespace prt
