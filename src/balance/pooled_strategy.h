#pragma once
// PooledStrategy: the skeleton of the dynamic strategies (reservoir, self-scheduling, guided,
// factoring). All tasks start in one pool in scan-line order; start() serves each worker in
// worker order from the front of the pool, and every request takes the next tasks from the
// front. Subclasses only say how many tasks each hand-out holds.
//
// Once the pool is empty, a request is answered by stealFor(): a subclass may have the
// requester take tasks from a peer's queue (a Transfer). Otherwise it gets NoMoreWork, or,
// where waitsForSteals(), it waits: every later result makes the strategy look again for a
// queue worth robbing, and once every task has come back the waiting get NoMoreWork. (A
// worker told NoMoreWork never asks again, so a strategy that steals would otherwise lose
// the fast workers that ran dry a moment too early.)
// Every strategy built on the pool also follows what each worker holds and how fast it
// returns results (throughput.h), from its own hand-outs and onResults().
//
// Lost workers: their unfinished tasks go back to the FRONT of the pool (so they go out
// first) and every live worker that was told NoMoreWork, and so would never ask again, is
// served at once as if it had just asked. A request from a lost worker gets NoMoreWork.
// A worker that joins is one more live worker, with its speed index; it asks next.
// Not thread-safe.

#include <cstdint>
#include <optional>
#include <set>
#include <utility>
#include <vector>

#include "balance/strategy.h"
#include "balance/task_pool.h"
#include "balance/task_split.h"
#include "balance/throughput.h"

namespace prt {

class PooledStrategy : public Strategy {
 public:
  Decisions start(const StartInfo& info) final;
  Decisions onRequest(int worker) final;
  Decisions onWorkerLost(int worker, const TaskSet& unfinished) final;
  Decisions onResults(int worker, const TaskSet& tasks, double computeSeconds) final;
  // The newcomer is live and idle; its request, which follows, is served like any other.
  Decisions onWorkerJoined(int worker, double speedIndexSeconds) final;

 protected:
  // The order in which tasks sit in the pool; hand-outs take its front. Called first by
  // start(). Defaults to scan-line order, 0 .. taskCount-1.
  virtual TaskSet initialPool(const StartInfo& info) {
    return TaskSet::range(0, info.taskCount);
  }
  // Called by start() when the pool holds every task and every worker is live.
  virtual void prepare(const StartInfo& info) = 0;
  // Tasks start() gives `worker`; may be 0. Defaults to one hand-out.
  virtual uint64_t initialSize(int worker) { return handOutSize(worker); }
  // Tasks a hand-out to live `worker` takes from the non-empty pool; the caller clamps the
  // answer to [1, remaining()]. Called exactly once per hand-out, so it may keep state.
  virtual uint64_t handOutSize(int worker) = 0;
  // Called after a worker is marked lost and its tasks are back in the pool, and after a
  // worker joins (before its first request).
  virtual void onLiveWorkersChanged() {}
  // Called after anything the strategy may index about `worker` changed: what it holds, its
  // rate, whether it is live, whether a steal is on its way to it. Strategies that keep
  // workers in indexed structures (so that no decision walks all workers) update them here.
  virtual void onWorkerChanged(int /*worker*/) {}
  // The pool is empty and live `worker` asks: a Transfer of tasks from a live peer's queue to
  // it, with count >= 1, or nothing (NoMoreWork). Defaults to nothing.
  virtual std::optional<Transfer> stealFor(int /*worker*/) { return std::nullopt; }
  // True: a request that finds nothing to steal waits instead of getting NoMoreWork.
  virtual bool waitsForSteals() const { return false; }

  uint64_t remaining() const { return pool_.size(); }
  const LiveWorkers& workers() const { return workers_; }
  const Throughput& throughput() const { return throughput_; }
  // True while tasks stolen for `worker` may still be on their way to it: its count includes
  // them, but its queue may not, so it is no victim yet.
  bool awaitingSteal(int worker) const { return inbound_[static_cast<size_t>(worker)]; }
  const std::vector<double>& speedIndexSeconds() const { return speedIndexSeconds_; }
  // The reservoir's division of labour over the live workers; 0 for lost workers.
  std::vector<double> liveDivisionOfLabor() const;

 private:
  Decision give(int worker, uint64_t count);
  // A Transfer for waiting or requesting `worker` from stealFor(), recorded; or nothing.
  std::optional<Decision> steal(int worker);

  TaskPool pool_;
  LiveWorkers workers_;
  Throughput throughput_;
  void setWaiting(int worker, bool waiting);
  void setIdle(int worker, bool idle);
  void setInbound(int worker, int victim);  // victim -1: none on its way any more

  // Every set below is kept so that no decision walks all workers.
  std::set<int> idle_;  // told NoMoreWork, or waiting, and given nothing since; by worker
  std::vector<bool> waiting_;  // asked and not answered yet
  // The waiting workers, fastest first (by their rate when they began to wait), then by
  // worker: the order in which results serve them.
  std::set<std::pair<double, int>> waitingByRate_;
  std::vector<double> waitingRate_;
  std::vector<bool> inbound_;  // a steal for it is on its way (until its next result or request)
  std::vector<int> victim_;    // whom that steal is from
  // Thieves each victim was robbed for (entries go stale once the steal arrives; read only
  // when the victim is lost).
  std::vector<std::vector<int>> thievesOf_;
  uint64_t taskCount_ = 0;
  uint64_t returnedCount_ = 0;  // tasks returned by live workers
  std::vector<double> speedIndexSeconds_;
};

}  // namespace prt
