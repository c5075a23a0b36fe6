#pragma once
// TaskLeases: a lease on the tasks a worker holds, not only on its connection. A worker's
// heartbeats show it is there; they do not show it is working. A worker that holds tasks
// must return results: once it has returned none for its task lease, the master takes it for
// lost and reissues what it holds (the first result for a pixel still wins, its own late
// ones included). The rule (docs/running.md, "Faults"):
//
//   task lease = max(minSeconds, batches x the worker's expected batch time)
//
// where the expected batch time is the longer of its own last batch (as it measured it, and
// never more than the master waited for it) and the slowest batch any worker has returned,
// per second of its speed index, times this worker's speed index — the latter never more than
// kSpeedSpread times the longest batch any worker has returned: a speed index is the worker's
// own word, and a joiner that claims to be very slow (or one that claims to be very fast and
// then takes its time) must not buy a lease without end. The lease runs from the
// worker's last fresh result, or from when it was given tasks while it held none. Until any
// batch has been measured there is no estimate, and no worker's task lease runs out.
//
// Pure bookkeeping, like the Ledger: no clock, no I/O. Only the next lease to run out is
// looked at (an ordered index), so a message costs O(log W). Leases are computed when they
// are armed and checked again when they run out: the estimates only grow between a worker's
// own results, so a lease is never found out early.
// Not thread-safe: one master owns it.

#include <cstdint>
#include <limits>
#include <set>
#include <utility>
#include <vector>

#include "cluster/leases.h"

namespace prt {

// How much longer than the longest batch returned so far a worker's batch may be expected to
// take from its speed index alone (its own measured batches count in full).
inline constexpr double kSpeedSpread = 10;

struct TaskLeaseOptions {
  double batches = 0;  // 0: no task leases (the simulator's default); drivers: kTaskLeaseBatches
  double minSeconds = kDefaultLeaseSeconds;  // never shorter than this (--worker-timeout)
};

class TaskLeases {
 public:
  TaskLeases(TaskLeaseOptions options, int workerCount);

  bool enabled() const { return options_.batches > 0; }
  double minSeconds() const { return options_.minSeconds; }
  void addWorker();
  // The worker's speed index (seconds; larger is slower).
  void setSpeedIndex(int worker, double seconds);
  // `worker` was given tasks at `now`: its lease starts, unless it runs already and the worker
  // was not `idle` (holding nothing: its lease starts again now).
  void given(int worker, double now, bool idle);
  // A results message from `worker` at `now`: the batch took `computeSeconds` by its own
  // measure (0: unmeasured); `fresh` when it held a pixel not done before, which renews the
  // lease from now.
  void returned(int worker, double now, double computeSeconds, bool fresh);
  // Work for the master (spot checks) also renews it.
  void renew(int worker, double now);
  // The worker is gone: no lease any more.
  void drop(int worker);
  // An expired lease not acted on (no other worker shows the time was there to work): looked
  // at again `seconds` from `now`, from the same start.
  void postpone(int worker, double now, double seconds);
  // When `worker` last returned a fresh result (-inf: never).
  double lastFresh(int worker) const { return workers_[static_cast<size_t>(worker)].lastFresh; }

  // The workers whose task lease has run out at `now`, taken off the index; each is checked
  // by the caller (does it still hold unfinished tasks?). O(k log W) for k of them.
  std::vector<int> expired(double now);
  double nextExpiry() const {
    return byDue_.empty() ? std::numeric_limits<double>::infinity() : byDue_.begin()->first;
  }
  // The current lease of `worker` (seconds; +inf while nothing is measured), and since when
  // it runs.
  double leaseOf(int worker) const;
  double since(int worker) const { return workers_[static_cast<size_t>(worker)].since; }

 private:
  struct Lease {
    bool armed = false;
    double since = 0;
    double due = 0;
    double speedIndex = 0;
    double lastBatch = 0;  // seconds of its last measured batch (0: none)
    double previous = -1;  // when it last returned results, or was given tasks idle (-1: never)
    double lastFresh = -std::numeric_limits<double>::infinity();
  };
  void arm(int worker, double since);

  TaskLeaseOptions options_;
  std::vector<Lease> workers_;
  std::set<std::pair<double, int>> byDue_;
  double slowestPerSpeed_ = 0;  // the longest batch per second of its worker's speed index
  double longestBatch_ = 0;     // the longest batch any worker has returned (seconds)
};

}  // namespace prt
