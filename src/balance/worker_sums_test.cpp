#include "balance/worker_sums.h"

#include <gtest/gtest.h>

#include <random>
#include <vector>

namespace prt {
namespace {

TEST(WorkerSumsTest, TheTotalIsTheSumOfTheValuesAsTheyChangeAndGrow) {
  WorkerSums sums;
  EXPECT_EQ(sums.total(), 0);
  std::vector<double> values;
  std::mt19937_64 random(5);
  for (int step = 0; step < 3000; ++step) {
    const auto w = static_cast<size_t>(random() % (1 + static_cast<uint64_t>(step) / 10));
    if (w >= values.size()) values.resize(w + 1, 0);
    values[w] = static_cast<double>(random() % 1000);  // integers: exact in any order
    sums.set(static_cast<int>(w), values[w]);
    double total = 0;
    for (double v : values) total += v;
    ASSERT_EQ(sums.total(), total) << "step " << step;
  }
  sums.clear();
  EXPECT_EQ(sums.total(), 0);
}

}  // namespace
}  // namespace prt
