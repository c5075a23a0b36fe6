#include "sim/synthetic_cost.h"

#include <span>
#include <utility>
#include <vector>

#include "core/check.h"

namespace prt {
namespace {

// A piecewise-linear profile: (position in [0, 1], relative cost) knots in increasing order,
// constant beyond the first and last.
struct Knot {
  double at;
  double value;
};

double profile(std::span<const Knot> knots, double x) {
  if (x <= knots.front().at) return knots.front().value;
  for (size_t i = 1; i < knots.size(); ++i) {
    if (x <= knots[i].at) {
      const Knot& a = knots[i - 1];
      const Knot& b = knots[i];
      return a.value + (b.value - a.value) * (x - a.at) / (b.at - a.at);
    }
  }
  return knots.back().value;
}

// The shape of scenes/complex.scene, fitted to a map recorded at 640x480, case A (prt render
// scenes/complex.scene --case A --threads 1 --cost-map FILE), with u = x / width and
// v = y / height (top = 0):
//  - a background that depends on the row: open sky above the horizon (v < 0.21) costs one
//    ray a pixel; the floor below costs 4 to 10 times more, most just under the cluster where
//    it sees its reflections and the lights' soft shadows;
//  - the cluster of glass and mirror spheres on the mirror pedestal, a separable bump of
//    column and row profiles to the right of centre (u 0.37..0.9, v 0.25..0.68) holding 80 %
//    of the image's cost on under a quarter of its pixels, the hottest ones about 450 times
//    the sky's.
// Pixel-level detail (sphere edges, glass against mirror) is smoothed away; batches of many
// pixels see the same totals.
constexpr Knot kBackgroundByRow[] = {{0.0, 0.3}, {0.205, 0.3}, {0.215, 1.3}, {0.45, 2.7},
                                     {0.6, 3.2}, {0.7, 2.3},   {1.0, 2.2}};
constexpr Knot kClusterByColumn[] = {{0.37, 0.0},  {0.39, 0.24}, {0.42, 0.63},  {0.45, 0.84},
                                     {0.52, 0.87}, {0.55, 0.58}, {0.58, 0.38},  {0.61, 0.5},
                                     {0.64, 0.93}, {0.70, 1.0},  {0.735, 0.55}, {0.765, 0.3},
                                     {0.83, 0.31}, {0.86, 0.44}, {0.885, 0.09}, {0.9, 0.0}};
constexpr Knot kClusterByRow[] = {{0.25, 0.0},  {0.33, 0.1},  {0.36, 0.23}, {0.39, 0.39},
                                  {0.42, 0.63}, {0.48, 1.0},  {0.52, 1.0},  {0.578, 0.76},
                                  {0.60, 0.2},  {0.64, 0.04}, {0.68, 0.0}};
constexpr double kClusterShare = 0.80;  // of the total cost

std::vector<double> sampled(std::span<const Knot> knots, int n) {
  std::vector<double> out(static_cast<size_t>(n));
  for (int i = 0; i < n; ++i) out[static_cast<size_t>(i)] = profile(knots, (i + 0.5) / n);
  return out;
}

double sum(const std::vector<double>& values) {
  double s = 0;
  for (double v : values) s += v;
  return s;
}

}  // namespace

CostMap uniformCostMap(int width, int height, double totalSeconds) {
  PRT_CHECK(width >= 1 && height >= 1 && totalSeconds > 0);
  const uint64_t pixels = static_cast<uint64_t>(width) * static_cast<uint64_t>(height);
  const auto each = static_cast<float>(totalSeconds / static_cast<double>(pixels));
  return CostMap(width, height, std::vector<float>(pixels, each));
}

CostMap complexSceneCostMap(int width, int height, double totalSeconds) {
  PRT_CHECK(width >= 1 && height >= 1 && totalSeconds > 0);
  const std::vector<double> background = sampled(kBackgroundByRow, height);
  const std::vector<double> columns = sampled(kClusterByColumn, width);
  const std::vector<double> rows = sampled(kClusterByRow, height);
  // Weights that give the background and the cluster their shares of the total.
  const double backgroundWeight = (1 - kClusterShare) * totalSeconds / (sum(background) * width);
  const double clusterWeight = kClusterShare * totalSeconds / (sum(columns) * sum(rows));
  std::vector<float> seconds(static_cast<size_t>(width) * static_cast<size_t>(height));
  for (int y = 0; y < height; ++y) {
    const double b = backgroundWeight * background[static_cast<size_t>(y)];
    const double r = clusterWeight * rows[static_cast<size_t>(y)];
    float* row = seconds.data() + static_cast<size_t>(y) * static_cast<size_t>(width);
    for (int x = 0; x < width; ++x) {
      row[x] = static_cast<float>(b + r * columns[static_cast<size_t>(x)]);
    }
  }
  return CostMap(width, height, std::move(seconds));
}

}  // namespace prt
