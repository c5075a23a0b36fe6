#pragma once
// The lease and the heartbeat, in one place for every driver and the simulator: a worker the
// master has not heard from for a lease is lost, and each side says it is there when it has
// been silent for a heartbeat interval.

#include <algorithm>

namespace prt {

// --worker-timeout's default up to about 10,000 workers: silence after which a worker (or,
// for a worker, the master) is taken to be gone.
inline constexpr double kDefaultLeaseSeconds = 5;

// The task lease (cluster/task_leases.h): a worker that holds tasks and returns no result for
// this many of its expected batches, and at least the lease, is lost and its tasks reissued.
// Ten: a batch may take several times longer than the last one (a costlier part of the
// image, a busy machine) without its worker being taken for one that keeps tasks.
inline constexpr double kTaskLeaseBatches = 10;

// The heartbeat interval for a lease: kBeatsPerLease beats fit in one lease (one a second for
// the default lease), at most a hundred a second.
inline constexpr double kBeatsPerLease = 5;
inline double heartbeatSecondsFor(double leaseSeconds) {
  return std::max(leaseSeconds / kBeatsPerLease, 0.01);
}

// The master's CPU time for one message in or out, a heartbeat as a result, as measured under
// MPI on a 2-core machine (docs/results.md, "One master's load"), and the share of its time
// heartbeats may take when no worker says anything else (each then sends one and gets one per
// interval).
inline constexpr double kMasterSecondsPerMessage = 2.5e-6;
inline constexpr double kMasterHeartbeatShare = 0.05;

// --worker-timeout's default for `workers` workers: kDefaultLeaseSeconds, or longer where the
// heartbeats of that many silent workers, two per worker and interval, would keep one master
// more than kMasterHeartbeatShare busy (0.5 ms per worker: 8.2 s at 16,384, 33 s at 65,536).
inline double defaultLeaseSeconds(int workers) {
  const double scaled = static_cast<double>(workers) * 2 * kMasterSecondsPerMessage *
                        kBeatsPerLease / kMasterHeartbeatShare;
  return std::max(kDefaultLeaseSeconds, scaled);
}

}  // namespace prt
