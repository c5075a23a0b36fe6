#pragma once
// The local driver: the master and N workers as threads of one process that share nothing but
// messages (encoded bytes through mailboxes, drive/local_transport.h). The default way to run
// PRT, and the reference the MPI driver and the simulator are checked against. Everything but
// the threads and mailboxes is the driver kit's (drive/master_loop.h, drive/worker_loop.h),
// shared with the MPI driver.
//
// Faults: a worker thread that ends before its StopMsg (an injected crash, an exception such
// as running out of memory) drops its connection and is lost at once; one that hangs is lost
// when its lease runs out (`workerTimeoutSeconds` without a message, heartbeats included).
// Either way its unfinished tasks go to the live workers and the image is the same.
// Workers measure their speed indices concurrently, as separate machines would; like the
// rendering, the measurement is faithful while the workers' combined demand (sum of 1/k_i)
// fits the free cores.

#include "farm/parallel_run.h"

namespace prt {

using LocalRunRequest = RunRequest;

// Throws InputError for invalid options, RunFailed if the run cannot finish.
ParallelRun renderLocal(const RunRequest& request);

}  // namespace prt
