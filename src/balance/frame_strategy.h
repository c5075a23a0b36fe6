#pragma once
// Whole frames to whole machines, as render farms schedule an animation (Flamenco, Deadline,
// OpenCue): each request takes the next frame of the sequence (StartInfo::frameTasks tasks;
// a still is one frame, all of it to the first worker). A baseline: a slow machine that takes
// the last frame decides when the job ends, and a frame is never shared. Lost workers: see
// PooledStrategy (the frame goes back to the pool whole).

#include <cstdint>
#include <string>

#include "balance/pooled_strategy.h"

namespace prt {

class FrameStrategy final : public PooledStrategy {
 public:
  std::string name() const override { return "frames"; }

 protected:
  void prepare(const StartInfo& info) override {
    frameTasks_ = info.frameTasks > 0 ? info.frameTasks : info.taskCount;
  }
  uint64_t handOutSize(int /*worker*/) override { return frameTasks_; }

 private:
  uint64_t frameTasks_ = 1;
};

}  // namespace prt
