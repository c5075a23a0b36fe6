#pragma once
// CostMap: what each pixel costs to render, in seconds on a full-speed worker (speed 1), for
// the simulator to replay without rendering. Pixels are indexed y * width + x (scan-line
// order, top row first), as tasks are.
//
// Range queries are what the simulator asks for, once per rendered batch: a prefix sum over
// the scan-line order (in double, so 8.3 M float costs add up without drift) makes a
// contiguous run O(1); a strided run (scatter: stride = worker count) is summed in
// O(count). Every pixel is rendered exactly once, so the strided sums of a whole simulation
// add up to one pass over the map, whatever the stride; a per-stride prefix table would cost
// a map-sized array per stride for no gain in total work.
// Immutable after construction; safe to share between threads.

#include <cstdint>
#include <vector>

#include "core/task_set.h"

namespace prt {

class CostMap {
 public:
  // `secondsPerPixel`: width * height values, each finite and >= 0 (a CHECK; files are
  // validated with InputError when read, see cost_map_file.h).
  CostMap(int width, int height, std::vector<float> secondsPerPixel);

  int width() const { return width_; }
  int height() const { return height_; }
  uint64_t pixelCount() const { return seconds_.size(); }
  const std::vector<float>& secondsPerPixel() const { return seconds_; }
  double pixelSeconds(uint64_t pixel) const { return seconds_[pixel]; }
  double totalSeconds() const { return prefix_.back(); }

  // Seconds to render the tasks at full speed. Every task must be < pixelCount() (a CHECK).
  double seconds(const TaskRun& run) const;
  double seconds(const TaskSet& tasks) const;

  // The same shape, every pixel scaled so the total is `totalSeconds` (> 0). The map's own
  // total must be positive.
  CostMap scaledTo(double totalSeconds) const;

 private:
  int width_;
  int height_;
  std::vector<float> seconds_;
  std::vector<double> prefix_;  // prefix_[i] = sum of the first i pixels; size pixelCount + 1
};

}  // namespace prt
