#include "balance/hybrid.h"

#include <algorithm>

#include "balance/reservoir_math.h"
#include "balance/scatter.h"
#include "balance/weighted_scatter.h"
#include "core/check.h"

namespace prt {
namespace {

struct Share {
  int worker = 0;
  uint64_t amount = 0;  // excess of a sender, deficit of a receiver
  bool waiting = false;
};

// Largest amount first; among equals, waiting workers, then lower index.
bool before(const Share& a, const Share& b) {
  if (a.amount != b.amount) return a.amount > b.amount;
  if (a.waiting != b.waiting) return a.waiting;
  return a.worker < b.worker;
}

}  // namespace

std::vector<Transfer> diffusionTransfers(const std::vector<uint64_t>& lengths,
                                         const std::vector<bool>& live,
                                         const std::vector<bool>& waiting) {
  PRT_CHECK(lengths.size() == live.size());
  uint64_t total = 0;
  uint64_t liveCount = 0;
  for (size_t w = 0; w < lengths.size(); ++w) {
    if (!live[w]) continue;
    total += lengths[w];
    ++liveCount;
  }
  if (liveCount == 0) return {};
  const uint64_t target = (total + liveCount - 1) / liveCount;
  return diffusionTransfersTowards(lengths, live, waiting,
                                   std::vector<uint64_t>(lengths.size(), target));
}

std::vector<Transfer> diffusionTransfersTowards(const std::vector<uint64_t>& lengths,
                                                const std::vector<bool>& live,
                                                const std::vector<bool>& waiting,
                                                const std::vector<uint64_t>& targets) {
  PRT_CHECK(lengths.size() == live.size() && live.size() == waiting.size() &&
            targets.size() == live.size());
  std::vector<Share> senders;
  std::vector<Share> receivers;
  for (size_t w = 0; w < lengths.size(); ++w) {
    if (!live[w]) continue;
    const int worker = static_cast<int>(w);
    const uint64_t target = targets[w];
    if (lengths[w] > target) senders.push_back({worker, lengths[w] - target, waiting[w]});
    if (lengths[w] < target) receivers.push_back({worker, target - lengths[w], waiting[w]});
  }
  std::sort(senders.begin(), senders.end(), before);
  std::sort(receivers.begin(), receivers.end(), before);

  std::vector<Transfer> out;
  size_t s = 0;
  size_t r = 0;
  while (s < senders.size() && r < receivers.size()) {
    const uint64_t count = std::min(senders[s].amount, receivers[r].amount);
    out.push_back(Transfer{senders[s].worker, receivers[r].worker, count});
    senders[s].amount -= count;
    receivers[r].amount -= count;
    if (senders[s].amount == 0) ++s;
    if (receivers[r].amount == 0) ++r;
  }
  return out;
}

std::vector<TaskSet> HybridStrategy::shares(const StartInfo& info) const {
  if (speedWeighted_) return weightedScatterShares(info.taskCount, info.speedIndexSeconds);
  return scatterShares(info.taskCount, static_cast<int>(info.speedIndexSeconds.size()));
}

Decisions HybridStrategy::start(const StartInfo& info) {
  Decisions out = StaticStrategy::start(info);
  speedIndexSeconds_ = info.speedIndexSeconds;
  waiting_.assign(info.speedIndexSeconds.size(), false);
  queryOutstanding_ = false;
  return out;
}

Decisions HybridStrategy::onRequest(int worker) {
  if (!workers().isLive(worker)) return {NoMoreWork{worker}};
  waiting_[static_cast<size_t>(worker)] = true;
  if (queryOutstanding_) return {};
  queryOutstanding_ = true;
  return {QueryQueues{}};
}

Decisions HybridStrategy::onQueueLengths(const std::vector<uint64_t>& lengths) {
  if (!queryOutstanding_) return {};  // unsolicited: nobody is waiting for it
  queryOutstanding_ = false;
  const int workerCount = workers().workerCount();
  PRT_CHECK(lengths.size() == static_cast<size_t>(workerCount));
  std::vector<bool> live(static_cast<size_t>(workerCount));
  for (int w = 0; w < workerCount; ++w) live[static_cast<size_t>(w)] = workers().isLive(w);

  std::vector<Transfer> transfers;
  if (speedWeighted_) {
    uint64_t total = 0;
    std::vector<double> liveSpeeds;
    for (int w = 0; w < workerCount; ++w) {
      if (!live[static_cast<size_t>(w)]) continue;
      total += lengths[static_cast<size_t>(w)];
      liveSpeeds.push_back(speedIndexSeconds_[static_cast<size_t>(w)]);
    }
    std::vector<uint64_t> targets(static_cast<size_t>(workerCount), 0);
    if (!liveSpeeds.empty()) {
      const std::vector<double> division = divisionOfLabor(liveSpeeds);
      size_t i = 0;
      for (int w = 0; w < workerCount; ++w) {
        if (live[static_cast<size_t>(w)]) {
          targets[static_cast<size_t>(w)] = ceilCount(static_cast<double>(total) * division[i++]);
        }
      }
    }
    transfers = diffusionTransfersTowards(lengths, live, waiting_, targets);
  } else {
    transfers = diffusionTransfers(lengths, live, waiting_);
  }
  Decisions out;
  std::vector<bool> answered(static_cast<size_t>(workerCount), false);
  for (const Transfer& t : transfers) {
    answered[static_cast<size_t>(t.to)] = true;
    out.push_back(t);
  }
  for (int w = 0; w < workerCount; ++w) {
    const auto i = static_cast<size_t>(w);
    if (waiting_[i] && !answered[i]) out.push_back(NoMoreWork{w});
    waiting_[i] = false;
  }
  return out;
}

Decisions HybridStrategy::onWorkerLost(int worker, const TaskSet& unfinished) {
  if (worker >= 0 && static_cast<size_t>(worker) < waiting_.size()) {
    waiting_[static_cast<size_t>(worker)] = false;
  }
  return StaticStrategy::onWorkerLost(worker, unfinished);
}

Decisions HybridStrategy::onWorkerJoined(int worker, double speedIndexSeconds) {
  Decisions out = StaticStrategy::onWorkerJoined(worker, speedIndexSeconds);
  speedIndexSeconds_.push_back(speedIndexSeconds);
  waiting_.push_back(false);
  return out;
}

}  // namespace prt
