#pragma once
// Engine: the effects a worker's reactor asks of its pump — load the scene the master sent,
// measure the speed index, render a batch — behind one interface, so the driver kit stays
// transport and protocol only. The renderer's engine is farm/worker_engine.h; a test may
// plug in its own. One engine per worker; used by the worker loop's threads one at a time.

#include <cstdint>
#include <functional>
#include <vector>

#include "cluster/messages.h"

namespace prt {

class Engine {
 public:
  virtual ~Engine() = default;
  virtual int threads() const = 0;      // the threads a batch renders on
  virtual double slowdown() const = 0;  // the emulated slowdown at the start (for the report)
  // This build and machine, as the worker tells the master with its speed index.
  virtual WorkerIdentity identity() const = 0;
  // Prepares to render the scene (its first frame).
  virtual void load(const SceneMsg& scene) = 0;
  virtual uint64_t taskCount() const = 0;  // once loaded: the tasks of every frame
  virtual double measureSpeedIndex() = 0;  // seconds, as the scene's worker renders
  // The frames of a sequence it has prepared so far (for the report; 0: not counted).
  virtual uint64_t framesBuilt() const { return 0; }
  // Samples of its tasks whose value was not finite, left out of their pixels (for the
  // report; 0: none, or not counted).
  virtual uint64_t nonFiniteSamples() const { return 0; }
  // Renders `batch`: 3 floats per task. `seconds` receives its time, `rays` adds the rays
  // traced. `between` (if set) is called all through an emulated slowdown's wait and, with
  // one thread, between pieces of the batch, so the caller can keep sending heartbeats while
  // it renders without a second thread.
  virtual std::vector<float> render(const TaskSet& batch, double& seconds, uint64_t& rays,
                                    const std::function<void()>& between = {}) = 0;
};

}  // namespace prt
