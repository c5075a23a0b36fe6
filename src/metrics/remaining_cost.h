#pragma once
// RemainingCost: how much of a render's work is left, and when it will be done, from the
// measured cost of the pixels finished so far, region by region. The pixel count alone is a
// poor guide: a sky renders many times faster than the glass below it, so a render that
// goes top to bottom is a quarter done in pixels long before it is a quarter done in time.
//
// The image (each frame of a sequence) is cut into a grid of cells. Every measured batch
// spreads its seconds evenly over its pixels and adds them to their cells. A pixel still to
// render is expected to cost the mean of the measured pixels of its cell, shrunk towards the
// same cell in the other frames (or the fallback below) by the weight of kShrinkPixels
// pixels; of the same cell in the other frames when its own has none yet; of every measured
// pixel, scaled by the cell's prior (setPrior) when there is one, when none of those has any. The remaining work is the sum of those expectations, in the same seconds the
// batches were measured in, and the time left is that work over the rate at which measured
// seconds came in over the recent past (a window of a quarter of the elapsed time, between 2
// and 30 s), so workers that join or are lost move the estimate within that window.
//
// Units: a batch's seconds are the wall time its worker spent on it, so the rate counts busy
// workers (a slow worker's pixels cost more seconds, and it delivers fewer per second). The
// estimate is exact when the cost per pixel of each cell is uniform and the mix of workers
// stays the same. Pure: no clock (times come in), no threads; not thread-safe.

#include <cstdint>
#include <deque>
#include <optional>
#include <utility>
#include <vector>

#include "core/task_set.h"

namespace prt {

class RemainingCost {
 public:
  // Tasks are pixel indices: task t is pixel t % (width * height) of frame t / (width * height).
  RemainingCost(int width, int height, uint64_t frames = 1);

  // `seconds` of measured work rendered `tasks` (duplicates of done pixels included: their
  // cost was real). Arrived at `now`, on any clock that only moves forward.
  void measured(const TaskSet& tasks, double seconds, double now);
  // Pixels finished for the first time (each exactly once), measured or not (a checkpoint's).
  void finished(const TaskSet& tasks);
  // Finished pixels that are to be rendered again (taken back from a rejected worker).
  void unfinished(const TaskSet& tasks);

  // The grid of cells of a frame, for a prior (setPrior).
  int cellsX() const { return cellsX_; }
  int cellsY() const { return cellsY_; }
  // The first pixel (x, y) of cell (cx, cy) and its size; a cell past the image is empty.
  int cellWidth() const { return cellW_; }
  int cellHeight() const { return cellH_; }
  // Relative costs of the cells of a frame (cellsY() x cellsX(), row-major; > 0), from a
  // sample rendered before the run: a cell nobody has measured yet is expected to cost the
  // measured mean scaled by its prior over the measured pixels' mean prior, not the plain
  // mean. Without one, every cell's prior is the same.
  void setPrior(std::vector<double> perCell);

  uint64_t taskCount() const { return taskCount_; }
  uint64_t finishedCount() const { return finished_; }
  // Expected seconds of work still to do; nothing before the first measurement.
  std::optional<double> remainingWork() const;
  // Expected seconds until the last pixel is in, at `now`; nothing before a second of
  // measurements. 0 once every pixel is finished.
  std::optional<double> etaSeconds(double now) const;
  // Of the whole render's expected work, the part done (0..1); nothing before a measurement.
  std::optional<double> doneFraction() const;

 private:
  struct Cell {
    double seconds = 0;    // measured
    uint64_t samples = 0;  // measured pixels
    uint64_t pixels = 0;   // in the cell
    uint64_t finished = 0;
  };
  size_t cellOf(uint64_t task) const;
  template <typename F>
  void forEachCellSpan(const TaskSet& tasks, F&& f) const;
  double rate(double now) const;
  double unmeasured(size_t frameCell, double overall) const;
  static double cellMean(const Cell& cell, const Cell& across, double fallback);

  int width_, height_;
  uint64_t frames_, perFrame_, taskCount_;
  int cellsX_, cellsY_;
  int cellW_, cellH_;
  std::vector<Cell> cells_;        // frames_ x cellsY_ x cellsX_
  std::vector<Cell> acrossFrames_; // cellsY_ x cellsX_: the same cell over every frame
  double measuredSeconds_ = 0;
  uint64_t measuredSamples_ = 0;
  uint64_t finished_ = 0;
  std::deque<std::pair<double, double>> history_;  // (time, measured seconds so far)
  std::vector<double> prior_;      // per frame cell, or empty
  double measuredPrior_ = 0;       // sum of the prior over the measured pixels
};

}  // namespace prt
