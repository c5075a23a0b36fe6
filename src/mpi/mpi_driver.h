#pragma once
// The MPI driver: the master and worker state machines (cluster/) as the ranks of an mpirun
// job, the same way the local driver (drive/local_driver.h) runs them as threads — the same
// encoded messages, event log, image assembly, report and worker effects (WorkerEngine), so a
// run under MPI is checked against a local run and the serial render bit for bit.
//
//   rank 0        the master: sends the scene, runs the strategy, assembles the image
//   rank r >= 1   worker r - 1: never reads the scene file; it gets the scene text from rank 0
//
// Protocol messages go rank to rank as their encoded bytes, worker-to-worker transfers
// directly between the two worker ranks. After StopMsg each worker sends the master a
// WorkerSummary (its events, rays and task count; see mpi/worker_summary.h for how its clock
// is aligned with the master's), and the master builds the report.
//
// Faults: unlike the local driver, a lost worker is not replaced. When a worker that owes the
// master an answer (Master::owesAnswer) stays silent for `workerTimeoutSeconds`, or MPI
// reports an error talking to a rank, the master prints a message naming the rank and aborts
// the job (MPI_Abort): the run fails, it never hangs. A worker process that dies is normally
// noticed by mpirun first, which then ends the job itself.
// `--inject-fault W:PIXELS:crash|hang` acts on worker W (rank W + 1): crash ends the process
// abruptly (exit code 3), hang stops it answering.

#include <optional>

#include "drive/parallel_run.h"
#include "mpi/mpi_session.h"

namespace prt {

struct MpiRunRequest {
  Scene scene;
  RenderSettings settings;
  ParallelOptions options;              // options.workers must be session.workerCount()
  double masterSpeedIndexSeconds = 0;   // the serial machine's speed index, for MASU
  std::optional<double> serialSeconds;  // for speed-up and ASU
};

// Rank 0. Throws InputError for invalid options, before anything is sent (the caller then
// releases the workers with session.releaseWorkers). Once the run has started, a lost worker or
// an MPI failure ends the job through session.abort() instead of returning.
ParallelRun renderMpiMaster(MpiSession& session, const MpiRunRequest& request);

// Ranks >= 1: runs worker rank - 1 until the master stops or releases it, and returns the
// process exit code (0 after a finished run; the master's code after a release). All ranks
// parse the same command line, so `options` matches the master's; only the per-worker fields
// (slowdown, faults), batchPixels, speedIndexKind and speedIndexDiscs are used here.
int runMpiWorker(MpiSession& session, const ParallelOptions& options);

}  // namespace prt
