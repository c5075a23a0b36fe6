#pragma once
// Throughput: what the adaptive strategies learn about each worker from the results it
// returns (Strategy::onResults) and the tasks they gave it. Times are the workers' own
// measured compute seconds, so no strategy reads a clock.
//
// Per worker it keeps:
//  - held(): tasks given and not yet returned, an estimate of its queue (exact after a
//    request, which the worker sends only once its queue is empty; transfers are counted as
//    ordered, so an order the sender could only partly fill leaves the estimate high until
//    the next request);
//  - rate(): tasks per second over the recent results, each batch's weight decaying by
//    kRecentDecay per later batch, so a worker that slows down mid-render is followed within
//    a few batches;
//  - the time per task over all results, its mean and variance (adaptive factoring's mu and
//    sigma^2), estimated from the batch means: a batch of n tasks with mean x is one sample
//    of weight n, and n (x - mu)^2 estimates sigma^2 when tasks are independent;
//  - AWF's weighted average time per task (wap): chunk k (the k-th hand-out) counts with
//    weight k, the current unfinished chunk with weight k + 1, as DLS4LB computes it
//    (C/DLS.c, DLS_EndChunk: mySumTimes += (1 + myExecs) * sumt1).
// Plain value; not thread-safe.

#include <cstddef>
#include <cstdint>
#include <vector>

namespace prt {

class Throughput {
 public:
  static constexpr double kRecentDecay = 0.7;

  void reset(int workerCount);
  void add() { workers_.emplace_back(); }  // a worker joins, knowing nothing yet
  int workerCount() const { return static_cast<int>(workers_.size()); }

  void given(int worker, uint64_t tasks);                   // an Assign
  void moved(int from, int to, uint64_t tasks);             // a Transfer as ordered
  void returned(int worker, uint64_t tasks, double seconds);  // onResults
  void chunkDone(int worker);  // a request: its queue is empty, its hand-out finished
  void lost(int worker);       // forget what it held

  uint64_t held(int worker) const { return at(worker).held; }
  bool measured(int worker) const { return at(worker).recentSeconds > 0; }
  // Tasks over all its measured results.
  double measuredTasks(int worker) const { return at(worker).tasks; }
  // Tasks per second over the recent results; 0 before any measured result.
  double rate(int worker) const;
  // Seconds per task over all results (mu) and their variance (sigma^2); 0 before any.
  double meanTaskSeconds(int worker) const;
  double taskSecondsVariance(int worker) const;
  // AWF's weighted average seconds per task; 0 before any measured result.
  double weightedAverageTaskSeconds(int worker) const;

 private:
  struct Worker {
    uint64_t held = 0;
    double recentTasks = 0, recentSeconds = 0;
    double tasks = 0, seconds = 0;  // all measured results
    double sumSquares = 0;          // sum of n * x^2 over batches (x = batch mean)
    uint64_t batches = 0;
    double chunkTasks = 0, chunkSeconds = 0;   // the current chunk so far
    double wapTasks = 0, wapSeconds = 0;       // closed chunks, weighted by their ordinal
    uint64_t chunks = 0;                       // closed chunks
  };
  const Worker& at(int worker) const { return workers_[static_cast<size_t>(worker)]; }
  Worker& at(int worker) { return workers_[static_cast<size_t>(worker)]; }

  std::vector<Worker> workers_;
};

}  // namespace prt
