#pragma once
// RunProgress: the render's side of a ProgressBoard. It hears every measured batch and every
// pixel as it is finished, keeps the RemainingCost estimate, and publishes a snapshot (and,
// when a reader wants it, the image so far) at most every `kPublishSeconds`: the same for a
// serial render (no worker rows) and for the master of a parallel one (a row per worker, from
// the Master's ledger). Not thread-safe: the render's thread calls it; readers read the board.

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "core/task_set.h"
#include "farm/progress_board.h"
#include "metrics/remaining_cost.h"

namespace prt {

class Master;
class Renderer;

class RunProgress {
 public:
  static constexpr double kPublishSeconds = 0.25;

  // A sequence's tasks are its frames' pixels one frame after another.
  RunProgress(ProgressBoard& board, int width, int height, uint64_t frames = 1);

  // Before the run: renders a few pixels of every cell of the estimate's grid on this
  // thread (frame 0, at most `budgetSeconds`), so that the estimate knows from the start
  // which parts of the image cost more, whatever order the strategy renders them in.
  // Costs about 1,000 pixels; returns the seconds it took.
  double probeCosts(const Renderer& renderer, double budgetSeconds = 0.5);

  void measured(const TaskSet& tasks, double seconds, double now) {
    cost_.measured(tasks, seconds, now);
  }
  // Pixels in for the first time.
  void finished(const TaskSet& tasks);
  void takenBack(const TaskSet& tasks);  // finished pixels to be rendered again
  void resumed(const TaskSet& tasks);  // a checkpoint's pixels, before the run starts

  // Publishes if a publish is due (or `force`). `image` holds the pixels of the tasks from
  // `imageFirstTask` on (a parallel render's: every task, a sequence's frames stacked; a
  // serial sequence's: the frame being rendered); `master` gives the worker rows, null for a
  // serial render.
  // `owner` (optional) holds who rendered each task, as the ImageAssembler keeps it.
  void tick(double now, const Image& image, const Master* master, bool force = false,
            uint64_t imageFirstTask = 0, const std::vector<int16_t>* owner = nullptr);
  // The run ended: a last snapshot with what happened.
  void end(double now, const Image& image, const Master* master, bool finished,
           const std::string& message, uint64_t imageFirstTask = 0,
           const std::vector<int16_t>* owner = nullptr);

  const RemainingCost& cost() const { return cost_; }
  // The whole run's expected seconds (elapsed + ETA), once known.
  std::optional<double> expectedTotal(double now) const;

 private:
  ProgressSnapshot build(double now, const Master* master);
  void copyImage(const Image& image, uint64_t imageFirstTask, const std::vector<int16_t>* owner);

  ProgressBoard& board_;
  int width_, height_;
  uint64_t frames_, perFrame_;
  RemainingCost cost_;
  std::vector<bool> done_;
  std::vector<uint64_t> frameDone_;
  uint64_t resumed_ = 0;
  double start_ = 0;
  bool started_ = false;
  double lastPublish_ = -1e300;
  struct RateSample { double at; uint64_t pixels; };
  std::vector<std::vector<RateSample>> rates_;  // per worker: recent (time, pixels)
  std::vector<WorkerProgress> last_;
};

}  // namespace prt
