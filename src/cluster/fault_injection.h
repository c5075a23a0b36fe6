#pragma once
// Test and demonstration hook: make a worker fail part-way through. The same flag
// (--inject-fault W:PIXELS:crash|hang|corrupt) for real runs (drive/worker_loop.h) and the
// simulator (sim/simulator.h).

#include <cstdint>
#include <vector>

#include "core/task_set.h"

namespace prt {

struct FaultInjection {
  enum class Kind { Crash, Hang, Corrupt };
  int worker = 0;
  uint64_t afterPixels = 0;  // fails once it has rendered at least this many pixels
  // Crash: the connection drops; Hang: it goes silent; Corrupt: it goes on, but a bit of
  // about half the pixels it renders from then on is flipped (see corruptPixels).
  Kind kind = Kind::Crash;
};

// What a Corrupt fault does to a rendered batch: flips bit 20 of the red channel (a change
// of about 12 % of its value) of the pixels whose index hashes odd, so some pixels of every
// batch are wrong and the others right.
void corruptPixels(const TaskSet& tasks, std::vector<float>& rgb);

}  // namespace prt
