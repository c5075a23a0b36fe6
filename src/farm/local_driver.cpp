#include "farm/local_driver.h"

#include <chrono>
#include <memory>
#include <thread>

#include "core/thread_failures.h"
#include "core/thread_start.h"
#include "drive/local_transport.h"

namespace prt {
namespace {

void runWorkerThread(LocalNetwork& net, int id, const ParallelOptions& options,
                     ThreadFailures& failures) {
  LocalTransport transport(net, id);
  WorkerFaultActions faults;
  faults.crash = [&] { transport.dropConnection(); };
  faults.hang = [&] {
    while (!net.isShutDown()) std::this_thread::sleep_for(std::chrono::milliseconds(5));
  };
  // An exception (out of memory above all) is kept for the caller, which stops the run and
  // reports it once: every worker shares this process's memory, so the others would not fare
  // better. A thread's exception must never reach std::terminate.
  const bool ran = failures.run([&] {
    if (runWorkerSide(transport, id, options, faults) == WorkerExit::MasterLost) {
      transport.dropConnection();
    }
  });
  if (!ran) transport.dropConnection();
}

}  // namespace

ParallelRun renderLocal(const RunRequest& request) {
  const ParallelOptions& options = request.options;
  validateParallelOptions(options, static_cast<uint64_t>(request.scene.image.width) *
                                       request.scene.image.height);
  const int n = options.workers;
  LocalNetwork net(options.totalWorkers());
  ThreadFailures failures;
  std::vector<std::thread> threads;
  const auto joinAll = [&] {
    net.shutDown();
    for (std::thread& t : threads) {
      if (t.joinable()) t.join();
    }
  };
  struct JoinOnExit {
    const decltype(joinAll)& join;
    ~JoinOnExit() { join(); }
  } joinOnExit{joinAll};
  net.restartClock();
  for (int w = 0; w < n; ++w) {
    threads.push_back(startThread(runWorkerThread, std::ref(net), w, std::cref(options),
                                  std::ref(failures)));
  }
  // --join-at: a thread that starts each wave's workers at its time, announcing each to the
  // master first, as a machine connecting does. It ends early when the run does.
  if (!options.joins.empty()) {
    // A joiner that cannot start (out of memory) is kept as the run's failure: the master
    // stops, and the joiners started so far end with the network.
    threads.push_back(startThread([&net, &options, &failures, n] {
      std::vector<std::thread> joiners;
      failures.run([&] {
        int next = n;
        for (const JoinWave& wave : options.joins) {  // in time order (validated)
          while (!net.isShutDown() && net.now() < wave.atSeconds) {
            std::this_thread::sleep_for(std::chrono::milliseconds(2));
          }
          if (net.isShutDown()) break;
          for (int k = 0; k < wave.count; ++k, ++next) {
            net.join(next);
            joiners.push_back(startThread(runWorkerThread, std::ref(net), next,
                                          std::cref(options), std::ref(failures)));
          }
        }
      });
      for (std::thread& t : joiners) t.join();
    }));
  }
  LocalTransport local(net, kMaster);
  const std::unique_ptr<Transport> wrapped =
      request.wrapLocalMaster ? request.wrapLocalMaster(local, net) : nullptr;
  Transport& master = wrapped ? *wrapped : local;
  try {
    ParallelRun run = runMasterSide(master, request, "local", [&] { return failures.any(); });
    joinAll();
    failures.rethrowFirst();
    return run;
  } catch (const RunFailed&) {
    joinAll();
    failures.rethrowFirst();  // what made the run stop, rather than its consequence
    throw;
  }
}

}  // namespace prt
