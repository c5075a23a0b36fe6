#pragma once
// The local driver: the master and N workers as threads of one process that share nothing but
// messages (encoded bytes through mailboxes). The default way to run PRT, and the reference
// the MPI driver and the simulator are checked against.
//
// Faults: a worker that crashes (its thread ends, as a dropped connection) is reported to the
// master at once; one that hangs is declared lost after `workerTimeoutSeconds` of silence
// while it owes the master an answer. Either way its unfinished tasks are reassigned and the
// image is the same.
// Workers measure their speed indices concurrently, as separate machines would; like the
// rendering, the measurement is faithful while the workers' combined demand (sum of 1/k_i)
// fits the free cores.

#include <optional>

#include "drive/parallel_run.h"

namespace prt {

struct LocalRunRequest {
  Scene scene;
  RenderSettings settings;
  ParallelOptions options;
  double masterSpeedIndexSeconds = 0;   // the serial machine's speed index, for MASU
  std::optional<double> serialSeconds;  // for speed-up and ASU
};

// Throws InputError for invalid options, std::runtime_error if every worker is lost.
ParallelRun renderLocal(const LocalRunRequest& request);

}  // namespace prt
