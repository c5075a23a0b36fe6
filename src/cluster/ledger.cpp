#include "cluster/ledger.h"

#include <algorithm>
#include <limits>
#include <unordered_set>

#include "core/check.h"

namespace prt {
namespace {

// Adds `sign` to counts[i] for every time distinct[i] (ascending, each once) occurs in `set`.
void countIn(const TaskSet& set, const std::vector<uint64_t>& distinct,
             std::vector<int64_t>& counts, int64_t sign) {
  if (distinct.empty()) return;
  for (const TaskRun& r : set.runs()) {
    if (r.count == 0) continue;
    const uint64_t last = r.stride == 0 ? r.first : r.last();
    auto it = std::lower_bound(distinct.begin(), distinct.end(), r.first);
    for (; it != distinct.end() && *it <= last; ++it) {
      if (r.stride == 0 ? *it == r.first : (*it - r.first) % r.stride == 0) {
        counts[static_cast<size_t>(it - distinct.begin())] +=
            sign * (r.stride == 0 ? static_cast<int64_t>(r.count) : 1);
      }
    }
  }
}

// Whether a task a worker was given is still owed by it: not done, and given to it more often
// than it sent it on to a peer. A task can come back to a worker it left: stolen from it, then
// returned to the strategy when the thief was lost, and handed to it again. Moved tasks are
// few next to the image, so sorted copies keep this cheap without a per-pixel table.
class StillOwed {
 public:
  StillOwed(const std::vector<int32_t>& owner, const TaskSet& given, const TaskSet& moved)
      : owner_(owner), moved_(moved.toVector()) {
    if (moved_.empty()) return;
    std::sort(moved_.begin(), moved_.end());
    // Each moved task once, with how often it was given (counted below) less moved out.
    for (size_t i = 0; i < moved_.size();) {
      size_t j = i;
      while (j < moved_.size() && moved_[j] == moved_[i]) ++j;
      distinct_.push_back(moved_[i]);
      net_.push_back(-static_cast<int64_t>(j - i));
      i = j;
    }
    countIn(given, distinct_, net_, 1);
  }
  bool operator()(uint64_t t) const {
    if (owner_[t] != Ledger::kNotDone) return false;
    const auto it = std::lower_bound(distinct_.begin(), distinct_.end(), t);
    return it == distinct_.end() || *it != t || net_[static_cast<size_t>(it - distinct_.begin())] > 0;
  }

 private:
  const std::vector<int32_t>& owner_;
  std::vector<uint64_t> moved_;
  std::vector<uint64_t> distinct_;
  std::vector<int64_t> net_;  // per distinct moved task: times given less times moved out
};

// Each task once, for a worker that may have been given some task twice.
class Once {
 public:
  explicit Once(bool needed) : needed_(needed) {}
  bool first(uint64_t t) { return !needed_ || seen_.insert(t).second; }

 private:
  bool needed_;
  std::unordered_set<uint64_t> seen_;
};

}  // namespace

Ledger::Ledger(int workerCount, uint64_t taskCount)
    : workers_(static_cast<size_t>(workerCount)), liveCount_(workerCount), owner_(taskCount, kNotDone), handedOut_(taskCount, false) {
  PRT_CHECK(workerCount >= 1);
  for (int w = 0; w < workerCount; ++w) byLastHeard_.emplace_hint(byLastHeard_.end(), 0.0, w);
}

size_t Ledger::index(int worker) const {
  PRT_CHECK(worker >= 0 && worker < workerCount());
  return static_cast<size_t>(worker);
}

int Ledger::addWorker(double now) {
  Holding h;
  h.lastHeard = now;
  h.joinedAt = now;
  workers_.push_back(std::move(h));
  ++liveCount_;
  byLastHeard_.emplace(now, workerCount() - 1);
  return workerCount() - 1;
}

void Ledger::seedDone(const TaskSet& done) {
  done.forEach([&](uint64_t t) {
    PRT_CHECK(t < taskCount());
    if (owner_[t] == kNotDone) {
      owner_[t] = kResumed;
      ++doneCount_;
    }
  });
}

void Ledger::setLastHeard(int worker, double when) {
  Holding& h = workers_[index(worker)];
  if (h.live && h.lastHeard != when) {
    byLastHeard_.erase({h.lastHeard, worker});
    byLastHeard_.emplace(when, worker);
  }
  h.lastHeard = when;
}

void Ledger::startLeases(double now) {
  for (int w = 0; w < workerCount(); ++w) setLastHeard(w, now);
}

void Ledger::heard(int worker, double now) {
  setLastHeard(worker, std::max(workers_[index(worker)].lastHeard, now));
}

double Ledger::silentSeconds(int worker, double now) const {
  return now - workers_[index(worker)].lastHeard;
}

std::vector<int> Ledger::expired(double now, double leaseSeconds) const {
  std::vector<int> out;
  for (const auto& [lastHeard, w] : byLastHeard_) {
    if (!(now - lastHeard > leaseSeconds)) break;
    out.push_back(w);
  }
  std::sort(out.begin(), out.end());
  return out;
}

double Ledger::nextExpiry(double leaseSeconds) const {
  if (byLastHeard_.empty()) return std::numeric_limits<double>::infinity();
  return byLastHeard_.begin()->first + leaseSeconds;
}

void Ledger::gave(int worker, const TaskSet& tasks) {
  Holding& h = workers_[index(worker)];
  h.given.append(tasks);
  tasks.forEach([&](uint64_t t) {
    PRT_CHECK(t < taskCount());
    // A task handed out before (a copy, or one back from a loss) may reach it twice.
    h.mayRepeat = h.mayRepeat || handedOut_[t];
    handedOut_[t] = true;
  });
}

bool Ledger::allHandedOut(const TaskSet& tasks) const {
  bool all = true;
  tasks.forEach([&](uint64_t t) { all = all && handedOut(t); });
  return all;
}

void Ledger::movedOut(int from, const TaskSet& tasks) {
  workers_[index(from)].moved.append(tasks);
}

uint64_t Ledger::notHeld(int worker, const TaskSet& tasks) const {
  const Holding& h = workers_[index(worker)];
  std::vector<uint64_t> wanted = tasks.toVector();
  std::sort(wanted.begin(), wanted.end());
  std::vector<uint64_t> distinct;
  std::vector<int64_t> need;
  for (size_t i = 0; i < wanted.size();) {
    size_t j = i;
    while (j < wanted.size() && wanted[j] == wanted[i]) ++j;
    distinct.push_back(wanted[i]);
    need.push_back(static_cast<int64_t>(j - i));
    i = j;
  }
  std::vector<int64_t> held(distinct.size(), 0);
  countIn(h.given, distinct, held, 1);
  countIn(h.moved, distinct, held, -1);
  uint64_t missing = 0;
  for (size_t i = 0; i < distinct.size(); ++i) {
    missing += static_cast<uint64_t>(std::max<int64_t>(0, need[i] - std::max<int64_t>(0, held[i])));
  }
  return missing;
}

TaskSet Ledger::accept(int worker, const TaskSet& tasks) {
  Holding& h = workers_[index(worker)];
  h.returned += tasks.size();
  TaskSet fresh;
  tasks.forEach([&](uint64_t t) {
    PRT_CHECK(t < taskCount());
    if (owner_[t] != kNotDone) {
      ++duplicates_;
      return;
    }
    owner_[t] = static_cast<int32_t>(worker);
    ++doneCount_;
    ++h.accepted;
    fresh.append(TaskRun{t, 1, 1});
  });
  return fresh;
}

bool Ledger::holdsWork(int worker) const {
  const Holding& h = workers_[index(worker)];
  return h.given.size() > h.moved.size() + h.returned;
}

TaskSet Ledger::unfinished(int worker) const {
  return unfinishedTail(worker, std::numeric_limits<uint64_t>::max());
}

uint64_t Ledger::unfinishedCount(int worker) const {
  const Holding& h = workers_[index(worker)];
  const StillOwed owed(owner_, h.given, h.moved);
  Once once(h.mayRepeat);
  uint64_t count = 0;
  h.given.forEach([&](uint64_t t) { count += owed(t) && once.first(t) ? 1 : 0; });
  return count;
}

TaskSet Ledger::unfinishedTail(int worker, uint64_t count) const {
  const Holding& h = workers_[index(worker)];
  TaskSet out;
  if (count == 0) return out;
  const StillOwed keeps(owner_, h.given, h.moved);
  Once once(h.mayRepeat);
  if (count >= h.given.size()) {
    h.given.forEach([&](uint64_t t) {
      if (keeps(t) && once.first(t)) out.append(TaskRun{t, 1, 1});
    });
    return out;
  }
  // From the back: walk the runs in reverse and keep the last `count` tasks still owed.
  std::vector<uint64_t> tail;
  const auto& runs = h.given.runs();
  for (auto r = runs.rbegin(); r != runs.rend() && tail.size() < count; ++r) {
    for (uint64_t i = r->count; i-- > 0 && tail.size() < count;) {
      const uint64_t t = r->at(i);
      if (keeps(t) && once.first(t)) tail.push_back(t);
    }
  }
  for (auto t = tail.rbegin(); t != tail.rend(); ++t) out.append(TaskRun{*t, 1, 1});
  return out;
}

TaskSet Ledger::markLost(int worker, double now, const std::string& reason) {
  Holding& h = workers_[index(worker)];
  PRT_CHECK(h.live);
  byLastHeard_.erase({h.lastHeard, worker});
  h.live = false;
  --liveCount_;
  TaskSet left = unfinished(worker);
  reissued_ += left.size();
  losses_.push_back(LostWorker{worker, now, reason, left.size(), workers_[index(worker)].lastHeard});
  return left;
}

TaskSet Ledger::takeBack(int worker) {
  Holding& h = workers_[index(worker)];
  const auto who = static_cast<int32_t>(worker);
  TaskSet back;
  for (uint64_t t = 0; t < taskCount(); ++t) {
    if (owner_[t] != who) continue;
    uint64_t end = t;
    while (end < taskCount() && owner_[end] == who) owner_[end++] = kNotDone;
    back.append(TaskRun{t, end - t, 1});
    t = end;
  }
  doneCount_ -= back.size();
  h.accepted = 0;
  takenBack_ += back.size();
  return back;
}

TaskSet Ledger::doneSet(const std::vector<uint64_t>& except) const {
  TaskSet out;
  size_t skip = 0;  // the next of `except` not passed yet
  const auto excluded = [&](uint64_t t) {
    while (skip < except.size() && except[skip] < t) ++skip;
    return skip < except.size() && except[skip] == t;
  };
  for (uint64_t t = 0; t < taskCount(); ++t) {
    if (owner_[t] == kNotDone || excluded(t)) continue;
    uint64_t end = t;
    while (end < taskCount() && owner_[end] != kNotDone && !excluded(end)) ++end;
    out.append(TaskRun{t, end - t, 1});
    t = end;
  }
  return out;
}

}  // namespace prt
