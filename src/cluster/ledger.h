#pragma once
// Ledger: the master's truth about the work — which worker holds which tasks, which tasks are
// done, when each worker was last heard from (its lease), and which workers were lost, when
// and why. Pure bookkeeping: no I/O, no clock (times come in as seconds on the driver's
// clock), so it is unit-tested with scripted losses, expiries and duplicates.
//
// Tasks here are pixels. A task may be held by several workers at once (a lost worker's tasks
// reissued while it is in fact only slow; an endgame duplicate): the first result for a pixel
// is accepted, every later copy is dropped. A lost worker stays lost, but a late result from
// it is still accepted where it is the first. Workers that join the running render are
// added at the end (the next index), live, their lease starting when they join.
// Not thread-safe: one master owns one ledger.

#include <cstdint>
#include <optional>
#include <set>
#include <string>
#include <utility>
#include <vector>

#include "core/task_set.h"

namespace prt {

struct LostWorker {
  int worker = 0;
  double atSeconds = 0;     // when the master declared it lost
  std::string reason;       // "connection dropped", "silent for 5.0 s", ...
  uint64_t unfinished = 0;  // tasks it held that were not done, handed back for reissue
  double lastHeardSeconds = 0;  // when the master last heard from it (heartbeats count)
};

class Ledger {
 public:
  Ledger(int workerCount, uint64_t taskCount);

  int workerCount() const { return static_cast<int>(workers_.size()); }
  uint64_t taskCount() const { return owner_.size(); }

  // A worker joins at `now`: live, holding nothing, its lease starting now. Returns its index.
  int addWorker(double now);
  // When `worker` joined; nothing for the workers the run started with.
  std::optional<double> joinedAt(int worker) const { return workers_[index(worker)].joinedAt; }

  // Tasks finished before this run started (a resumed checkpoint): never handed out.
  void seedDone(const TaskSet& done);

  // Leases. Every message from a worker renews its lease; `start` begins every lease.
  void startLeases(double now);
  void heard(int worker, double now);
  double silentSeconds(int worker, double now) const;
  // Live workers silent for longer than `leaseSeconds`, in worker order. O(k log W) for k of
  // them: the live workers are indexed by when they were last heard.
  std::vector<int> expired(double now, double leaseSeconds) const;
  // When the next lease runs out (for a driver's poll deadline); +inf when none is live. O(1).
  double nextExpiry(double leaseSeconds) const;
  // The live worker heard from longest ago (the next lease to run out); -1 when none is live.
  int longestSilent() const { return byLastHeard_.empty() ? -1 : byLastHeard_.begin()->second; }

  // Holdings.
  void gave(int worker, const TaskSet& tasks);
  // Whether every task of `tasks` was handed out to some worker (or resumed): a result for one
  // that never was cannot come from a correct worker.
  bool allHandedOut(const TaskSet& tasks) const;
  bool handedOut(uint64_t task) const {
    return task < taskCount() && (handedOut_[task] || owner_[task] == kResumed);
  }
  void movedOut(int from, const TaskSet& tasks);  // `from` sent them to a peer (diffusion)
  // How many of `tasks` (each copy counted) `worker` does not hold: not given to it, or sent
  // on already, as many times as it would send them now. What a transfer notice may move.
  // O(n log n + runs) for n tasks; `tasks` must be of a size the caller has bounded.
  uint64_t notHeld(int worker, const TaskSet& tasks) const;
  // Records results from `worker` (live or lost) and returns the tasks of `tasks` that were
  // not done before, in order; a task already done is dropped.
  TaskSet accept(int worker, const TaskSet& tasks);
  // True while `worker` holds tasks it has not returned (whether or not another worker has
  // since finished them).
  bool holdsWork(int worker) const;
  // What `worker` holds that is not done yet, in the order it received them.
  TaskSet unfinished(int worker) const;
  // How many tasks unfinished(worker) holds, without building the set.
  uint64_t unfinishedCount(int worker) const;
  // Holdings of `worker` not done yet, taken from the back of what it received (the part it
  // renders last), at most `count` tasks.
  TaskSet unfinishedTail(int worker, uint64_t count) const;

  // Losses.
  bool isLive(int worker) const { return workers_[index(worker)].live; }
  int liveCount() const { return liveCount_; }
  // Marks `worker` lost and returns its unfinished tasks (also counted as reissued).
  TaskSet markLost(int worker, double now, const std::string& reason);
  // Tasks that reached a worker already lost (a transfer in flight): counted as reissued.
  void reissuedLate(const TaskSet& tasks) { reissued_ += tasks.size(); }
  const std::vector<LostWorker>& losses() const { return losses_; }
  uint64_t reissuedTasks() const { return reissued_; }

  // Takes back every task whose first result came from `worker` (a worker whose results were
  // found wrong): they are not done any more, and are returned, ascending, for reissue. Tasks
  // resumed from a checkpoint are never taken back.
  TaskSet takeBack(int worker);
  uint64_t takenBackTasks() const { return takenBack_; }

  // Completion.
  bool isDone(uint64_t task) const { return owner_[task] != kNotDone; }
  // The worker whose result for `task` is in the image; kResumed for a checkpoint's task,
  // kNotDone while it is not done.
  static constexpr int32_t kNotDone = -1;
  static constexpr int32_t kResumed = -2;
  int32_t ownerOf(uint64_t task) const { return owner_[task]; }
  // Tasks whose first result came from `worker` (its share of the image).
  uint64_t acceptedFrom(int worker) const { return workers_[index(worker)].accepted; }
  uint64_t doneCount() const { return doneCount_; }
  bool complete() const { return doneCount_ == taskCount(); }
  // Every task done, ascending, but those of `except` (ascending: tasks not to count as done,
  // such as pixels whose spot checks are still open).
  TaskSet doneSet(const std::vector<uint64_t>& except = {}) const;
  uint64_t duplicates() const { return duplicates_; }  // result copies dropped

 private:
  struct Holding {
    bool live = true;
    double lastHeard = 0;
    std::optional<double> joinedAt;
    TaskSet given;     // every task it received, in order (assignments, transfers in)
    TaskSet moved;     // tasks it sent to peers
    uint64_t returned = 0;  // tasks it returned results for
    uint64_t accepted = 0;  // of those, the ones that were first (in the image)
    bool mayRepeat = false;  // given a task that was handed out before: `given` may repeat it
  };
  size_t index(int worker) const;
  void setLastHeard(int worker, double when);

  std::vector<Holding> workers_;
  // The live workers by (last heard, worker): a message renews a lease in O(log W), and the
  // master loop asks for the next expiry after every message without walking the workers.
  std::set<std::pair<double, int>> byLastHeard_;
  int liveCount_;
  std::vector<int32_t> owner_;  // per task: who delivered its result (4 bytes a pixel)
  std::vector<bool> handedOut_;  // per task: given to a worker at least once
  uint64_t doneCount_ = 0;
  uint64_t reissued_ = 0;
  uint64_t duplicates_ = 0;
  uint64_t takenBack_ = 0;
  std::vector<LostWorker> losses_;
};

}  // namespace prt
