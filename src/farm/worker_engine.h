#pragma once
// WorkerEngine: the effects a worker state machine asks its driver for, shared by the thread
// and MPI drivers: build the renderer from the scene the master sent, measure the speed index,
// render a batch — all under the worker's slowdown, on `threads` threads (a machine's cores).
// One engine per worker; not shared.

#include <functional>
#include <memory>
#include <utility>
#include <vector>

#include "cluster/messages.h"
#include "drive/engine.h"
#include "farm/speed_index_kind.h"
#include "farm/frame_renderer.h"
#include "farm/throttle.h"
#include "trace/renderer.h"

namespace prt {

class WorkerEngine final : public Engine {
 public:
  // slowdownChanges: this worker's --slowdown-at changes, sorted (changesOf()); threads: its
  // rendering threads.
  WorkerEngine(double slowdown, SpeedIndexKind speedIndexKind, int speedIndexDiscs,
               std::vector<SpeedChange> slowdownChanges = {}, int threads = 1)
      : throttle_(slowdown, std::move(slowdownChanges)),
        speedIndexKind_(speedIndexKind),
        speedIndexDiscs_(speedIndexDiscs),
        threads_(threads < 1 ? 1 : threads) {}

  int threads() const override { return threads_; }
  double slowdown() const override { return throttle_.slowdown(); }  // the factor at the start
  WorkerIdentity identity() const override;

  // Parses the scene text (the master already validated it) and prepares the renderer of its
  // first frame.
  void load(const SceneMsg& scene) override;
  uint64_t taskCount() const override { return frames_ ? frames_->taskCount() : 0; }  // once loaded
  uint64_t framesBuilt() const override { return frames_ ? frames_->framesBuilt() : 0; }
  // Of the tasks it rendered (the speed probe's pixels are not counted: they are rendered
  // again as tasks).
  uint64_t nonFiniteSamples() const override {
    return frames_ ? frames_->nonFiniteSamples() - nonFiniteOfProbe_ : 0;
  }
  // The speed index (Towers of Hanoi time, or the ray-tracing probe's on the loaded scene),
  // slowed down like everything else this worker computes, for the worker as it renders: the
  // probe renders with all its threads; the Hanoi run solves one puzzle on each thread at
  // once and reports the time per puzzle (the wall time over the thread count), so a worker
  // of N cores has 1/N of one core's index.
  double measureSpeedIndex() override;
  // Renders `batch` (tasks of the frame sequence: FrameRenderer) on the worker's threads;
  // returns 3 floats per task. `seconds` receives the wall
  // time including the slowdown wait, `rays` the rays traced.
  // `between` (if set) is called on this thread all through the slowdown's wait and, with one
  // thread, between pieces of the batch, so the caller can keep sending heartbeats while it
  // renders without a second thread (a batch of several threads is rendered here when the
  // last one was short, and a machine emulated 1000 times slower waits seconds after it).
  std::vector<float> render(const TaskSet& batch, double& seconds, uint64_t& rays,
                            const std::function<void()>& between = {}) override;


 private:
  Throttle throttle_;
  SpeedIndexKind speedIndexKind_;
  int speedIndexDiscs_;
  int threads_;
  std::unique_ptr<FrameRenderer> frames_;
  uint64_t nonFiniteOfProbe_ = 0;
};

}  // namespace prt
