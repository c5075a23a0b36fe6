#pragma once
// Strategy: a load-balancing policy as a pure decision object. It never touches MPI, threads,
// mutexes or the clock: the master state machine feeds it events (start, a worker's request
// for more, queue lengths, a lost worker) and carries out the decisions it returns. The same
// object therefore runs unchanged under the local-thread driver, the MPI driver and the
// simulator, and is unit-tested with scripted events.
//
// Tasks are pixel indices 0 .. taskCount-1 in scan-line order. Workers are 0 .. c-1, where c
// starts as the size of StartInfo::speedIndexSeconds and grows by one with every worker that
// joins the running render (onWorkerJoined). Not thread-safe: one master owns one strategy.

#include <cstdint>
#include <memory>
#include <string>
#include <variant>
#include <vector>

#include "core/task_set.h"

namespace prt {

// Give `tasks` to `worker`; they go to the back of its queue.
struct Assign {
  int worker = 0;
  TaskSet tasks;
  bool operator==(const Assign&) const = default;
};

// Nothing for `worker` now. It waits; it may still get tasks later (a transfer, a lost
// worker's tasks). The master stops every worker once the image is complete.
struct NoMoreWork {
  int worker = 0;
  bool operator==(const NoMoreWork&) const = default;
};

// Ask every live worker for its queue length; the answers come back in onQueueLengths().
struct QueryQueues {
  bool operator==(const QueryQueues&) const = default;
};

// Worker `from` sends up to `count` tasks from the back of its queue straight to worker `to`
// (fewer if its queue has shrunk meanwhile; possibly none).
struct Transfer {
  int from = 0;
  int to = 0;
  uint64_t count = 0;
  bool operator==(const Transfer&) const = default;
};

using Decision = std::variant<Assign, NoMoreWork, QueryQueues, Transfer>;
using Decisions = std::vector<Decision>;

// The strategies' parameters. Which strategy reads which field, its range and its help text
// are declared by the strategy's registry row (registry.h); the defaults are these.
struct StrategyOptions {
  double initialPercent = 80;  // reservoir: share of tasks handed out at the start, (0, 100]
  uint64_t chunk = 64;         // self: tasks per hand-out, >= 1
  uint64_t minChunk = 8;       // AWF, AF, stealing, adaptive: the smallest hand-out, >= 1
  double firstPercent = 10;    // adaptive: share of the image handed out at the start, (0, 100]
  double reservePercent = 50;  // adaptive: share of the expected remaining time each hand-out
                               // leaves in the reserve, [0, 100)
};

struct StartInfo {
  uint64_t taskCount = 0;                 // tasks are 0 .. taskCount-1
  std::vector<double> speedIndexSeconds;  // one per worker; lower is faster; size is c >= 1
  // A frame sequence's tasks per frame (frame i's are i * frameTasks ..., in order), or 0 for
  // a still. Strategies with an order of their own keep frames apart in it, so that frames
  // complete one after another (interleaved_order.h); the paper's static strategies ignore it.
  uint64_t frameTasks = 0;
  // A resumed sequence's frames, which lack what the earlier run finished: the tasks of each,
  // in order (frame i's follow frame i - 1's). Empty: every frame has frameTasks.
  std::vector<uint64_t> frameTaskCounts = {};
};

class Strategy {
 public:
  virtual ~Strategy() = default;

  virtual std::string name() const = 0;

  // Called once, before anything else. Typically returns the initial assignments.
  virtual Decisions start(const StartInfo& info) = 0;

  // `worker` has an empty queue and asks for more. The answer must contain, for this worker,
  // an Assign, a NoMoreWork, or (diffusion) a QueryQueues whose outcome answers it later; or
  // nothing, if the strategy answers it later from onResults() (a thief waiting for a queue
  // worth robbing), and by NoMoreWork at the latest once every task has come back.
  virtual Decisions onRequest(int worker) = 0;

  // Answers to the last QueryQueues: lengths[w] is worker w's queue length (0 for lost
  // workers). Only strategies that emit QueryQueues receive this; the default ignores it.
  virtual Decisions onQueueLengths(const std::vector<uint64_t>& lengths);

  // `worker` returned `tasks`, which took it `computeSeconds` to render (measured by the
  // worker, so the strategy never reads a clock; 0 when unmeasured). Adaptive strategies
  // learn speeds from it, and may answer requests they left waiting; the default ignores it
  // and returns nothing. Called for every batch of results, before the request that may
  // follow it from the same worker.
  virtual Decisions onResults(int worker, const TaskSet& tasks, double computeSeconds);

  // `worker` is gone; `unfinished` are the tasks it held and had not returned. The strategy
  // must see that they are rendered by live workers, and never give `worker` anything again
  // (a later request from it is answered with NoMoreWork). Two policies exist:
  //  - dynamic and adaptive strategies (PooledStrategy: reservoir, adaptive, self, guided,
  //    factoring, AWF, AF, stealing) put the tasks back at the front of their pool, so they
  //    go out first, and at once serve the live workers that were told NoMoreWork (or left
  //    waiting) and would otherwise never ask again;
  //  - static ones (StaticStrategy: scatter, scatter-weighted, blocks; and both hybrids)
  //    assign them at once to the live workers, split evenly into contiguous pieces.
  // It may be called again for a worker already lost, with tasks that reached it afterwards
  // (a transfer in flight); they are treated the same way. When no worker is left alive it
  // returns nothing: the master reports the failure.
  virtual Decisions onWorkerLost(int worker, const TaskSet& unfinished) = 0;

  // A worker joins the running render (after start()): it is worker c, the next index, with
  // speed index `speedIndexSeconds` (> 0, finite; lower is faster). It holds nothing. The
  // decisions say what it gets at once; right after this call the master enters a request
  // for it, as for every worker given nothing at the start, so a strategy that returns
  // nothing here answers that request instead. What the strategies do:
  //  - dynamic and adaptive ones (PooledStrategy) count it among the live workers and answer
  //    its request like any other: the reservoir gives it a share of what remains in the
  //    reservoir by its speed index (its division of labour among the live workers), the
  //    others their usual hand-out, or a steal once the pool is empty;
  //  - static ones (scatter, scatter-weighted, blocks) give it nothing: the image was divided
  //    at the start; it renders only the tasks of workers lost later (spread over the live
  //    workers, it among them);
  //  - the hybrids give it nothing at once: its request starts a diffusion round, which
  //    moves tasks to it from the longest queues.
  virtual Decisions onWorkerJoined(int worker, double speedIndexSeconds) = 0;
};

// Creates a strategy by name (registry.h lists the rows); an unknown name or an option outside
// its declared range throws InputError listing the valid names or the valid range.
std::unique_ptr<Strategy> makeStrategy(const std::string& name, const StrategyOptions& options);
std::vector<std::string> strategyNames();  // in the order the help text lists them

// Throws InputError when an option is out of range (whichever strategy would use it).
void validateStrategyOptions(const StrategyOptions& options);

}  // namespace prt
