#pragma once
// Internal to src/mpi (it includes <mpi.h>).
//
// MpiAcceptor: the master's door for workers that join a running render. It opens an MPI port
// (MPI_Open_port), writes the port's name to a file (net/port_file.h: a joiner never reads
// half a name; never through a link; refused while another render holds it), and accepts
// connections (MPI_Comm_accept, collective over the joining job) on a thread of its own, so the
// master's loop never blocks: each accepted intercommunicator waits in a queue until the loop takes
// it (take()).
//
// Ending: MPI_Comm_accept cannot be cancelled, and a process that connects to its own port
// deadlocks in Open MPI 4.1, so another process must connect once to wake the thread: the
// master hands the port name to a live worker with its release (MpiLink::wakePort), which
// connects, says it is the wake-up call (a message with kWakeTag) and disconnects. A late
// joiner that read the port file just before it was removed may connect first: without that
// message it is turned away and the thread waits on for the real call. finishStop() waits up
// to `graceSeconds` for the thread; when no worker could wake it (all lost) the thread is left
// behind blocked, which Open MPI 4.1 tolerates at MPI_Finalize; what it uses is shared with
// it, so it outlives this object. The port file is removed first, so no new joiner reads it.
//
// Invitations (net/invitation.h): the port file, readable by its owner only, also holds a
// random secret. Before a joining job is queued, each of its ranks must answer a challenge
// with proof of the secret and a compatible version, within kProofSeconds; a job with a rank
// that does not is told why (kRefusedTag), dropped without a collective call (a hostile one
// cannot hold the thread up) and listed in refused().
// Needs MPI_THREAD_MULTIPLE.

#include <mpi.h>

#include <atomic>
#include <deque>
#include <memory>
#include <mutex>
#include <optional>
#include <set>
#include <string>
#include <thread>
#include <vector>

#include "net/invitation.h"
#include "net/port_file.h"

namespace prt::mpi_detail {

class MpiAcceptor {
 public:
  // Opens the port and writes its name to `portFile`. Throws InputError when the file cannot
  // be written, MpiError when MPI refuses (it lacks MPI_THREAD_MULTIPLE, or ports).
  // The file also gets the invitation's `secret` and the TCP door's `tcpAddresses`.
  MpiAcceptor(const std::string& portFile, const Secret& secret,
              const std::vector<std::string>& tcpAddresses);
  ~MpiAcceptor();
  MpiAcceptor(const MpiAcceptor&) = delete;
  MpiAcceptor& operator=(const MpiAcceptor&) = delete;

  static constexpr double kProofSeconds = 10;

  const std::string& portName() const { return state_->port; }
  // Why each joining job refused so far was turned away.
  std::vector<std::string> refused() const;
  // Refuses joiners from `host` from now on (a machine whose worker was rejected).
  void block(const std::string& host);
  // The next accepted intercommunicator, if one is waiting.
  std::optional<MPI_Comm> take();
  // Stops accepting in two steps: beginStop() removes the port file and makes the next
  // connection the wake-up call; finishStop() (after the wake-up was asked of a worker) waits
  // up to `graceSeconds` for the thread and closes the port. Joins accepted in the meantime are
  // disconnected. Both idempotent.
  void beginStop();
  void finishStop(double graceSeconds);

 private:
  // What the accepting thread uses: shared, so a thread left blocked outlives the acceptor.
  struct State {
    std::string port;
    Secret secret{};
    mutable std::mutex mutex;
    std::deque<MPI_Comm> accepted;
    std::vector<std::string> refused;
    std::set<std::string> blocked;  // machines refused
    std::atomic<bool> stopping{false};
    std::atomic<bool> finished{false};
  };
  static void acceptLoop(const std::shared_ptr<State>& state);
  // Empty when every rank of `inter` proved it was invited; otherwise why not.
  static std::string admit(const State& state, MPI_Comm inter);

  std::string file_;
  std::optional<PortFileClaim> claim_;  // the port file, held while joiners may come
  std::shared_ptr<State> state_ = std::make_shared<State>();
  std::thread thread_;
  bool begun_ = false;
  bool stopped_ = false;
};

// A worker's half of waking the acceptor: connects to `port` once, says it is the wake-up
// call, and disconnects.
void wakeAcceptor(const std::string& port);

}  // namespace prt::mpi_detail
