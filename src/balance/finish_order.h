#pragma once
// FinishOrder: workers kept in order of a key (for the adaptive reservoir, the time at which a
// worker would finish what it holds), with sums over any prefix of that order, so that the
// questions a hand-out asks of all workers — "at which common time T would the pool and every
// queue be done?", "who finishes last?" — are answered in O(log W) instead of a walk over all
// W workers. A treap (a binary search tree balanced by pseudo-random priorities, here a hash
// of the worker, so every run builds the same tree) whose nodes carry their subtree's sums.
//
// Each entry: a key, three summed values a, b, c (what they mean is the user's: rate, held,
// rate x speed index), and whether it is eligible (as a victim of a steal). Entries are
// ordered by key, ties by worker in DESCENDING order, so that among equal keys the last entry
// is the lowest-numbered worker. Sums are recomputed from the children at every change, so
// they never drift however many updates there are. Not thread-safe.

#include <cstddef>
#include <cstdint>
#include <vector>

namespace prt {

class FinishOrder {
 public:
  struct Entry {
    double key = 0;
    double a = 0, b = 0, c = 0;
    bool eligible = true;
  };
  struct Sums {
    double a = 0, b = 0, c = 0;
    int count = 0;
    Sums& operator+=(const Sums& o) {
      a += o.a;
      b += o.b;
      c += o.c;
      count += o.count;
      return *this;
    }
  };

  // Inserts or replaces worker's entry; workers are 0 .. any, slots grow as needed.
  void set(int worker, const Entry& entry);
  void erase(int worker);  // no-op when absent
  bool contains(int worker) const;
  const Entry& entry(int worker) const;  // contains(worker) must hold

  Sums total() const;
  // Sums over the entries with key < `key`.
  Sums below(double key) const;
  // The longest prefix of the order whose entries all pass `pass(sumsBefore, key)`, where
  // sumsBefore sums the entries before that one; `pass` must be true up to some entry and
  // false from there on. Returns the prefix's sums.
  template <typename Pass>
  Sums prefixWhile(Pass&& pass) const;
  // The eligible entry last in the order (largest key; among equal keys the lowest worker),
  // or -1 when none is eligible.
  int lastEligible() const;

 private:
  struct Node {
    Entry entry;
    Sums sums;  // of its subtree
    int eligibleCount = 0;
    int left = -1, right = -1;
    uint32_t priority = 0;
    bool present = false;
  };
  bool before(int x, int y) const;  // x's entry precedes y's
  void update(int x);
  // Splits t into the entries before `pivot`'s position (exclusive) and the rest.
  void split(int t, int pivot, int& left, int& right);
  int merge(int left, int right);

  std::vector<Node> nodes_;
  int root_ = -1;
  std::vector<int> path_;  // erase()'s way down, kept to spare an allocation per change
};

template <typename Pass>
FinishOrder::Sums FinishOrder::prefixWhile(Pass&& pass) const {
  Sums taken;
  int x = root_;
  while (x >= 0) {
    const Node& n = nodes_[static_cast<size_t>(x)];
    Sums before = taken;
    if (n.left >= 0) before += nodes_[static_cast<size_t>(n.left)].sums;
    if (pass(static_cast<const Sums&>(before), n.entry.key)) {
      taken = before;
      taken += Sums{n.entry.a, n.entry.b, n.entry.c, 1};
      x = n.right;
    } else {
      x = n.left;
    }
  }
  return taken;
}

}  // namespace prt
