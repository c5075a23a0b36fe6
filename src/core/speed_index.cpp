#include "core/speed_index.h"

#include <algorithm>
#include <chrono>
#include <vector>

namespace prt {
namespace {

// Pegs are 0, 1, 2; the checksum folds in every move so the recursion must really run.
void moveTower(int n, int from, int to, int via, uint64_t& checksum) {
  if (n == 0) return;
  moveTower(n - 1, from, via, to, checksum);
  checksum = checksum * 31 + static_cast<uint64_t>(n * 9 + from * 3 + to);
  moveTower(n - 1, via, to, from, checksum);
}

}  // namespace

uint64_t solveHanoi(int discs) {
  uint64_t checksum = 0;
  moveTower(discs, 0, 2, 1, checksum);
  return checksum;
}

double measureSpeedIndexSeconds(int discs, int repeats) {
  std::vector<double> times;
  volatile uint64_t sink = 0;
  for (int i = 0; i < std::max(1, repeats); ++i) {
    const auto start = std::chrono::steady_clock::now();
    sink = sink + solveHanoi(discs);
    const auto end = std::chrono::steady_clock::now();
    times.push_back(std::chrono::duration<double>(end - start).count());
  }
  std::sort(times.begin(), times.end());
  return times[times.size() / 2];
}

}  // namespace prt
