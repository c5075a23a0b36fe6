#pragma once
// Internal to src/mpi (it includes <mpi.h>): what an MpiSession holds behind its opaque
// pointer.

#include <mpi.h>

#include <memory>

#include "mpi/mpi_acceptor.h"
#include "mpi/mpi_session.h"
#include "mpi/mpi_transport.h"
#include "net/tcp_door.h"

namespace prt {

struct MpiComm {
  MPI_Comm comm = MPI_COMM_NULL;  // a duplicate of MPI_COMM_WORLD with MPI_ERRORS_RETURN
  bool runStarted = false;        // master: the scene has gone out (releaseWorkers does nothing)
  bool released = false;          // master: workers already released
  bool skipFinalize = false;      // a rank was lost: MPI_Finalize would wait for it
  bool threadMultiple = false;    // MPI_THREAD_MULTIPLE provided (needed to accept joiners)
  std::unique_ptr<mpi_detail::MpiLink> link;           // master: the run's, joiners and all
  std::unique_ptr<mpi_detail::MpiAcceptor> acceptor;   // master: --accept-workers (MPI)
  std::unique_ptr<TcpDoor> door;                       // master: --accept-workers (TCP)
};

}  // namespace prt
