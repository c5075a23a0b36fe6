// The end-game index against a walk of every worker: random hand-outs, work done behind its
// back (as copies rendered by others are), eligibility, weights and askers.

#include "cluster/endgame_order.h"

#include <gtest/gtest.h>

#include <random>
#include <vector>

namespace prt {
namespace {

// The walk Master::endgameCopy made before the index: the largest positive count x weight,
// ties to the lowest-numbered, the asker and the ineligible left out.
int walk(const std::vector<uint64_t>& counts, const std::vector<double>& weights,
         const std::vector<bool>& eligible, int asker) {
  int best = -1;
  double latest = 0;
  for (size_t v = 0; v < counts.size(); ++v) {
    if (static_cast<int>(v) == asker || !eligible[v]) continue;
    const double finish = static_cast<double>(counts[v]) * (weights[v] > 0 ? weights[v] : 1.0);
    if (counts[v] > 0 && finish > latest) {
      latest = finish;
      best = static_cast<int>(v);
    }
  }
  return best;
}

TEST(EndgameOrderTest, PicksAsAWalkOfEveryWorkerWould) {
  std::mt19937_64 random(11);
  for (int round = 0; round < 20; ++round) {
    EndgameOrder order;
    const int n = 1 + static_cast<int>(random() % 40);
    std::vector<uint64_t> counts(static_cast<size_t>(n), 0);
    std::vector<double> weights(static_cast<size_t>(n), 0.0);
    std::vector<bool> eligible(static_cast<size_t>(n), true);
    order.grow(n);
    for (int w = 0; w < n; ++w) order.setEligible(w, true);
    const auto exact = [&](int w) { return counts[static_cast<size_t>(w)]; };
    for (int step = 0; step < 2000; ++step) {
      const int w = static_cast<int>(random() % static_cast<uint64_t>(counts.size()));
      const auto i = static_cast<size_t>(w);
      switch (random() % 8) {
        case 0:
        case 1: {  // a hand-out
          const uint64_t k = random() % 20;
          counts[i] += k;
          order.gave(w, k);
          break;
        }
        case 2:
        case 3:  // done, by itself or by a copy: the index is not told
          counts[i] -= std::min<uint64_t>(counts[i], random() % 10);
          break;
        case 4:
          eligible[i] = !eligible[i];
          order.setEligible(w, eligible[i]);
          break;
        case 5:  // speed indices, equal ones included (ties), and none
          weights[i] = static_cast<double>(random() % 4) * 0.25;
          order.setWeight(w, weights[i]);
          break;
        case 6:  // a joiner
          counts.push_back(0);
          weights.push_back(0);
          eligible.push_back(true);
          order.setEligible(static_cast<int>(counts.size()) - 1, true);
          break;
        default: {
          const int asker = static_cast<int>(random() % static_cast<uint64_t>(counts.size()));
          ASSERT_EQ(order.pick(asker, exact), walk(counts, weights, eligible, asker))
              << "round " << round << " step " << step;
        }
      }
    }
  }
}

TEST(EndgameOrderTest, CountsThatGrowBackAreFoundAfterInvalidation) {
  EndgameOrder order;
  order.grow(3);
  for (int w = 0; w < 3; ++w) order.setEligible(w, true);
  std::vector<uint64_t> counts{5, 3, 0};
  order.gave(0, 5);
  order.gave(1, 3);
  const auto exact = [&](int w) { return counts[static_cast<size_t>(w)]; };
  EXPECT_EQ(order.pick(-1, exact), 0);
  counts[0] = 0;  // done by a copy
  EXPECT_EQ(order.pick(-1, exact), 1);
  counts[2] = 9;  // pixels taken back from a rejected worker, held by worker 2 as copies
  order.invalidate();
  EXPECT_EQ(order.pick(-1, exact), 2);
  EXPECT_EQ(order.pick(2, exact), 1) << "never the asker";
}

}  // namespace
}  // namespace prt
