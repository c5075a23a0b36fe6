// FinishOrder against a plain list of the same entries, over random inserts, updates and
// removals.

#include <gtest/gtest.h>

#include <algorithm>
#include <map>
#include <random>

#include "balance/finish_order.h"

namespace prt {
namespace {

struct Plain {
  std::map<int, FinishOrder::Entry> entries;
  // In the order's order: key ascending, ties by worker descending.
  std::vector<std::pair<int, FinishOrder::Entry>> sorted() const {
    std::vector<std::pair<int, FinishOrder::Entry>> out(entries.begin(), entries.end());
    std::sort(out.begin(), out.end(), [](const auto& x, const auto& y) {
      return x.second.key < y.second.key || (x.second.key == y.second.key && x.first > y.first);
    });
    return out;
  }
};

TEST(FinishOrderTest, AgreesWithAPlainListOverRandomChanges) {
  std::mt19937_64 random(7);
  FinishOrder order;
  Plain plain;
  for (int step = 0; step < 4000; ++step) {
    const int worker = static_cast<int>(random() % 64);
    if (random() % 4 == 0) {
      order.erase(worker);
      plain.entries.erase(worker);
    } else {
      // Few distinct keys, so that ties are common.
      const FinishOrder::Entry e{static_cast<double>(random() % 16),
                                 static_cast<double>(random() % 100), static_cast<double>(random() % 7),
                                 static_cast<double>(random() % 3), random() % 3 != 0};
      order.set(worker, e);
      plain.entries[worker] = e;
    }
    const auto sorted = plain.sorted();
    const FinishOrder::Sums total = order.total();
    ASSERT_EQ(total.count, static_cast<int>(sorted.size()));
    double a = 0;
    for (const auto& [w, e] : sorted) a += e.a;
    EXPECT_EQ(total.a, a);  // integers: exact in any order
    // below(): entries of key < k.
    const double k = static_cast<double>(random() % 17);
    double b = 0;
    int count = 0;
    for (const auto& [w, e] : sorted) {
      if (e.key < k) {
        b += e.b;
        ++count;
      }
    }
    const FinishOrder::Sums below = order.below(k);
    EXPECT_EQ(below.b, b);
    EXPECT_EQ(below.count, count);
    // prefixWhile(): the longest prefix whose running sum of a before each entry stays below
    // a limit (true, then false: monotone).
    const double limit = static_cast<double>(random() % 2000);
    int prefix = 0;
    double running = 0;
    for (const auto& [w, e] : sorted) {
      if (!(running < limit)) break;
      running += e.a;
      ++prefix;
    }
    const FinishOrder::Sums taken =
        order.prefixWhile([&](const FinishOrder::Sums& before, double) { return before.a < limit; });
    EXPECT_EQ(taken.count, prefix);
    // lastEligible(): the last eligible entry in the order.
    int last = -1;
    for (const auto& [w, e] : sorted) {
      if (e.eligible) last = w;
    }
    EXPECT_EQ(order.lastEligible(), last);
    for (const auto& [w, e] : plain.entries) {
      ASSERT_TRUE(order.contains(w));
      EXPECT_EQ(order.entry(w).key, e.key);
    }
  }
}

}  // namespace
}  // namespace prt
