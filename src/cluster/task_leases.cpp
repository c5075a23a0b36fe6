#include "cluster/task_leases.h"

#include <algorithm>
#include <cmath>

#include "core/check.h"

namespace prt {

TaskLeases::TaskLeases(TaskLeaseOptions options, int workerCount)
    : options_(options), workers_(static_cast<size_t>(workerCount)) {
  PRT_CHECK(options_.batches >= 0 && options_.minSeconds >= 0);
}

void TaskLeases::addWorker() { workers_.emplace_back(); }

void TaskLeases::setSpeedIndex(int worker, double seconds) {
  workers_[static_cast<size_t>(worker)].speedIndex = seconds;
}

double TaskLeases::leaseOf(int worker) const {
  const Lease& l = workers_[static_cast<size_t>(worker)];
  const double scaled = std::min(slowestPerSpeed_ * l.speedIndex, kSpeedSpread * longestBatch_);
  const double expected = std::max(l.lastBatch, scaled);
  if (!(expected > 0)) return std::numeric_limits<double>::infinity();
  return std::max(options_.minSeconds, options_.batches * expected);
}

void TaskLeases::arm(int worker, double since) {
  Lease& l = workers_[static_cast<size_t>(worker)];
  if (l.armed) byDue_.erase({l.due, worker});
  const double lease = leaseOf(worker);
  l.armed = true;
  l.since = since;
  // Nothing measured yet: looked at again after the least lease.
  l.due = since + (std::isfinite(lease) ? lease : options_.minSeconds);
  byDue_.emplace(l.due, worker);
}

void TaskLeases::given(int worker, double now, bool idle) {
  if (!enabled()) return;
  Lease& l = workers_[static_cast<size_t>(worker)];
  if (l.armed && !idle) return;
  l.previous = now;  // its next batch starts once these arrive
  arm(worker, now);
}

void TaskLeases::returned(int worker, double now, double computeSeconds, bool fresh) {
  if (!enabled()) return;
  Lease& l = workers_[static_cast<size_t>(worker)];
  // What it says a batch took, never more than the master waited for it: a worker cannot
  // lengthen its own lease (nor everyone's) by its word alone.
  if (l.previous >= 0 && std::isfinite(computeSeconds) && computeSeconds > 0) {
    const double measured = std::min(computeSeconds, now - l.previous);
    if (measured > 0) {
      l.lastBatch = measured;
      longestBatch_ = std::max(longestBatch_, measured);
      if (l.speedIndex > 0) slowestPerSpeed_ = std::max(slowestPerSpeed_, measured / l.speedIndex);
    }
  }
  l.previous = now;
  if (fresh) {
    l.lastFresh = now;
    arm(worker, now);
  }
}

void TaskLeases::postpone(int worker, double now, double seconds) {
  Lease& l = workers_[static_cast<size_t>(worker)];
  if (l.armed) byDue_.erase({l.due, worker});
  l.armed = true;
  l.due = now + (std::isfinite(seconds) && seconds > 0 ? seconds : options_.minSeconds);
  byDue_.emplace(l.due, worker);
}

void TaskLeases::renew(int worker, double now) {
  if (!enabled()) return;
  Lease& l = workers_[static_cast<size_t>(worker)];
  l.previous = now;
  if (l.armed) arm(worker, now);
}

void TaskLeases::drop(int worker) {
  Lease& l = workers_[static_cast<size_t>(worker)];
  if (l.armed) byDue_.erase({l.due, worker});
  l.armed = false;
}

std::vector<int> TaskLeases::expired(double now) {
  std::vector<int> out;
  while (!byDue_.empty() && byDue_.begin()->first <= now) {
    const int w = byDue_.begin()->second;
    byDue_.erase(byDue_.begin());
    Lease& l = workers_[static_cast<size_t>(w)];
    const double lease = leaseOf(w);
    // Estimates grow meanwhile (a slower batch elsewhere): looked at again when it runs out.
    const double due = std::isfinite(lease) ? l.since + lease : now + options_.minSeconds;
    if (due > now) {
      l.due = due;
      byDue_.emplace(due, w);
      continue;
    }
    l.armed = false;
    out.push_back(w);
  }
  std::sort(out.begin(), out.end());
  return out;
}

}  // namespace prt
