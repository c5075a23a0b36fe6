#include "metrics/remaining_cost.h"

#include <algorithm>
#include <cmath>

#include "core/check.h"

namespace prt {
namespace {
constexpr int kCellsAcross = 16;  // per side of a frame
constexpr double kMinWindow = 2, kMaxWindow = 30, kWindowShare = 0.25;
constexpr double kShrinkPixels = 64;
constexpr double kMinRateSpan = 1;
}  // namespace

RemainingCost::RemainingCost(int width, int height, uint64_t frames)
    : width_(width),
      height_(height),
      frames_(std::max<uint64_t>(frames, 1)),
      perFrame_(static_cast<uint64_t>(width) * static_cast<uint64_t>(height)),
      taskCount_(perFrame_ * frames_),
      cellsX_(std::min(width, kCellsAcross)),
      cellsY_(std::min(height, kCellsAcross)),
      cellW_((width + cellsX_ - 1) / cellsX_),
      cellH_((height + cellsY_ - 1) / cellsY_) {
  PRT_CHECK(width > 0 && height > 0);
  // Cells that the rounding leaves empty stay empty; cellOf never picks them.
  const size_t perFrameCells = static_cast<size_t>(cellsX_) * static_cast<size_t>(cellsY_);
  acrossFrames_.resize(perFrameCells);
  cells_.resize(perFrameCells * frames_);
  for (int y = 0; y < height; ++y) {
    for (int cx = 0; cx < cellsX_; ++cx) {
      const int x0 = cx * cellW_, x1 = std::min(width, x0 + cellW_);
      if (x1 <= x0) continue;
      const size_t c = static_cast<size_t>(y / cellH_) * static_cast<size_t>(cellsX_) +
                       static_cast<size_t>(cx);
      acrossFrames_[c].pixels += static_cast<uint64_t>(x1 - x0) * frames_;
      for (uint64_t f = 0; f < frames_; ++f) {
        cells_[f * perFrameCells + c].pixels += static_cast<uint64_t>(x1 - x0);
      }
    }
  }
}

size_t RemainingCost::cellOf(uint64_t task) const {
  const uint64_t frame = task / perFrame_, p = task % perFrame_;
  const auto x = static_cast<int>(p % static_cast<uint64_t>(width_));
  const auto y = static_cast<int>(p / static_cast<uint64_t>(width_));
  const size_t perFrameCells = acrossFrames_.size();
  return frame * perFrameCells + static_cast<size_t>(y / cellH_) * static_cast<size_t>(cellsX_) +
         static_cast<size_t>(x / cellW_);
}

void RemainingCost::setPrior(std::vector<double> perCell) {
  if (perCell.size() != acrossFrames_.size() || measuredSamples_ > 0) return;
  for (double v : perCell) {
    if (!(v > 0) || !std::isfinite(v)) return;
  }
  prior_ = std::move(perCell);
}

// Calls f(cell, n) for the tasks of `tasks` below taskCount_, n at a time in one cell: a run
// of neighbouring pixels is cut only at the ends of rows and cells, so the work is in
// proportion to the cells a batch touches, not to its pixels.
template <typename F>
void RemainingCost::forEachCellSpan(const TaskSet& tasks, F&& f) const {
  const auto w = static_cast<uint64_t>(width_);
  const auto cw = static_cast<uint64_t>(cellW_);
  for (const TaskRun& run : tasks.runs()) {
    if (run.stride != 1) {
      for (uint64_t i = 0; i < run.count; ++i) {
        const uint64_t t = run.at(i);
        if (t < taskCount_) f(cellOf(t), uint64_t{1});
      }
      continue;
    }
    const uint64_t end = std::min(run.first + run.count, taskCount_);
    for (uint64_t t = run.first; t < end;) {
      const uint64_t x = (t % perFrame_) % w;
      const uint64_t rowLeft = w - x;                      // to the end of the row
      const uint64_t cellLeft = std::min(cw - x % cw, rowLeft);  // to the end of the cell
      const uint64_t n = std::min(cellLeft, end - t);
      f(cellOf(t), n);
      t += n;
    }
  }
}

void RemainingCost::measured(const TaskSet& tasks, double seconds, double now) {
  if (tasks.empty() || !std::isfinite(seconds) || seconds < 0) return;
  const double each = seconds / static_cast<double>(tasks.size());
  const size_t perFrameCells = acrossFrames_.size();
  forEachCellSpan(tasks, [&](size_t c, uint64_t n) {
    const double share = each * static_cast<double>(n);
    cells_[c].seconds += share;
    cells_[c].samples += n;
    acrossFrames_[c % perFrameCells].seconds += share;
    acrossFrames_[c % perFrameCells].samples += n;
    if (!prior_.empty()) measuredPrior_ += prior_[c % perFrameCells] * static_cast<double>(n);
  });
  measuredSeconds_ += seconds;
  measuredSamples_ += tasks.size();
  history_.emplace_back(now, measuredSeconds_);
  // Kept for the longest window, plus one entry before it to interpolate from.
  while (history_.size() > 2 && history_[1].first < now - kMaxWindow) history_.pop_front();
}

void RemainingCost::finished(const TaskSet& tasks) {
  forEachCellSpan(tasks, [&](size_t c, uint64_t n) {
    cells_[c].finished += n;
    finished_ += n;
  });
}

void RemainingCost::unfinished(const TaskSet& tasks) {
  forEachCellSpan(tasks, [&](size_t c, uint64_t n) {
    Cell& cell = cells_[c];
    const uint64_t back = std::min(n, cell.finished);
    cell.finished -= back;
    finished_ -= back;
  });
}

std::optional<double> RemainingCost::remainingWork() const {
  if (measuredSamples_ == 0) return std::nullopt;
  const double overall = measuredSeconds_ / static_cast<double>(measuredSamples_);
  const size_t perFrameCells = acrossFrames_.size();
  double work = 0;
  for (size_t c = 0; c < cells_.size(); ++c) {
    const Cell& cell = cells_[c];
    const uint64_t left = cell.pixels - std::min(cell.pixels, cell.finished);
    if (left == 0) continue;
    const Cell& across = acrossFrames_[c % perFrameCells];
    const double mean = cellMean(cell, across, unmeasured(c % perFrameCells, overall));
    work += static_cast<double>(left) * mean;
  }
  return work;
}

std::optional<double> RemainingCost::doneFraction() const {
  const std::optional<double> left = remainingWork();
  if (!left) return std::nullopt;
  // The finished pixels' expected cost, by the same means (a checkpoint's pixels included).
  const double overall = measuredSeconds_ / static_cast<double>(measuredSamples_);
  const size_t perFrameCells = acrossFrames_.size();
  double done = 0;
  for (size_t c = 0; c < cells_.size(); ++c) {
    const Cell& cell = cells_[c];
    if (cell.finished == 0) continue;
    const Cell& across = acrossFrames_[c % perFrameCells];
    const double mean = cellMean(cell, across, unmeasured(c % perFrameCells, overall));
    done += static_cast<double>(std::min(cell.finished, cell.pixels)) * mean;
  }
  return done + *left > 0 ? done / (done + *left) : 1.0;
}

// A cell's mean, shrunk towards what it would be without its own samples by the weight of
// kShrinkPixels pixels: a cell seen through one tile is not trusted as much as one seen whole.
double RemainingCost::cellMean(const Cell& cell, const Cell& across, double fallback) {
  const double prior = across.samples > cell.samples
                           ? (across.seconds - cell.seconds) /
                                 static_cast<double>(across.samples - cell.samples)
                           : fallback;
  const auto n = static_cast<double>(cell.samples);
  return (cell.seconds + kShrinkPixels * prior) / (n + kShrinkPixels);
}

double RemainingCost::unmeasured(size_t frameCell, double overall) const {
  if (prior_.empty() || measuredPrior_ <= 0) return overall;
  const double meanPrior = measuredPrior_ / static_cast<double>(measuredSamples_);
  return overall * prior_[frameCell] / meanPrior;
}

double RemainingCost::rate(double now) const {
  if (history_.size() < 2) return 0;
  const double first = history_.front().first;
  // Less than a second of measurements says little about the rate (a strategy's first
  // batches, a speed index still running elsewhere): no estimate yet.
  if (now - first < kMinRateSpan) return 0;
  const double window =
      std::clamp(kWindowShare * (now - first), kMinWindow, kMaxWindow);
  const double from = now - window;
  // The measured total at `from`, interpolated between the entries around it.
  double fromTime = history_.front().first, fromSeconds = history_.front().second;
  for (size_t i = 1; i < history_.size(); ++i) {
    if (history_[i].first >= from) {
      const auto& [t0, s0] = history_[i - 1];
      const auto& [t1, s1] = history_[i];
      if (from > t0 && t1 > t0) {
        fromTime = from;
        fromSeconds = s0 + (s1 - s0) * (from - t0) / (t1 - t0);
      } else {
        fromTime = t0;
        fromSeconds = s0;
      }
      break;
    }
  }
  const double span = now - fromTime;
  return span > 0 ? (measuredSeconds_ - fromSeconds) / span : 0;
}

std::optional<double> RemainingCost::etaSeconds(double now) const {
  if (finished_ >= taskCount_) return 0.0;
  const std::optional<double> left = remainingWork();
  const double r = rate(now);
  if (!left || r <= 0) return std::nullopt;
  return *left / r;
}

}  // namespace prt
