// libFuzzer target: the master's and a worker's state machines fed hostile traffic. The input is
// a script of records — [kind][sender][length: 2 bytes][message bytes] — each delivering one
// message (any bytes; most do not decode and are dropped, as the drivers drop them) to the
// master or to worker 0 from any sender, declaring a worker lost, or letting one join, while the
// master's clock runs and leases expire. Whatever the traffic, nothing may crash (a PRT_CHECK
// failure aborts: a crash here), and the master's books stay consistent: its pixel count never
// exceeds the image, and an image it calls complete has every pixel done.

#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <stdexcept>

#include "cluster/master.h"
#include "cluster/worker.h"

namespace {

constexpr uint64_t kPixels = 48;

prt::Message decodeOr(const uint8_t* data, size_t size, bool& ok) {
  try {
    ok = true;
    return prt::decode(data, size);
  } catch (const std::runtime_error&) {
    ok = false;
    return prt::HeartbeatMsg{};
  }
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  if (size < 1) return 0;
  static const char* kStrategies[] = {"adaptive", "hybrid", "reservoir", "scatter", "stealing"};
  const char* strategy = kStrategies[data[0] % 5];
  prt::MasterOptions options;
  options.checks = {50, 7};
  options.referee = [](const prt::TaskSet& pixels) {
    return std::vector<float>(3 * pixels.size(), 0.25f);
  };
  options.admit = [](const prt::WorkerIdentity& id) {
    return id.build.empty() || id.build[0] == 'p' ? std::string() : std::string("other build");
  };
  prt::Master master(prt::makeStrategy(strategy, {}), 3, kPixels, prt::SceneMsg{"s", 1, 1},
                     [](int, const prt::TaskSet&, const std::vector<float>&) {}, options);
  prt::Worker worker(0, prt::WorkerOptions{4, 0});
  double now = 0;
  master.start(now);
  size_t at = 1;
  int joins = 0;
  while (at + 4 <= size) {
    const uint8_t kind = data[at], sender = data[at + 1];
    const size_t length = data[at + 2] | (size_t{data[at + 3]} << 8);
    at += 4;
    const size_t take = length < size - at ? length : size - at;
    bool ok = false;
    const prt::Message message = decodeOr(data + at, take, ok);
    at += take;
    now += 0.01;
    const int workers = master.workerCount();
    switch (kind % 5) {
      case 0:
        if (ok) master.onMessage(sender % workers, message, now);
        break;
      case 1:
        if (ok) {
          const int from = sender % 4 == 0 ? prt::kMaster : sender % 4;
          worker.onMessage(from, message);
        }
        break;
      case 2:
        master.onWorkerLost(sender % workers, now, "fuzz");
        break;
      case 3:
        if (joins < 4) {
          master.onWorkerJoined(workers, now);
          ++joins;
        }
        break;
      default:
        master.expireLeases(now, 0.05 + (sender % 8) * 0.05);
        break;
    }
    if (worker.needsSetup()) {
      worker.limitTasks(kPixels);
      worker.setupDone(0.1, {"prt fuzz", "here"});
    } else if (worker.hasWork()) {
      const prt::TaskSet batch = worker.nextBatch();
      worker.batchDone(batch, std::vector<float>(3 * batch.size(), 0.25f));
    }
    if (master.doneCount() > kPixels) std::abort();
    if (master.complete() && master.doneCount() != kPixels) std::abort();
  }
  return 0;
}
