#pragma once
// WorkerSums: one value per worker and their total, kept in a binary tree of partial sums so
// that changing a value costs O(log W) and the total never drifts (each sum is recomputed
// from its two halves, not adjusted by differences). Slots grow as workers join. Plain value;
// not thread-safe.

#include <cstddef>
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

}  // namespace prt
