#include "balance/fake_master.h"

#include <algorithm>
#include <cmath>
#include <numeric>

#include "core/rng.h"

namespace prt::testing {
namespace {

struct FakeWorker {
  TaskSet queue;
  uint64_t rate = 1;  // tasks rendered per round
  bool lost = false;
  bool outstanding = false;  // asked for more, not answered yet
  bool needsRequest = true;  // will ask once its queue is empty
};

class FakeMaster {
 public:
  FakeMaster(Strategy& strategy, const FakeRunConfig& config)
      : strategy_(strategy), config_(config) {
    slowest_ =
        *std::max_element(config.speedIndexSeconds.begin(), config.speedIndexSeconds.end());
    for (double s : config.speedIndexSeconds) workers_.push_back(makeWorker(s));
    const auto n = static_cast<size_t>(config.taskCount);
    result_.renderCount.assign(n, 0);
    result_.assignCount.assign(n, 0);
    result_.recoveredCount.assign(n, 0);
    result_.lastBusyRound.assign(workers_.size(), 0);
    result_.renderedBy.assign(workers_.size(), 0);
  }

  FakeRunResult run() {
    const std::vector<double> told = config_.hideSpeedIndex
                                         ? std::vector<double>(workers_.size(), 1.0)
                                         : config_.speedIndexSeconds;
    StartInfo info{config_.taskCount, told};
    info.frameTasks = config_.frameTasks;
    apply(strategy_.start(info));
    const uint64_t maxRounds = config_.maxRounds ? config_.maxRounds : 2 * config_.taskCount + 100;
    while (result_.rounds < maxRounds && result_.errors.empty()) {
      ++result_.rounds;
      if (pendingQuery_) answerQuery();
      admitArrivals();
      maybeLoseWorker();
      for (int w : visitOrder()) visit(w);
      if (quiescent()) {
        result_.terminated = true;
        break;
      }
    }
    for (size_t w = 0; w < workers_.size(); ++w) {
      if (workers_[w].outstanding && !workers_[w].lost && result_.terminated) {
        error("worker " + std::to_string(w) + "'s request was never answered");
      }
    }
    return result_;
  }

 private:
  void error(const std::string& message) { result_.errors.push_back(message); }

  FakeWorker makeWorker(double speedIndexSeconds) const {
    FakeWorker w;
    w.rate = static_cast<uint64_t>(std::clamp(std::lround(slowest_ / speedIndexSeconds), 1L, 64L));
    return w;
  }

  // Arrivals due this round join as the master introduces them: onWorkerJoined, then a
  // request of their own unless they were given tasks at once.
  void admitArrivals() {
    const auto& arrivals = config_.arrivals;
    while (nextArrival_ < arrivals.size() && arrivals[nextArrival_].atRound <= result_.rounds) {
      const double s = arrivals[nextArrival_++].speedIndexSeconds;
      const int id = static_cast<int>(workers_.size());
      workers_.push_back(makeWorker(s));
      workers_.back().needsRequest = false;
      result_.lastBusyRound.push_back(0);
      result_.renderedBy.push_back(0);
      ++result_.joined;
      apply(strategy_.onWorkerJoined(id, config_.hideSpeedIndex ? 1.0 : s));
      FakeWorker& w = workers_[static_cast<size_t>(id)];
      if (w.queue.empty() && !w.outstanding) {
        w.outstanding = true;
        ++result_.requests;
        apply(strategy_.onRequest(id));
      }
    }
  }

  bool liveWorker(int w, const char* what) {
    if (w < 0 || static_cast<size_t>(w) >= workers_.size() ||
        workers_[static_cast<size_t>(w)].lost) {
      error(std::string(what) + " names worker " + std::to_string(w) + ", unknown or lost");
      return false;
    }
    return true;
  }

  void apply(const Decisions& decisions) {
    for (const Decision& d : decisions) std::visit([&](const auto& x) { on(x); }, d);
  }

  void on(const Assign& a) {
    if (!liveWorker(a.worker, "Assign")) return;
    FakeWorker& w = workers_[static_cast<size_t>(a.worker)];
    a.tasks.forEach([&](uint64_t t) {
      if (t >= config_.taskCount) {
        error("task " + std::to_string(t) + " out of range");
      } else {
        ++result_.assignCount[static_cast<size_t>(t)];
      }
    });
    w.queue.append(a.tasks);
    w.outstanding = false;
    w.needsRequest = true;
  }

  void on(const NoMoreWork& m) {
    if (m.worker >= 0 && static_cast<size_t>(m.worker) < workers_.size()) {
      workers_[static_cast<size_t>(m.worker)].outstanding = false;
    }
  }

  void on(const QueryQueues&) {
    ++result_.queries;
    pendingQuery_ = true;
  }

  void on(const Transfer& t) {
    ++result_.transfers;
    if (!liveWorker(t.from, "Transfer") || !liveWorker(t.to, "Transfer")) return;
    if (t.from == t.to) return error("Transfer to the sender itself");
    TaskSet moved = workers_[static_cast<size_t>(t.from)].queue.takeBack(t.count);
    FakeWorker& to = workers_[static_cast<size_t>(t.to)];
    to.queue.append(moved);
    if (to.outstanding || !moved.empty()) to.needsRequest = true;
    to.outstanding = false;
  }

  void answerQuery() {
    pendingQuery_ = false;
    std::vector<uint64_t> lengths;
    for (const FakeWorker& w : workers_) lengths.push_back(w.lost ? 0 : w.queue.size());
    apply(strategy_.onQueueLengths(lengths));
  }

  void maybeLoseWorker() {
    const int lost = config_.lostWorker;
    if (lost < 0 || lostDone_ || rendered_ < config_.loseAfterRendered) return;
    if (static_cast<size_t>(lost) >= workers_.size()) return;  // has not joined yet
    lostDone_ = true;
    FakeWorker& w = workers_[static_cast<size_t>(lost)];
    w.lost = true;
    w.outstanding = false;
    TaskSet unfinished = std::move(w.queue);
    w.queue = TaskSet();
    unfinished.forEach([&](uint64_t t) { ++result_.recoveredCount[static_cast<size_t>(t)]; });
    apply(strategy_.onWorkerLost(lost, unfinished));
  }

  // A reproducible shuffle of the workers for this round.
  std::vector<int> visitOrder() const {
    std::vector<int> order(workers_.size());
    std::iota(order.begin(), order.end(), 0);
    Rng rng(config_.seed * 0x9e3779b97f4a7c15ULL + result_.rounds);
    for (size_t i = order.size(); i > 1; --i) {
      const auto j = static_cast<size_t>(rng.uniform() * static_cast<double>(i));
      std::swap(order[i - 1], order[std::min(j, i - 1)]);
    }
    return order;
  }

  void visit(int index) {
    FakeWorker& w = workers_[static_cast<size_t>(index)];
    if (w.lost) return;
    uint64_t rate = w.rate;
    if (index == config_.slowedWorker && result_.rounds >= config_.slowedFromRound) {
      rate = config_.slowedRate;
    }
    TaskSet done = w.queue.takeFront(rate);
    done.forEach([&](uint64_t t) { ++result_.renderCount[static_cast<size_t>(t)]; });
    rendered_ += done.size();
    result_.renderedBy[static_cast<size_t>(index)] += done.size();
    if (!done.empty()) {
      result_.lastBusyRound[static_cast<size_t>(index)] = result_.rounds;
      // A round is one second; a worker that ran out part-way used a share of it.
      apply(strategy_.onResults(index, done,
                                static_cast<double>(done.size()) / static_cast<double>(rate)));
    }
    if (w.queue.empty() && w.needsRequest && !w.outstanding) {
      w.needsRequest = false;
      w.outstanding = true;
      ++result_.requests;
      apply(strategy_.onRequest(index));
    }
  }

  bool quiescent() const {
    if (pendingQuery_) return false;
    // The run goes on until every scripted arrival has joined, as a real one would not know.
    if (nextArrival_ < config_.arrivals.size() &&
        result_.renderCount.size() > 0 && !allRendered()) {
      return false;
    }
    return std::all_of(workers_.begin(), workers_.end(), [](const FakeWorker& w) {
      return w.lost || (w.queue.empty() && !w.needsRequest);
    });
  }

  bool allRendered() const {
    return std::all_of(result_.renderCount.begin(), result_.renderCount.end(),
                       [](uint32_t c) { return c > 0; });
  }

  Strategy& strategy_;
  const FakeRunConfig& config_;
  double slowest_ = 1;
  size_t nextArrival_ = 0;
  std::vector<FakeWorker> workers_;
  FakeRunResult result_;
  uint64_t rendered_ = 0;
  bool pendingQuery_ = false;
  bool lostDone_ = false;
};

}  // namespace

FakeRunResult runFakeMaster(Strategy& strategy, const FakeRunConfig& config) {
  return FakeMaster(strategy, config).run();
}

}  // namespace prt::testing
