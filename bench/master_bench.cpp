// What one message costs the master as the number of workers grows: the real Master (ledger,
// leases, the default strategy) at 1,024 to 65,536 workers on a 3840x2160 image, each message
// followed by what the master loop does after every message (the next lease to run out, the
// leases that ran out). The time per iteration is, in microseconds:
//   BM_Heartbeat  a HeartbeatMsg from a worker (its lease renewed)
//   BM_Result     a ResultsMsg of 128 pixels without colours (the ledger's accounting, the
//                 strategy's learning, and a RequestMsg with its hand-out when the worker's
//                 queue is empty; the stand-in workers' own queue keeping is included)
// Colours are left out (the simulator's results): their cost, about 60 ns a pixel copied into
// the image, is per pixel and the same at any worker count (docs/results.md, "One master's
// load"). The transport's cost (decode, MPI) is not here either: bench/master_load.py measures
// whole runs.
//
// Run: build/bench/prt_bench_master

#include <benchmark/benchmark.h>

#include <cstdint>
#include <deque>
#include <memory>
#include <string>
#include <variant>
#include <vector>

#include "balance/registry.h"
#include "cluster/master.h"

namespace prt {
namespace {

constexpr uint64_t kPixels = 3840ull * 2160ull;
constexpr double kLease = 5;

// A master past its start: every worker set up and holding its first hand-out.
struct StartedMaster {
  explicit StartedMaster(int workers)
      : master(makeStrategy(kDefaultStrategy, {}), workers, kPixels, SceneMsg{"", 1, 1},
               nullptr),
        queues(static_cast<size_t>(workers)) {
    take(master.start(now));
    for (int w = 0; w < workers; ++w) take(master.onMessage(w, SpeedIndexMsg{0.08, {}}, now));
  }
  void take(const Outbox& out) {
    for (const Envelope& e : out) {
      if (const auto* t = std::get_if<TasksMsg>(&e.message)) {
        queues[static_cast<size_t>(e.to)].push_back(t->tasks);
      }
    }
  }
  // What the master loop does after each message.
  void afterMessage() {
    benchmark::DoNotOptimize(master.ledger().nextExpiry(kLease));
    take(master.expireLeases(now, kLease));
  }
  Master master;
  std::vector<std::deque<TaskSet>> queues;  // per worker: what it was given, in order
  double now = 0;
};

void BM_Heartbeat(benchmark::State& state) {
  const int workers = static_cast<int>(state.range(0));
  StartedMaster m(workers);
  int w = 0;
  for (auto _ : state) {
    m.now += 1e-6;
    m.take(m.master.onMessage(w, HeartbeatMsg{}, m.now));
    m.afterMessage();
    w = (w + 1) % workers;
  }
}

void BM_Result(benchmark::State& state) {
  const int workers = static_cast<int>(state.range(0));
  StartedMaster m(workers);
  int w = 0;
  for (auto _ : state) {
    // The next worker that holds something returns its next 128 pixels.
    auto& queue = m.queues[static_cast<size_t>(w)];
    while (!queue.empty() && queue.front().empty()) queue.pop_front();
    TaskSet batch;
    if (!queue.empty()) batch = queue.front().takeFront(128);
    const bool asks = queue.empty() || (queue.size() == 1 && queue.front().empty());
    m.now += 1e-6;
    if (!batch.empty()) m.take(m.master.onMessage(w, ResultsMsg{batch, {}, 0.1}, m.now));
    if (asks) m.take(m.master.onMessage(w, RequestMsg{}, m.now));
    m.afterMessage();
    w = (w + 1) % workers;
  }
}

void workerCounts(benchmark::internal::Benchmark* b) {
  for (int w : {1024, 4096, 16384, 65536}) b->Arg(w);
  b->Unit(benchmark::kMicrosecond);
}

BENCHMARK(BM_Heartbeat)->Apply(workerCounts);
BENCHMARK(BM_Result)->Apply(workerCounts);

}  // namespace
}  // namespace prt

BENCHMARK_MAIN();
