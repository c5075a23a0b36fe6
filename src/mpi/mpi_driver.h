#pragma once
// The MPI driver: start-up and shutdown of a parallel render as the ranks of an mpirun job.
// All policy — the master and worker loops, leases, heartbeats, reissue, checkpoints, the
// report — is the driver kit's (farm/parallel_run.h), the same as the local driver's; this
// driver only provides the transport (mpi_transport.h) and decides how the job ends.
//
//   rank 0        the master: sends the scene, runs the strategy, assembles the image
//   rank r >= 1   worker r - 1: never reads the scene file; it gets the scene text from rank 0
//
// Faults (see docs/running.md, "Faults"): a worker rank that dies, hangs or is cut off is lost
// when its lease runs out, and the master finishes the image with the live ranks. For a rank
// that dies to leave the job alive, run `mpirun --enable-recovery`; without it mpirun ends the
// whole job, and the checkpoint (--checkpoint) keeps the finished pixels for --resume. After
// a loss, no rank calls MPI_Finalize (it would wait for the lost one); without recovery the
// master then ends the job with MPI_Abort(0) so that mpirun does not wait for a hung rank.
// `--inject-fault W:PIXELS:crash|hang` acts on worker W (rank W + 1): crash ends the process
// abruptly (exit code 3), hang stops it answering.

#include <string>
#include <vector>

#include "core/speed_schedule.h"
#include "farm/parallel_run.h"
#include "mpi/mpi_session.h"

namespace prt {

using MpiRunRequest = RunRequest;

// Rank 0. Throws InputError for invalid options, before anything is sent (the caller then
// releases the workers with session.releaseWorkers), and RunFailed when the run cannot finish.
ParallelRun renderMpiMaster(MpiSession& session, const RunRequest& request);

// Rank 0, after the outputs are written: ends the workers and tells the session how to end.
void finishMpiMaster(MpiSession& session, const ParallelRun& run);

// Ranks >= 1: runs worker rank - 1 until the master stops or releases it, and returns the
// process exit code (0 after a finished run; the master's code after a release). All ranks
// parse the same command line, so `options` matches the master's; only the per-worker fields
// (slowdown, faults), batchPixels, speedIndexKind, speedIndexDiscs and the timeout are used.
int runMpiWorker(MpiSession& session, const ParallelOptions& options);

// `prt join FILE`: every rank of this job is a worker that joins the render whose master wrote
// its port name to FILE (--accept-workers). Rank 0 reads the file and tells the others; all
// connect at once (MPI_Comm_connect), get their endpoints and the run's options from the
// master, and work until it stops or releases them. Returns the exit code: 0 after the run,
// 2 when the file holds no port name, 1 when the master cannot be reached within
// connectTimeoutSeconds (a render that has ended leaves a port nobody answers: Open MPI then
// waits for ever, so a watchdog ends the job).
struct JoinRequest {
  std::string portFile;
  int threads = 0;       // rendering threads of each joiner; 0: all its affinity allows
  double slowdown = 1;   // each joiner runs this many times slower (emulation)
  std::vector<SpeedChange> slowdownChanges;  // its --slowdown-at (the worker field unused)
  double connectTimeoutSeconds = 30;
};
int runJoinedWorkers(MpiSession& session, const JoinRequest& request);

}  // namespace prt
