// The simulator at scale: cost-map range queries as the simulator asks them (contiguous and
// scatter-strided batches over a 3840x2160 map), and whole simulations of 1,024 workers on a
// 3840x2160 image for every strategy (target: well under 10 s each).
//
// Run: build/bench/sim/prt_bench_sim  (add --benchmark_filter=Simulate to skip the queries)

#include <benchmark/benchmark.h>

#include <algorithm>
#include <string>

#include "balance/strategy.h"
#include "sim/simulator.h"
#include "sim/synthetic_cost.h"
#include "sim/worker_speeds.h"

namespace prt {
namespace {

constexpr int kWidth = 3840;
constexpr int kHeight = 2160;

const CostMap& map4k() {
  static const CostMap map = complexSceneCostMap(kWidth, kHeight, 3600);
  return map;
}

// One pass over the whole map in batches of 128 tasks, as 1,024 workers would render it:
// contiguous blocks (range(0) == 1) or scatter shares (stride 1,024).
void BM_CostMapOnePass(benchmark::State& state) {
  const CostMap& map = map4k();
  const uint64_t stride = static_cast<uint64_t>(state.range(0));
  const uint64_t pixels = map.pixelCount();
  for (auto _ : state) {
    double total = 0;
    for (uint64_t share = 0; share < stride; ++share) {
      const uint64_t count = (pixels - share + stride - 1) / stride;
      for (uint64_t i = 0; i < count; i += 128) {
        const uint64_t n = std::min<uint64_t>(128, count - i);
        total += map.seconds(TaskRun{share + i * stride, n, stride});
      }
    }
    benchmark::DoNotOptimize(total);
  }
  state.SetItemsProcessed(static_cast<int64_t>(state.iterations() * pixels));
}
BENCHMARK(BM_CostMapOnePass)->Arg(1)->Arg(1024)->Unit(benchmark::kMillisecond);

void BM_SyntheticMap4k(benchmark::State& state) {
  for (auto _ : state) benchmark::DoNotOptimize(complexSceneCostMap(kWidth, kHeight, 60));
}
BENCHMARK(BM_SyntheticMap4k)->Unit(benchmark::kMillisecond);

// 1,024 workers with log-normal speeds (sigma 0.5) on 3840x2160, batches of 128 pixels.
void BM_Simulate1024Workers4k(benchmark::State& state, const std::string& strategy) {
  SimulationOptions options;
  options.strategy = strategy;
  options.speeds = lognormalSpeeds(1024, 0.5, 1);
  const CostMap& map = map4k();
  double elapsed = 0;
  uint64_t events = 0;
  for (auto _ : state) {
    const SimulatedRun run = simulate(map, options);
    elapsed = run.report.elapsedSeconds;
    events = run.simulationEvents;
  }
  state.counters["virtual_s"] = elapsed;
  state.counters["events"] = static_cast<double>(events);
}

}  // namespace
}  // namespace prt

int main(int argc, char** argv) {
  for (const std::string& name : prt::strategyNames()) {
    benchmark::RegisterBenchmark(("BM_Simulate1024Workers4k/" + name).c_str(),
                                 prt::BM_Simulate1024Workers4k, name)
        ->Unit(benchmark::kSecond)
        ->Iterations(1);
  }
  benchmark::Initialize(&argc, argv);
  benchmark::RunSpecifiedBenchmarks();
  benchmark::Shutdown();
  return 0;
}
