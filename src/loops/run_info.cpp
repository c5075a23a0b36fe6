#include "loops/run_info.h"

#include <utility>

namespace prt {

void recordMaster(RunInfo& info, MasterRecord r) {
  const Master& master = r.master;
  const Ledger& ledger = master.ledger();
  info.workerSpeedIndexSeconds = master.speedIndices();
  const std::vector<Event> masterEvents = r.sharedClock ? std::vector<Event>{} : r.events;
  // Every worker of the run, those that joined included.
  for (int w = 0; w < master.workerCount(); ++w) {
    info.joinedAt.push_back(ledger.joinedAt(w));
    info.acceptedPixels.push_back(ledger.acceptedFrom(w));
    info.hosts.push_back(master.identity(w).host);
    info.kernels.push_back(kernelsOf(master.identity(w).build));
    auto& summary = r.summaries[static_cast<size_t>(w)];
    if (!summary) {
      info.slowdowns.push_back(r.slowdownOf ? r.slowdownOf(w) : 1.0);
      if (master.isLive(w)) info.faults.missingSummaries.push_back(w);
      info.tasksReceived.push_back(0);
      info.threads.push_back(0);  // unknown
      info.framesBuilt.push_back(0);
      info.nonFiniteSamples.push_back(0);
      continue;
    }
    info.slowdowns.push_back(summary->slowdown);
    const double offset =
        r.sharedClock ? 0.0 : workerClockOffset(masterEvents, summary->events, w);
    for (Event& e : summary->events) {
      e.start += offset;
      e.end += offset;
      r.events.push_back(std::move(e));
    }
    summary->events.clear();
    info.tasksReceived.push_back(summary->tasksReceived);
    info.threads.push_back(summary->threads);
    info.framesBuilt.push_back(summary->framesBuilt);
    info.nonFiniteSamples.push_back(summary->nonFiniteSamples);
    info.rays += summary->rays;
  }
  for (const LostWorker& l : ledger.losses()) {
    info.faults.lostWorkers.push_back(
        {l.worker, l.atSeconds, l.reason, l.unfinished, l.lastHeardSeconds});
  }
  for (const RejectedWorker& rej : master.rejections()) {
    info.faults.rejectedWorkers.push_back(
        {rej.worker, rej.atSeconds, rej.reason, rej.pixelsTakenBack, rej.host});
  }
  info.faults.verifiedPixels = master.spotChecks().verifiedPixels();
  info.faults.refereeChecks = master.spotChecks().refereeChecks();
  info.faults.reissuedTasks = ledger.reissuedTasks();
  info.faults.duplicatePixels = ledger.duplicates();
  info.faults.endgameCopies = master.endgameCopies();
  info.faults.resumedPixels = master.resumedCount();
  info.faults.workerTimeoutSeconds = r.leaseSeconds;
  info.faults.heartbeatSeconds = r.heartbeatSeconds;
}

}  // namespace prt
