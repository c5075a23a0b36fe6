#pragma once
// prt join over TCP: this process becomes one more worker of a running render whose master
// opened its door with --accept-workers FILE (net/tcp_door.h). No MPI is involved, so it works
// across hosts and under any launcher: `prt join FILE` on a machine, `srun prt join FILE` in a
// Slurm job (one worker per task), or ssh. Each process joins on its own.

#include <string>
#include <vector>

#include "core/speed_schedule.h"

namespace prt {

struct TcpJoinRequest {
  std::string portFile;
  int threads = 0;      // rendering threads; 0: every CPU it may use (core/cpu_allocation.h)
  int sharingProcesses = 1;  // joiners started on this machine together, sharing its CPUs
  double slowdown = 1;  // emulation: this many times slower
  std::vector<SpeedChange> slowdownChanges;  // its --slowdown-at (the worker field unused)
  double connectTimeoutSeconds = 30;
};

// Joins, renders until the master stops it, and returns the process's exit code: 0 when the
// run ended (or this worker was told to stop), 1 when the master could not be reached, refused
// it or stopped answering. Throws InputError for a missing or unreadable port file.
int runTcpJoiner(const TcpJoinRequest& request);

}  // namespace prt
