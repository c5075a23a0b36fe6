#pragma once
// Test support (linked into prt_tests only): a scripted master that drives a Strategy the way
// the real master does, with deterministic fake workers. Each round, the live workers in a
// shuffled but reproducible order render a few tasks from the front of their queues (faster
// workers, with lower speed indices, render more per round) and ask for more when their
// queue is empty. Queue-length queries are answered at the start of the next round with the
// true lengths at that time, so answers are as stale as a real network makes them; transfers
// move tasks from the back of the sender's queue, fewer if it holds fewer. Every round's
// rendering is reported to the strategy as results (onResults) taking one second per round,
// before the request that may follow. Workers may join at the start of a given round
// (onWorkerJoined, then a request unless it was given tasks at once), as the real master
// introduces them once their speed index is in.

#include <cstdint>
#include <string>
#include <vector>

#include "balance/strategy.h"

namespace prt::testing {

struct FakeArrival {
  uint64_t atRound = 1;          // joins at the start of this round (rounds count from 1)
  double speedIndexSeconds = 1;  // renders as a worker with this index would
};

struct FakeRunConfig {
  uint64_t taskCount = 0;
  std::vector<double> speedIndexSeconds;  // one per worker
  int lostWorker = -1;                    // this worker (possibly one that joins) is lost ...
  uint64_t loseAfterRendered = 0;         // ... once this many tasks are rendered in all
  uint64_t seed = 1;                      // the interleaving of workers
  uint64_t maxRounds = 0;                 // 0: 2 * taskCount + 100
  bool hideSpeedIndex = false;            // the strategy is told every index is 1
  int slowedWorker = -1;                  // this worker renders only slowedRate tasks a
  uint64_t slowedFromRound = 0;           // round from this round on
  uint64_t slowedRate = 1;
  std::vector<FakeArrival> arrivals = {};  // workers c, c+1, ... join, in this order
  uint64_t frameTasks = 0;                 // StartInfo::frameTasks: a frame sequence's
};

struct FakeRunResult {
  bool terminated = false;  // every live worker idle, nothing pending
  uint64_t rounds = 0;
  uint64_t requests = 0;
  uint64_t queries = 0;
  uint64_t transfers = 0;
  std::vector<uint32_t> renderCount;     // per task
  std::vector<uint32_t> assignCount;     // per task, by Assign decisions
  std::vector<uint32_t> recoveredCount;  // per task, times it was handed back as unfinished
  std::vector<uint64_t> lastBusyRound;   // per worker, the last round it rendered anything
  std::vector<uint64_t> renderedBy;      // per worker, tasks it rendered
  uint64_t joined = 0;                   // arrivals that happened before the run ended
  std::vector<std::string> errors;       // protocol violations, empty when all is well
};

FakeRunResult runFakeMaster(Strategy& strategy, const FakeRunConfig& config);

}  // namespace prt::testing
