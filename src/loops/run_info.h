#pragma once
// What the master knows at the end of a run, put into the report's RunInfo the same way for
// every driver (threads, MPI, the simulator): per worker its arrival, the pixels accepted from
// it, its host, its summary (slowdown, tasks, threads, rays, events placed on the master's
// clock), and the run's losses, rejections, spot checks, reissues and duplicates. The driver
// adds what only it knows (the image's size and sampling, the serial time, the speed index
// kind, frames).

#include <functional>
#include <optional>
#include <vector>

#include "cluster/master.h"
#include "loops/worker_summary.h"
#include "metrics/events.h"
#include "metrics/run_report.h"

namespace prt {

struct MasterRecord {
  const Master& master;
  std::vector<std::optional<WorkerSummary>>& summaries;  // per worker; events moved out
  std::vector<Event>& events;  // the master's events; the workers' are appended
  bool sharedClock = false;    // the workers' event times need no alignment
  double leaseSeconds = 0;
  double heartbeatSeconds = 0;
  std::function<double(int worker)> slowdownOf;  // for a worker whose summary is missing
};

void recordMaster(RunInfo& info, MasterRecord record);

}  // namespace prt
