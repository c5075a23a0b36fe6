#pragma once
// EndgameOrder: the master's index of the workers by when they are expected to finish, for
// end-game copies (Master::endgameCopy): the eligible worker with the most unfinished tasks
// times its speed index (ties: the lowest-numbered), found without walking every worker.
//
// What a worker has unfinished shrinks also when another worker renders a copy of its tasks,
// which the master does not see per worker. So each worker is kept under an upper bound of its
// unfinished count: it grows by what it is given, and is set to the exact count whenever it
// comes to the top. A pick takes the largest bound, asks for the exact count and corrects it,
// and repeats until the largest bound is exact: that worker's key is then at least every other
// worker's bound, hence their exact keys, so the pick is the one a walk of every worker would
// make. Each correction lowers a bound to what is still owed, so the corrections over a run are
// paid for by the tasks handed out and finished.
// Not thread-safe: one master owns it.

#include <cstdint>
#include <functional>
#include <set>
#include <utility>
#include <vector>

namespace prt {

class EndgameOrder {
 public:
  // Workers are numbered 0..n-1; new ones join at the end, ineligible and holding nothing.
  void grow(int workers);
  // `worker` may be picked (live, its tail not copied yet) or not.
  void setEligible(int worker, bool eligible);
  // The factor its count is weighed by (its speed index; 1 when it has none).
  void setWeight(int worker, double weight);
  void gave(int worker, uint64_t tasks);  // the bound grows
  // Every bound may be low (tasks became undone again, as when a worker's pixels are taken
  // back): the next pick recomputes them all.
  void invalidate() { stale_ = true; }

  // The eligible worker other than `asker` whose exact unfinished count (`unfinished(w)`)
  // times its weight is largest and positive, ties to the lowest-numbered; -1 if none.
  int pick(int asker, const std::function<uint64_t(int)>& unfinished);

 private:
  double key(size_t w) const { return static_cast<double>(bound_[w]) * weight_[w]; }
  void reindex(int worker);

  std::vector<uint64_t> bound_;    // per worker: at least its unfinished count
  std::vector<double> weight_;
  std::vector<bool> eligible_;
  std::vector<double> indexed_;    // per worker: its key in order_ (< 0: not in it)
  // (-key, worker): the largest key first, ties to the lowest-numbered.
  std::set<std::pair<double, int>> order_;
  bool stale_ = false;
};

}  // namespace prt
