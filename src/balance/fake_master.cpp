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
    const double slowest =
        *std::max_element(config.speedIndexSeconds.begin(), config.speedIndexSeconds.end());
    for (double s : config.speedIndexSeconds) {
      FakeWorker w;
      w.rate = static_cast<uint64_t>(std::clamp(std::lround(slowest / s), 1L, 64L));
      workers_.push_back(w);
    }
    const auto n = static_cast<size_t>(config.taskCount);
    result_.renderCount.assign(n, 0);
    result_.assignCount.assign(n, 0);
    result_.recoveredCount.assign(n, 0);
    result_.lastBusyRound.assign(workers_.size(), 0);
  }

  FakeRunResult run() {
    const std::vector<double> told = config_.hideSpeedIndex
                                         ? std::vector<double>(workers_.size(), 1.0)
                                         : config_.speedIndexSeconds;
    apply(strategy_.start(StartInfo{config_.taskCount, told}));
    const uint64_t maxRounds = config_.maxRounds ? config_.maxRounds : 2 * config_.taskCount + 100;
    while (result_.rounds < maxRounds && result_.errors.empty()) {
      ++result_.rounds;
      if (pendingQuery_) answerQuery();
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
    return std::all_of(workers_.begin(), workers_.end(), [](const FakeWorker& w) {
      return w.lost || (w.queue.empty() && !w.needsRequest);
    });
  }

  Strategy& strategy_;
  const FakeRunConfig& config_;
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
