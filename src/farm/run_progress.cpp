#include "farm/run_progress.h"

#include <algorithm>

#include <chrono>

#include "cluster/master.h"
#include "trace/renderer.h"

namespace prt {
namespace {
constexpr double kRateWindowSeconds = 5;
}  // namespace

RunProgress::RunProgress(ProgressBoard& board, int width, int height, uint64_t frames)
    : board_(board),
      width_(width),
      height_(height),
      frames_(std::max<uint64_t>(frames, 1)),
      perFrame_(static_cast<uint64_t>(width) * static_cast<uint64_t>(height)),
      cost_(width, height, frames_),
      done_(perFrame_ * frames_, false),
      frameDone_(frames_, 0) {}

double RunProgress::probeCosts(const Renderer& renderer, double budgetSeconds) {
  using Clock = std::chrono::steady_clock;
  const auto start = Clock::now();
  const auto seconds = [](Clock::duration d) { return std::chrono::duration<double>(d).count(); };
  const int cx = cost_.cellsX(), cy = cost_.cellsY();
  const int cw = cost_.cellWidth(), ch = cost_.cellHeight();
  std::vector<double> prior(static_cast<size_t>(cx) * static_cast<size_t>(cy), 0.0);
  uint64_t rays = 0;
  for (int y = 0; y < cy; ++y) {
    for (int x = 0; x < cx; ++x) {
      // 2 x 2 pixels spread over the cell.
      const int x0 = x * cw, y0 = y * ch;
      double spent = 0;
      int samples = 0;
      for (const auto& [fx, fy] : {std::pair{1, 1}, std::pair{3, 1}, std::pair{1, 3}, std::pair{3, 3}}) {
        const int px = x0 + fx * cw / 4, py = y0 + fy * ch / 4;
        if (px >= width_ || py >= height_) continue;
        const auto t0 = Clock::now();
        (void)renderer.renderPixel(static_cast<uint64_t>(py) * static_cast<uint64_t>(width_) +
                                       static_cast<uint64_t>(px),
                                   rays);
        spent += seconds(Clock::now() - t0);
        ++samples;
      }
      prior[static_cast<size_t>(y) * static_cast<size_t>(cx) + static_cast<size_t>(x)] =
          samples > 0 ? spent / samples : 0.0;
      if (seconds(Clock::now() - start) > budgetSeconds) return seconds(Clock::now() - start);
    }
  }
  // Cells past the image (none measured) and too-cheap-to-time ones get the smallest cost
  // measured, so every prior is positive.
  double least = 0;
  for (double v : prior) {
    if (v > 0 && (least == 0 || v < least)) least = v;
  }
  if (least > 0) {
    for (double& v : prior) v = std::max(v, least);
    cost_.setPrior(std::move(prior));
  }
  return seconds(Clock::now() - start);
}

void RunProgress::finished(const TaskSet& tasks) {
  cost_.finished(tasks);
  tasks.forEach([&](uint64_t t) {
    if (t >= done_.size() || done_[t]) return;
    done_[t] = true;
    ++frameDone_[t / perFrame_];
  });
}

void RunProgress::takenBack(const TaskSet& tasks) {
  cost_.unfinished(tasks);
  tasks.forEach([&](uint64_t t) {
    if (t >= done_.size() || !done_[t]) return;
    done_[t] = false;
    --frameDone_[t / perFrame_];
  });
}

void RunProgress::resumed(const TaskSet& tasks) {
  finished(tasks);
  resumed_ += tasks.size();
}

std::optional<double> RunProgress::expectedTotal(double now) const {
  const std::optional<double> eta = cost_.etaSeconds(now);
  if (!eta || !started_) return std::nullopt;
  return now - start_ + *eta;
}

ProgressSnapshot RunProgress::build(double now, const Master* master) {
  if (!started_) {
    started_ = true;
    start_ = now;
  }
  ProgressSnapshot s;
  s.phase = cost_.finishedCount() > resumed_ || master == nullptr
                ? ProgressSnapshot::Phase::Rendering
                : ProgressSnapshot::Phase::Starting;
  s.elapsedSeconds = now - start_;
  s.pixelsDone = cost_.finishedCount();
  s.pixelsTotal = cost_.taskCount();
  s.resumedPixels = resumed_;
  s.etaSeconds = cost_.etaSeconds(now);
  s.doneFraction = cost_.doneFraction();
  if (master == nullptr) return s;
  const Ledger& ledger = master->ledger();
  const int n = master->workerCount();
  rates_.resize(static_cast<size_t>(n));
  for (int w = 0; w < n; ++w) {
    WorkerProgress p;
    p.pixels = ledger.acceptedFrom(w);
    auto& samples = rates_[static_cast<size_t>(w)];
    samples.push_back({now, p.pixels});
    while (samples.size() > 2 && samples[1].at < now - kRateWindowSeconds) {
      samples.erase(samples.begin());
    }
    const RateSample& first = samples.front();
    if (now > first.at) {
      p.pixelsPerSecond = static_cast<double>(p.pixels - first.pixels) / (now - first.at);
    }
    p.silentSeconds = std::max(0.0, ledger.silentSeconds(w, now));
    if (const auto joined = ledger.joinedAt(w)) p.joinedAt = *joined - start_;
    if (!ledger.isLive(w)) {
      p.state = WorkerProgress::State::Lost;
      for (const LostWorker& l : ledger.losses()) {
        if (l.worker == w) {
          p.lostAt = l.atSeconds - start_;
          p.lostReason = l.reason;
        }
      }
    } else if (master->holdsWork(w)) {
      p.state = WorkerProgress::State::Working;
    } else {
      p.state = p.pixels > 0 ? WorkerProgress::State::Idle : WorkerProgress::State::Starting;
    }
    s.workers.push_back(std::move(p));
  }
  return s;
}

void RunProgress::copyImage(const Image& image, uint64_t imageFirstTask,
                            const std::vector<int16_t>* owner) {
  // The earliest frame still being rendered (the last one once all are done).
  uint64_t frame = 0;
  while (frame + 1 < frames_ && frameDone_[frame] == perFrame_) ++frame;
  PartialImage partial;
  partial.frame = frame;
  partial.image = Image(width_, height_);
  const size_t count = static_cast<size_t>(perFrame_);
  const size_t offset = static_cast<size_t>(frame * perFrame_);
  if (offset < imageFirstTask || offset - imageFirstTask + count > image.pixelCount()) return;
  const auto from = image.data().subspan(3 * (offset - imageFirstTask), 3 * count);
  const auto to = partial.image.data();
  partial.done.resize(count);
  partial.owner.assign(count, -1);
  // Only finished pixels are read: a serial render's threads may be writing the others.
  for (size_t i = 0; i < count; ++i) {
    if (!done_[offset + i]) continue;
    partial.done[i] = 1;
    std::copy_n(from.begin() + static_cast<std::ptrdiff_t>(3 * i), 3,
                to.begin() + static_cast<std::ptrdiff_t>(3 * i));
    if (owner != nullptr && offset + i < owner->size()) partial.owner[i] = (*owner)[offset + i];
  }
  partial.version = board_.snapshot().version;
  board_.publishImage(std::move(partial));
}

void RunProgress::tick(double now, const Image& image, const Master* master, bool force,
                       uint64_t imageFirstTask, const std::vector<int16_t>* owner) {
  if (!force && now - lastPublish_ < kPublishSeconds) return;
  lastPublish_ = now;
  board_.publish(build(now, master));
  if (board_.imageWanted()) copyImage(image, imageFirstTask, owner);
}

void RunProgress::end(double now, const Image& image, const Master* master, bool finished,
                      const std::string& message, uint64_t imageFirstTask,
                      const std::vector<int16_t>* owner) {
  ProgressSnapshot s = build(now, master);
  s.phase = finished ? ProgressSnapshot::Phase::Finished : ProgressSnapshot::Phase::Failed;
  if (finished) {
    s.etaSeconds = 0.0;
    for (WorkerProgress& w : s.workers) {
      if (w.state != WorkerProgress::State::Lost) w.state = WorkerProgress::State::Done;
    }
  }
  s.message = message;
  board_.publish(std::move(s));
  if (board_.watched()) copyImage(image, imageFirstTask, owner);
}

}  // namespace prt
