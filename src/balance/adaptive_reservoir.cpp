#include "balance/adaptive_reservoir.h"

#include <algorithm>
#include <numeric>

#include "balance/interleaved_order.h"
#include "balance/reservoir_math.h"
#include "core/check.h"

namespace prt {

double commonFinishSeconds(const std::vector<double>& rates, const std::vector<uint64_t>& held,
                           uint64_t remaining) {
  PRT_CHECK(rates.size() == held.size());
  // Water filling: raise T past each worker's own finishing time h_i / r_i in turn.
  std::vector<size_t> order;
  for (size_t i = 0; i < rates.size(); ++i) {
    if (rates[i] > 0) order.push_back(i);
  }
  if (order.empty()) return 0;
  std::sort(order.begin(), order.end(), [&](size_t a, size_t b) {
    return static_cast<double>(held[a]) / rates[a] < static_cast<double>(held[b]) / rates[b];
  });
  double rateSum = 0;
  double heldSum = 0;
  double t = 0;
  for (size_t k = 0; k < order.size(); ++k) {
    rateSum += rates[order[k]];
    heldSum += static_cast<double>(held[order[k]]);
    t = (static_cast<double>(remaining) + heldSum) / rateSum;
    const bool last = k + 1 == order.size();
    if (last || t <= static_cast<double>(held[order[k + 1]]) / rates[order[k + 1]]) break;
  }
  return t;
}

AdaptiveReservoirStrategy::AdaptiveReservoirStrategy(double firstPercent, double reservePercent,
                                                     uint64_t minChunk)
    : firstPercent_(firstPercent), reservePercent_(reservePercent), minChunk_(minChunk) {
  PRT_CHECK(firstPercent_ > 0 && firstPercent_ <= 100);
  PRT_CHECK(reservePercent_ >= 0 && reservePercent_ < 100);
  PRT_CHECK(minChunk_ >= 1);
}

TaskSet AdaptiveReservoirStrategy::initialPool(const StartInfo& info) {
  return interleavedOrder(info.taskCount, info.frameTasks);
}

void AdaptiveReservoirStrategy::prepare(const StartInfo& info) {
  const std::vector<double>& speeds = info.speedIndexSeconds;
  const bool indexRun = std::any_of(speeds.begin(), speeds.end(),
                                    [&](double s) { return s != speeds.front(); });
  const std::vector<double> division =
      indexRun ? divisionOfLabor(speeds)
               : std::vector<double>(speeds.size(), 1.0 / static_cast<double>(speeds.size()));
  firstBlocks_ = initialBlockSizes(division, initialLimit(firstPercent_, info.taskCount));
}

uint64_t AdaptiveReservoirStrategy::initialSize(int worker) {
  return firstBlocks_[static_cast<size_t>(worker)];
}

std::vector<double> AdaptiveReservoirStrategy::rates() const {
  const int workerCount = workers().workerCount();
  std::vector<double> out(static_cast<size_t>(workerCount), 0.0);
  const std::vector<double>& index = speedIndexSeconds();
  double rateTimesIndex = 0;
  int measured = 0;
  for (int w : workers().liveList()) {
    if (throughput().measured(w)) {
      out[static_cast<size_t>(w)] = throughput().rate(w);
      rateTimesIndex += out[static_cast<size_t>(w)] * index[static_cast<size_t>(w)];
      ++measured;
    }
  }
  if (measured == 0) return out;
  // A worker not measured yet (one that just joined, above all) is taken to run as the
  // measured ones do per unit of speed index: rate x speed index averaged over them, divided
  // by its own index. With equal indices (no index run) that is their mean rate.
  for (int w : workers().liveList()) {
    if (!throughput().measured(w)) {
      out[static_cast<size_t>(w)] = rateTimesIndex / measured / index[static_cast<size_t>(w)];
    }
  }
  return out;
}

uint64_t AdaptiveReservoirStrategy::handOutSize(int worker) {
  const std::vector<double> rate = rates();
  const double mine = rate[static_cast<size_t>(worker)];
  if (mine <= 0) return minChunk_;  // results without times: fall back to small hand-outs
  std::vector<uint64_t> held(rate.size(), 0);
  for (int w : workers().liveList()) held[static_cast<size_t>(w)] = throughput().held(w);
  const double t = commonFinishSeconds(rate, held, remaining());
  const double share = mine * t - static_cast<double>(held[static_cast<size_t>(worker)]);
  const double take = share * (1 - reservePercent_ / 100);
  return std::max(minChunk_, ceilCount(take));
}

std::optional<Transfer> AdaptiveReservoirStrategy::stealFor(int worker) {
  const std::vector<double> rate = rates();
  const double mine = rate[static_cast<size_t>(worker)];
  if (mine <= 0) return std::nullopt;
  int victim = -1;
  double latest = 0;
  for (int w : workers().liveList()) {
    if (w == worker || rate[static_cast<size_t>(w)] <= 0 || awaitingSteal(w)) continue;
    const double finish =
        static_cast<double>(throughput().held(w)) / rate[static_cast<size_t>(w)];
    if (finish > latest) {
      latest = finish;
      victim = w;
    }
  }
  if (victim < 0) return std::nullopt;
  const double theirs = rate[static_cast<size_t>(victim)];
  const double held = static_cast<double>(throughput().held(victim));
  // The thief's part of what everyone holds were it shared so that all finish together: the
  // other idle workers will take their parts from the same victim.
  double heldSum = 0;
  double rateSum = 0;
  for (int w : workers().liveList()) {
    heldSum += static_cast<double>(throughput().held(w));
    rateSum += rate[static_cast<size_t>(w)];
  }
  const double fair = mine * heldSum / rateSum;
  const auto count = static_cast<uint64_t>(std::min(held * mine / (theirs + mine), fair));
  if (count < minChunk_) return std::nullopt;
  return Transfer{victim, worker, count};
}

}  // namespace prt
