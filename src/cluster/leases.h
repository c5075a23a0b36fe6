#pragma once
// The lease and the heartbeat, in one place for every driver and the simulator: a worker the
// master has not heard from for a lease is lost, and each side says it is there when it has
// been silent for a heartbeat interval.

#include <algorithm>

namespace prt {

// --worker-timeout's default: silence after which a worker (or, for a worker, the master) is
// taken to be gone.
inline constexpr double kDefaultLeaseSeconds = 5;

// The heartbeat interval for a lease: several beats fit in one lease, and never more than one
// a second.
inline double heartbeatSecondsFor(double leaseSeconds) {
  return std::clamp(leaseSeconds / 4, 0.01, 1.0);
}

}  // namespace prt
