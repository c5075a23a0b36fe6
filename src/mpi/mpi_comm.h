#pragma once
// Internal to src/mpi (it includes <mpi.h>): what an MpiSession holds behind its opaque
// pointer.

#include <mpi.h>

#include "mpi/mpi_session.h"

namespace prt {

struct MpiComm {
  MPI_Comm comm = MPI_COMM_NULL;  // a duplicate of MPI_COMM_WORLD with MPI_ERRORS_RETURN
  bool runStarted = false;        // master: the scene has gone out (releaseWorkers does nothing)
  bool released = false;          // master: workers already released
  bool skipFinalize = false;      // a rank was lost: MPI_Finalize would wait for it
};

}  // namespace prt
