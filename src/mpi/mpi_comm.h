#pragma once
// Internal to src/mpi (it includes <mpi.h>): what an MpiSession holds behind its opaque
// pointer.

#include <mpi.h>

#include "mpi/mpi_session.h"

namespace prt {

struct MpiComm {
  MPI_Comm comm = MPI_COMM_NULL;  // a duplicate of MPI_COMM_WORLD with MPI_ERRORS_RETURN
  // Workers on one node time the Towers of Hanoi one after another, as the local driver does
  // with its threads, so ranks sharing cores do not slow each other's measurement. These are
  // the neighbouring worker ranks on this rank's node, or -1.
  int previousWorkerOnNode = -1;
  int nextWorkerOnNode = -1;
  bool runStarted = false;  // master: the scene has gone out (releaseWorkers does nothing)
  bool released = false;    // master: workers already released
};

}  // namespace prt
