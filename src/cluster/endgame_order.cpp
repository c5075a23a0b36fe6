#include "cluster/endgame_order.h"

namespace prt {

void EndgameOrder::grow(int workers) {
  const auto n = static_cast<size_t>(workers);
  if (n <= bound_.size()) return;
  bound_.resize(n, 0);
  weight_.resize(n, 1.0);
  eligible_.resize(n, false);
  indexed_.resize(n, -1.0);
}

void EndgameOrder::reindex(int worker) {
  const auto w = static_cast<size_t>(worker);
  if (indexed_[w] >= 0) order_.erase({-indexed_[w], worker});
  indexed_[w] = -1.0;
  const double k = key(w);
  if (eligible_[w] && k > 0) {
    order_.emplace(-k, worker);
    indexed_[w] = k;
  }
}

void EndgameOrder::setEligible(int worker, bool eligible) {
  grow(worker + 1);
  if (eligible_[static_cast<size_t>(worker)] == eligible) return;
  eligible_[static_cast<size_t>(worker)] = eligible;
  reindex(worker);
}

void EndgameOrder::setWeight(int worker, double weight) {
  grow(worker + 1);
  weight_[static_cast<size_t>(worker)] = weight > 0 ? weight : 1.0;
  reindex(worker);
}

void EndgameOrder::gave(int worker, uint64_t tasks) {
  grow(worker + 1);
  bound_[static_cast<size_t>(worker)] += tasks;
  reindex(worker);
}

int EndgameOrder::pick(int asker, const std::function<uint64_t(int)>& unfinished) {
  if (stale_) {
    stale_ = false;
    for (size_t w = 0; w < bound_.size(); ++w) {
      bound_[w] = unfinished(static_cast<int>(w));
      reindex(static_cast<int>(w));
    }
  }
  std::vector<int> skipped;  // the asker, put back after the pick
  int chosen = -1;
  while (!order_.empty()) {
    const int w = order_.begin()->second;
    const auto i = static_cast<size_t>(w);
    const uint64_t exact = unfinished(w);
    // A bound below the count (nothing known makes one) is corrected like any other.
    if (exact != bound_[i]) {
      bound_[i] = exact;
      reindex(w);
      continue;
    }
    if (w == asker) {
      order_.erase(order_.begin());
      indexed_[i] = -1.0;
      skipped.push_back(w);
      continue;
    }
    chosen = w;
    break;
  }
  for (int w : skipped) reindex(w);
  return chosen;
}

}  // namespace prt
