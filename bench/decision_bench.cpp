// What each strategy's decisions cost as the number of workers grows: 1,024 to 65,536 workers,
// half of them 4x slower, driven by a small event loop (each worker renders its queue in
// batches of 128 tasks at its speed, returns results, asks when its queue is empty; transfers
// move tasks from the back of the sender's queue; queue queries are answered at once). Only
// the time spent inside the strategy is counted, per kind of call:
//   handout_us  a request answered by an Assign (onRequest)
//   steal_us    a call that ordered a Transfer (onRequest, or onResults serving a waiting thief)
//   results_us  onResults that decided nothing (the learning)
//   query_us    onQueueLengths (the hybrids' diffusion round; it sees every worker's queue)
//   lost_us     onWorkerLost of one worker, with its queue
//   decision_us all the strategy's time over all the decisions it made, start() aside
//   start_s     start(), once per run (it orders the pool: O(tasks), not O(W))
// Two workloads: "4k", a 3840x2160 image (8,294,400 tasks), cut off after 50,000 strategy
// calls (PRT_BENCH_CALLS sets another number) (the hand-out phase; a full run is prt simulate's job, bench/scale.py); and "end",
// 256 tasks per worker run to the end (each batch's time
// jittered by up to half its mean), which reaches the end game (steals) at every size,
// with 1 in 512 workers lost along the way.
//
// Run: build/bench/prt_bench_decisions [--benchmark_filter=adaptive]
//      bench/decisions.py fits the growth exponent of each figure over the worker counts.

#include <benchmark/benchmark.h>

#include <chrono>
#include <cstdlib>
#include <cstdint>
#include <queue>
#include <string>
#include <variant>
#include <vector>

#include "balance/strategy.h"
#include "core/task_set.h"

namespace prt {
namespace {

using Clock = std::chrono::steady_clock;

// A run stops once the strategy has spent this long deciding (a strategy that walks every
// worker per decision would take many minutes at 65,536 workers); its figures are then over
// the calls made, and cut_off says so.
constexpr double kBudgetSeconds = 20;

struct Timed {
  double seconds = 0;
  uint64_t calls = 0;
  void add(double s) {
    seconds += s;
    ++calls;
  }
  double micros() const { return calls == 0 ? 0 : 1e6 * seconds / static_cast<double>(calls); }
};

struct Figures {
  Timed handout, steal, results, query, lost, other;
  double startSeconds = 0;  // start(): once per run, O(tasks) (the pool's order)
  bool cutOff = false;      // stopped at the time budget
  uint64_t decisions = 0;
  double totalSeconds() const {
    return handout.seconds + steal.seconds + results.seconds + query.seconds + lost.seconds +
           other.seconds;
  }
};

class Driver {
 public:
  Driver(Strategy& strategy, int workers, uint64_t tasks, uint64_t maxCalls, int loseEvery)
      : strategy_(strategy), maxCalls_(maxCalls), loseEvery_(loseEvery) {
    queue_.resize(static_cast<size_t>(workers));
    busy_.assign(static_cast<size_t>(workers), false);
    lost_.assign(static_cast<size_t>(workers), false);
    batch_.resize(static_cast<size_t>(workers));
    speed_.resize(static_cast<size_t>(workers));
    batches_.assign(static_cast<size_t>(workers), 0);
    computed_.assign(static_cast<size_t>(workers), 0);
    StartInfo info;
    info.taskCount = tasks;
    for (int w = 0; w < workers; ++w) {
      const bool slow = w % 2 == 1;
      info.speedIndexSeconds.push_back(slow ? 4.0 : 1.0);
      speed_[static_cast<size_t>(w)] = slow ? 250.0 : 1000.0;  // tasks per second
    }
    const Clock::time_point t0 = Clock::now();
    Decisions start = strategy_.start(info);
    figures_.startSeconds = seconds(t0);
    apply(start);
  }

  Figures run() {
    uint64_t finished = 0;
    while (!events_.empty() && calls_ < maxCalls_) {
      if (figures_.totalSeconds() > kBudgetSeconds) {  // a walk per decision at scale
        figures_.cutOff = true;
        break;
      }
      const auto [at, w] = events_.top();
      events_.pop();
      now_ = at;
      const auto i = static_cast<size_t>(w);
      busy_[i] = false;
      if (lost_[i]) continue;
      const TaskSet batch = std::move(batch_[i]);
      const double compute = computed_[i];
      ++finished;
      if (loseEvery_ > 0 && finished % static_cast<uint64_t>(loseEvery_) == 0 && w != 0) {
        lose(w, batch);
        continue;
      }
      timed(Call::Results, [&] { return strategy_.onResults(w, batch, compute); });
      if (queue_[i].empty()) {
        timed(Call::Request, [&] { return strategy_.onRequest(w); });
      } else {
        startBatch(w);
      }
    }
    return figures_;
  }

 private:
  enum class Call { Results, Request, Query, Lost };

  static double seconds(Clock::time_point t0) {
    return std::chrono::duration<double>(Clock::now() - t0).count();
  }

  template <typename F>
  void timed(Call call, F&& f) {
    const Clock::time_point t0 = Clock::now();
    Decisions out = f();
    const double s = seconds(t0);
    ++calls_;
    bool assign = false;
    bool transfer = false;
    bool query = false;
    for (const Decision& d : out) {
      assign |= std::holds_alternative<Assign>(d);
      transfer |= std::holds_alternative<Transfer>(d);
      query |= std::holds_alternative<QueryQueues>(d);
    }
    if (call == Call::Lost) {
      figures_.lost.add(s);
    } else if (call == Call::Query) {
      figures_.query.add(s);
    } else if (transfer) {
      figures_.steal.add(s);
    } else if (call == Call::Request && assign) {
      figures_.handout.add(s);
    } else if (call == Call::Results && out.empty()) {
      figures_.results.add(s);
    } else {
      figures_.other.add(s);
    }
    (void)query;
    apply(out);
  }

  void lose(int w, const TaskSet& current) {
    const auto i = static_cast<size_t>(w);
    lost_[i] = true;
    TaskSet unfinished = current;
    unfinished.append(queue_[i]);
    queue_[i] = TaskSet();
    timed(Call::Lost, [&] { return strategy_.onWorkerLost(w, unfinished); });
  }

  void apply(const Decisions& decisions) {
    figures_.decisions += decisions.size();
    bool queried = false;
    for (const Decision& d : decisions) {
      if (const auto* a = std::get_if<Assign>(&d)) {
        queue_[static_cast<size_t>(a->worker)].append(a->tasks);
        startBatch(a->worker);
      } else if (const auto* t = std::get_if<Transfer>(&d)) {
        TaskSet& from = queue_[static_cast<size_t>(t->from)];
        const TaskSet moved = from.takeBack(std::min(t->count, from.size()));
        if (lost_[static_cast<size_t>(t->to)]) continue;
        queue_[static_cast<size_t>(t->to)].append(moved);
        startBatch(t->to);
      } else if (std::holds_alternative<QueryQueues>(d)) {
        queried = true;
      }
    }
    if (queried) {
      std::vector<uint64_t> lengths(queue_.size(), 0);
      for (size_t w = 0; w < queue_.size(); ++w) {
        if (!lost_[w]) lengths[w] = queue_[w].size() + batch_[w].size();
      }
      timed(Call::Query, [&] { return strategy_.onQueueLengths(lengths); });
    }
  }

  void startBatch(int w) {
    const auto i = static_cast<size_t>(w);
    if (busy_[i] || lost_[i] || queue_[i].empty()) return;
    batch_[i] = queue_[i].takeFront(std::min<uint64_t>(128, queue_[i].size()));
    busy_[i] = true;
    computed_[i] = seconds(w, batch_[i].size());
    events_.emplace(now_ + computed_[i], w);
  }

  // A batch's time at the worker's speed, from half to one and a half times its mean (a fixed
  // hash of the worker and its batch count), so that queues drift apart and the end game
  // has work to steal.
  double seconds(int w, uint64_t tasks) {
    const auto i = static_cast<size_t>(w);
    uint64_t z = (static_cast<uint64_t>(w) << 32) + batches_[i]++;
    z = (z ^ (z >> 31)) * 0x7fb5d329728ea185ull;
    z = (z ^ (z >> 27)) * 0x81dadef4bc2dd44dull;
    const double jitter = 0.5 + static_cast<double>(z >> 11) / 9007199254740992.0;
    return jitter * static_cast<double>(tasks) / speed_[i];
  }

  Strategy& strategy_;
  uint64_t maxCalls_;
  int loseEvery_;
  uint64_t calls_ = 0;
  double now_ = 0;
  std::vector<TaskSet> queue_, batch_;
  std::vector<bool> busy_, lost_;
  std::vector<double> speed_;
  std::vector<uint64_t> batches_;
  std::vector<double> computed_;  // the current batch's seconds
  using Event = std::pair<double, int>;
  std::priority_queue<Event, std::vector<Event>, std::greater<>> events_;
  Figures figures_;
};

void report(benchmark::State& state, const Figures& f) {
  state.counters["handout_us"] = f.handout.micros();
  state.counters["steal_us"] = f.steal.micros();
  state.counters["results_us"] = f.results.micros();
  state.counters["query_us"] = f.query.micros();
  state.counters["lost_us"] = f.lost.micros();
  state.counters["decision_us"] =
      f.decisions == 0 ? 0 : 1e6 * f.totalSeconds() / static_cast<double>(f.decisions);
  state.counters["decisions"] = static_cast<double>(f.decisions);
  state.counters["steals"] = static_cast<double>(f.steal.calls);
  state.counters["strategy_s"] = f.totalSeconds();
  state.counters["start_s"] = f.startSeconds;
  state.counters["cut_off"] = f.cutOff ? 1 : 0;
}

uint64_t callLimit() {
  const char* text = std::getenv("PRT_BENCH_CALLS");
  return text != nullptr ? std::strtoull(text, nullptr, 10) : 50000;
}

void BM_Decisions4k(benchmark::State& state, const std::string& name) {
  const int workers = static_cast<int>(state.range(0));
  Figures f;
  for (auto _ : state) {
    std::unique_ptr<Strategy> strategy = makeStrategy(name, StrategyOptions{});
    Driver driver(*strategy, workers, 3840ull * 2160, callLimit(), 0);
    f = driver.run();
  }
  report(state, f);
}

void BM_DecisionsEnd(benchmark::State& state, const std::string& name) {
  const int workers = static_cast<int>(state.range(0));
  Figures f;
  for (auto _ : state) {
    std::unique_ptr<Strategy> strategy = makeStrategy(name, StrategyOptions{});
    Driver driver(*strategy, workers, 256ull * static_cast<uint64_t>(workers), UINT64_MAX, 512);
    f = driver.run();
  }
  report(state, f);
}

}  // namespace
}  // namespace prt

int main(int argc, char** argv) {
  for (const std::string& name : prt::strategyNames()) {
    using Bench = void (*)(benchmark::State&, const std::string&);
    const std::pair<const char*, Bench> kinds[] = {{"4k", prt::BM_Decisions4k},
                                                   {"end", prt::BM_DecisionsEnd}};
    for (const auto& [label, fn] : kinds) {
      benchmark::RegisterBenchmark(("BM_Decisions/" + std::string(label) + "/" + name).c_str(),
                                   fn, name)
          ->RangeMultiplier(4)
          ->Range(1024, 65536)
          ->Unit(benchmark::kSecond)
          ->Iterations(1);
    }
  }
  benchmark::Initialize(&argc, argv);
  if (benchmark::ReportUnrecognizedArguments(argc, argv)) return 1;
  benchmark::RunSpecifiedBenchmarks();
  benchmark::Shutdown();
  return 0;
}
