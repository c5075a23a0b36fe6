#include "sim/cost_map.h"

#include <cmath>
#include <utility>

#include "core/check.h"

namespace prt {

CostMap::CostMap(int width, int height, std::vector<float> secondsPerPixel)
    : width_(width), height_(height), seconds_(std::move(secondsPerPixel)) {
  PRT_CHECK(width >= 1 && height >= 1);
  PRT_CHECK(seconds_.size() == static_cast<uint64_t>(width) * static_cast<uint64_t>(height));
  prefix_.resize(seconds_.size() + 1);
  prefix_[0] = 0;
  for (size_t i = 0; i < seconds_.size(); ++i) {
    PRT_CHECK(std::isfinite(seconds_[i]) && seconds_[i] >= 0);
    prefix_[i + 1] = prefix_[i] + seconds_[i];
  }
}

double CostMap::seconds(const TaskRun& run) const {
  if (run.count == 0) return 0;
  PRT_CHECK(run.last() < pixelCount());
  if (run.stride == 1 || run.count == 1) return prefix_[run.first + run.count] - prefix_[run.first];
  double sum = 0;
  for (uint64_t p = run.first, i = 0; i < run.count; ++i, p += run.stride) sum += seconds_[p];
  return sum;
}

double CostMap::seconds(const TaskSet& tasks) const {
  double sum = 0;
  for (const TaskRun& run : tasks.runs()) sum += seconds(run);
  return sum;
}

CostMap CostMap::scaledTo(double totalSeconds) const {
  PRT_CHECK(totalSeconds > 0 && this->totalSeconds() > 0);
  const double factor = totalSeconds / this->totalSeconds();
  std::vector<float> scaled(seconds_.size());
  for (size_t i = 0; i < seconds_.size(); ++i) {
    scaled[i] = static_cast<float>(seconds_[i] * factor);
  }
  return CostMap(width_, height_, std::move(scaled));
}

}  // namespace prt
