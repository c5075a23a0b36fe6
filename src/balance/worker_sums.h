#pragma once
// Per-worker values indexed so that a decision needs no walk over the workers:
//  - WorkerSums: one value per worker and their total, kept in a binary tree of partial sums
//    so that changing a value costs O(log W) and the total never drifts (each sum is
//    recomputed from its two halves, not adjusted by differences);
//  - WorkerMinimum: the workers that have a (positive) value, and the one of least value
//    (ties: the lowest-numbered), O(log W) per change.
// Slots grow as workers join. Plain values; not thread-safe.

#include <cstddef>
#include <set>
#include <utility>
#include <vector>

namespace prt {

class WorkerSums {
 public:
  void clear() { tree_.clear(); leaves_ = 0; }
  void set(int worker, double value);
  double total() const { return tree_.empty() ? 0 : tree_[1]; }

 private:
  std::vector<double> tree_;  // tree_[1] the root; leaves at leaves_ .. 2 leaves_ - 1
  size_t leaves_ = 0;
};

class WorkerMinimum {
 public:
  void clear() { ordered_.clear(); values_.clear(); }
  // value > 0 enters the worker with it; anything else takes it out.
  void set(int worker, double value) {
    const auto w = static_cast<size_t>(worker);
    if (w >= values_.size()) values_.resize(w + 1, 0);
    if (values_[w] > 0) ordered_.erase({values_[w], worker});
    values_[w] = value > 0 ? value : 0;
    if (value > 0) ordered_.emplace(value, worker);
  }
  bool empty() const { return ordered_.empty(); }
  size_t count() const { return ordered_.size(); }
  int least() const { return ordered_.begin()->second; }  // !empty()
  double leastValue() const { return ordered_.begin()->first; }

 private:
  std::set<std::pair<double, int>> ordered_;
  std::vector<double> values_;  // each worker's value as entered (0: not there)
};

}  // namespace prt
