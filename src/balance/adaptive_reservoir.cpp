#include "balance/adaptive_reservoir.h"

#include <algorithm>
#include <cmath>
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
  return interleavedOrder(info);
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

void AdaptiveReservoirStrategy::onWorkerChanged(int worker) {
  const auto w = static_cast<size_t>(worker);
  if (w >= held_.size()) held_.resize(w + 1, 0);
  heldSum_ -= held_[w];
  held_[w] = 0;
  if (!workers().isLive(worker)) {
    measured_.erase(worker);
    unmeasured_.erase(worker);
    setFactor(w, NAN);
    return;
  }
  const uint64_t held = throughput().held(worker);
  held_[w] = held;
  heldSum_ += held;
  const double index = speedIndexSeconds()[w];
  const auto h = static_cast<double>(held);
  // A victim must hold something and have no steal on its way to it. (set() leaves an entry
  // that did not change alone.)
  const bool eligible = held > 0 && !awaitingSteal(worker);
  if (throughput().measured(worker) &&
      throughput().measuredTasks(worker) >= static_cast<double>(kMeasuredTasks)) {
    unmeasured_.erase(worker);
    const double r = throughput().rate(worker);
    if (r > 0) {
      measured_.set(worker, {h / r, r, h, r * index, eligible});
      setFactor(w, r * index);
    } else {
      measured_.erase(worker);
      setFactor(w, NAN);
    }
  } else {
    measured_.erase(worker);
    setFactor(w, NAN);
    unmeasured_.set(worker, {h * index, 1 / index, h, 0, eligible});
  }
}

double AdaptiveReservoirStrategy::unmeasuredFactor() const {
  return factors_.empty() ? 0 : *factors_.begin();
}

void AdaptiveReservoirStrategy::setFactor(size_t w, double factor) {
  if (w >= factorOf_.size()) factorOf_.resize(w + 1, NAN);
  double& mine = factorOf_[w];
  if (mine == factor) return;
  if (!std::isnan(mine)) factors_.erase(factors_.find(mine));
  mine = factor;
  if (!std::isnan(factor)) factors_.insert(factor);
}

double AdaptiveReservoirStrategy::rateOf(int worker) const {
  if (measured_.contains(worker)) return measured_.entry(worker).a;
  if (unmeasured_.contains(worker)) return unmeasuredFactor() * unmeasured_.entry(worker).a;
  return 0;
}

double AdaptiveReservoirStrategy::finishSeconds(uint64_t remaining) const {
  // T solves g(T) = sum_i max(0, r_i T - h_i) - R = 0, g increasing; a worker takes part
  // exactly when its own finishing time is below T, i.e. when g(its time) < 0. The measured
  // take part in order of h_i / r_i, the unmeasured (rate K / index_i) of h_i index_i / K.
  const double k = unmeasuredFactor();
  const auto r = static_cast<double>(remaining);
  auto unmeasuredPart = [&](double t) {  // sum over the unmeasured at time t
    const FinishOrder::Sums s = unmeasured_.below(k * t);
    return k * t * s.a - s.b;
  };
  auto measuredPart = [&](double t) {
    const FinishOrder::Sums s = measured_.below(t);
    return t * s.a - s.b;
  };
  const FinishOrder::Sums m = measured_.prefixWhile([&](const FinishOrder::Sums& before, double t) {
    return t * before.a - before.b + unmeasuredPart(t) - r < 0;
  });
  const FinishOrder::Sums u = k > 0 ? unmeasured_.prefixWhile([&](const FinishOrder::Sums& before,
                                                                  double key) {
    const double t = key / k;
    return measuredPart(t) + key * before.a - before.b - r < 0;
  })
                                    : FinishOrder::Sums{};
  const double rateSum = m.a + k * u.a;
  return rateSum > 0 ? (r + m.b + u.b) / rateSum : 0;
}

uint64_t AdaptiveReservoirStrategy::handOutSize(int worker) {
  const double mine = rateOf(worker);
  if (mine <= 0) return minChunk_;  // results without times: fall back to small hand-outs
  const double t = finishSeconds(remaining());
  const double share = mine * t - static_cast<double>(throughput().held(worker));
  const double take = share * (1 - reservePercent_ / 100);
  return std::max(minChunk_, ceilCount(take));
}

std::optional<Transfer> AdaptiveReservoirStrategy::stealFor(int worker) {
  const double mine = rateOf(worker);
  if (mine <= 0) return std::nullopt;
  const double k = unmeasuredFactor();
  // The eligible worker expected to finish last (ties: the lowest-numbered), never the thief.
  int victim = -1;
  double latest = 0;
  auto consider = [&](int w, double finish) {
    if (w < 0 || w == worker) return;
    if (finish > latest || (finish == latest && victim >= 0 && w < victim)) {
      latest = finish;
      victim = w;
    }
  };
  int a = measured_.lastEligible();
  int b = unmeasured_.lastEligible();
  if (a == worker || b == worker) {  // the thief holds something itself: look past it
    FinishOrder& order = a == worker ? measured_ : unmeasured_;
    FinishOrder::Entry e = order.entry(worker);
    e.eligible = false;
    order.set(worker, e);
    (a == worker ? a : b) = order.lastEligible();
    e.eligible = true;
    order.set(worker, e);
  }
  if (a >= 0) consider(a, measured_.entry(a).key);
  if (b >= 0 && k > 0) consider(b, unmeasured_.entry(b).key / k);
  if (victim < 0) return std::nullopt;
  const double theirs = rateOf(victim);
  const double held = static_cast<double>(throughput().held(victim));
  // The thief's part of what everyone holds were it shared so that all finish together: the
  // other idle workers will take their parts from the same victim.
  const double rateSum = measured_.total().a + k * unmeasured_.total().a;
  const double fair = mine * static_cast<double>(heldSum_) / rateSum;
  const auto count = static_cast<uint64_t>(std::min(held * mine / (theirs + mine), fair));
  if (count < minChunk_) return std::nullopt;
  return Transfer{victim, worker, count};
}

}  // namespace prt
