#include "drive/local_driver.h"

#include <chrono>
#include <cstdio>
#include <memory>
#include <thread>

#include "drive/local_transport.h"

namespace prt {
namespace {

void runWorkerThread(LocalNetwork& net, int id, const ParallelOptions& options) {
  LocalTransport transport(net, id);
  WorkerFaultActions faults;
  faults.crash = [&] { transport.dropConnection(); };
  faults.hang = [&] {
    while (!net.isShutDown()) std::this_thread::sleep_for(std::chrono::milliseconds(5));
  };
  try {
    const WorkerExit exit = runWorkerSide(transport, id, options, faults);
    if (exit == WorkerExit::MasterLost) transport.dropConnection();
  } catch (const std::bad_alloc&) {
    std::fprintf(stderr, "prt: worker %d: out of memory; its tasks go to the others\n", id);
    transport.dropConnection();
  } catch (const std::exception& e) {
    std::fprintf(stderr, "prt: worker %d failed: %s; its tasks go to the others\n", id, e.what());
    transport.dropConnection();
  }
}

}  // namespace

ParallelRun renderLocal(const RunRequest& request) {
  const ParallelOptions& options = request.options;
  validateParallelOptions(options, static_cast<uint64_t>(request.scene.image.width) *
                                       request.scene.image.height);
  const int n = options.workers;
  LocalNetwork net(n);
  std::vector<std::thread> threads;
  struct Joiner {
    LocalNetwork& net;
    std::vector<std::thread>& threads;
    ~Joiner() {
      net.shutDown();
      for (std::thread& t : threads) t.join();
    }
  } joiner{net, threads};
  net.restartClock();
  for (int w = 0; w < n; ++w) {
    threads.emplace_back(runWorkerThread, std::ref(net), w, std::cref(options));
  }
  LocalTransport master(net, kMaster);
  return runMasterSide(master, request, "local");
}

}  // namespace prt
