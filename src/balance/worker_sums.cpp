#include "balance/worker_sums.h"

#include <utility>

#include "core/check.h"

namespace prt {

void WorkerSums::set(int worker, double value) {
  PRT_CHECK(worker >= 0);
  const auto w = static_cast<size_t>(worker);
  if (w >= leaves_) {  // grow to the next power of two, keeping the values
    size_t leaves = leaves_ == 0 ? 1 : leaves_;
    while (leaves <= w) leaves *= 2;
    std::vector<double> tree(2 * leaves, 0.0);
    for (size_t i = 0; i < leaves_; ++i) tree[leaves + i] = tree_[leaves_ + i];
    for (size_t i = leaves - 1; i >= 1; --i) tree[i] = tree[2 * i] + tree[2 * i + 1];
    tree_ = std::move(tree);
    leaves_ = leaves;
  }
  size_t i = leaves_ + w;
  tree_[i] = value;
  for (i /= 2; i >= 1; i /= 2) tree_[i] = tree_[2 * i] + tree_[2 * i + 1];
}

}  // namespace prt
