#include "balance/finish_order.h"

#include "core/check.h"

namespace prt {
namespace {

// A fixed hash of the worker: the same tree in every run, and expected depth O(log W).
uint32_t priorityOf(int worker) {
  uint64_t z = static_cast<uint64_t>(worker) + 0x9e3779b97f4a7c15ull;
  z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ull;
  z = (z ^ (z >> 27)) * 0x94d049bb133111ebull;
  return static_cast<uint32_t>((z ^ (z >> 31)) >> 32);
}

}  // namespace

bool FinishOrder::before(int x, int y) const {
  const double kx = nodes_[static_cast<size_t>(x)].entry.key;
  const double ky = nodes_[static_cast<size_t>(y)].entry.key;
  return kx < ky || (kx == ky && x > y);
}

void FinishOrder::update(int x) {
  Node& n = nodes_[static_cast<size_t>(x)];
  n.sums = Sums{n.entry.a, n.entry.b, n.entry.c, 1};
  n.eligibleCount = n.entry.eligible ? 1 : 0;
  for (int child : {n.left, n.right}) {
    if (child < 0) continue;
    const Node& c = nodes_[static_cast<size_t>(child)];
    n.sums += c.sums;
    n.eligibleCount += c.eligibleCount;
  }
}

void FinishOrder::split(int t, int pivot, int& left, int& right) {
  if (t < 0) {
    left = right = -1;
    return;
  }
  Node& n = nodes_[static_cast<size_t>(t)];
  if (before(t, pivot)) {
    split(n.right, pivot, nodes_[static_cast<size_t>(t)].right, right);
    left = t;
  } else {
    split(n.left, pivot, left, nodes_[static_cast<size_t>(t)].left);
    right = t;
  }
  update(t);
}

int FinishOrder::merge(int left, int right) {
  if (left < 0) return right;
  if (right < 0) return left;
  Node& l = nodes_[static_cast<size_t>(left)];
  Node& r = nodes_[static_cast<size_t>(right)];
  if (l.priority > r.priority) {
    l.right = merge(l.right, right);
    update(left);
    return left;
  }
  r.left = merge(left, r.left);
  update(right);
  return right;
}

bool FinishOrder::contains(int worker) const {
  return worker >= 0 && static_cast<size_t>(worker) < nodes_.size() &&
         nodes_[static_cast<size_t>(worker)].present;
}

const FinishOrder::Entry& FinishOrder::entry(int worker) const {
  PRT_CHECK(contains(worker));
  return nodes_[static_cast<size_t>(worker)].entry;
}

void FinishOrder::set(int worker, const Entry& entry) {
  PRT_CHECK(worker >= 0);
  if (contains(worker)) {
    Node& old = nodes_[static_cast<size_t>(worker)];
    if (old.entry.key == entry.key && old.entry.a == entry.a && old.entry.b == entry.b &&
        old.entry.c == entry.c && old.entry.eligible == entry.eligible) {
      return;  // nothing changed
    }
  }
  erase(worker);
  if (static_cast<size_t>(worker) >= nodes_.size()) nodes_.resize(static_cast<size_t>(worker) + 1);
  Node& n = nodes_[static_cast<size_t>(worker)];
  n = Node{};
  n.entry = entry;
  n.priority = priorityOf(worker);
  n.present = true;
  update(worker);
  int left = -1;
  int right = -1;
  split(root_, worker, left, right);
  root_ = merge(merge(left, worker), right);
}

void FinishOrder::erase(int worker) {
  if (!contains(worker)) return;
  // Find the link that points at the node, then put its children's merge in its place.
  std::vector<int>& path = path_;
  path.clear();
  int x = root_;
  while (x != worker) {
    PRT_CHECK(x >= 0);
    path.push_back(x);
    x = before(worker, x) ? nodes_[static_cast<size_t>(x)].left
                          : nodes_[static_cast<size_t>(x)].right;
  }
  Node& n = nodes_[static_cast<size_t>(worker)];
  const int replacement = merge(n.left, n.right);
  n.present = false;
  n.left = n.right = -1;
  if (path.empty()) {
    root_ = replacement;
    return;
  }
  Node& parent = nodes_[static_cast<size_t>(path.back())];
  (parent.left == worker ? parent.left : parent.right) = replacement;
  for (auto it = path.rbegin(); it != path.rend(); ++it) update(*it);
}

FinishOrder::Sums FinishOrder::total() const {
  return root_ < 0 ? Sums{} : nodes_[static_cast<size_t>(root_)].sums;
}

FinishOrder::Sums FinishOrder::below(double key) const {
  Sums out;
  int x = root_;
  while (x >= 0) {
    const Node& n = nodes_[static_cast<size_t>(x)];
    if (n.entry.key < key) {
      if (n.left >= 0) out += nodes_[static_cast<size_t>(n.left)].sums;
      out += Sums{n.entry.a, n.entry.b, n.entry.c, 1};
      x = n.right;
    } else {
      x = n.left;
    }
  }
  return out;
}

int FinishOrder::lastEligible() const {
  int x = root_;
  while (x >= 0) {
    const Node& n = nodes_[static_cast<size_t>(x)];
    if (n.eligibleCount == 0) return -1;
    if (n.right >= 0 && nodes_[static_cast<size_t>(n.right)].eligibleCount > 0) {
      x = n.right;
    } else if (n.entry.eligible) {
      return x;
    } else {
      x = n.left;
    }
  }
  return -1;
}

}  // namespace prt
