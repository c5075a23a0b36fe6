#include "loops/master_reactor.h"

#include <algorithm>
#include <cmath>
#include <exception>
#include <utility>

namespace prt {

MasterReactor::MasterReactor(Master& master, const MasterReactorOptions& options, EventLog* log)
    : master_(master), options_(options), log_(log != nullptr ? log : &own_) {
  summaries_.resize(static_cast<size_t>(master.workerCount()));
}

void MasterReactor::start(double now) {
  take(master_.start(now), now);
  if (std::isfinite(options_.heartbeatSeconds)) nextBeat_ = now + options_.heartbeatSeconds;
  if (options_.checkpoint) nextCheckpoint_ = now + options_.checkpointEverySeconds;
}

double MasterReactor::nextDeadline() const {
  return std::min({nextBeat_, nextCheckpoint_, master_.nextExpiry(options_.leaseSeconds)});
}

void MasterReactor::take(Outbox out, double now) {
  for (const Envelope& e : out) {
    if (e.to >= 0) lastSentTo(e.to) = now;
  }
  load_.sent += out.size();
  if (outbox_.empty()) {
    outbox_ = std::move(out);
  } else {
    for (Envelope& e : out) outbox_.push_back(std::move(e));
  }
}

Outbox MasterReactor::takeOutbox() { return std::exchange(outbox_, {}); }
std::vector<int> MasterReactor::takeHeartbeats() { return std::exchange(heartbeats_, {}); }

double& MasterReactor::lastSentTo(int worker) {
  const auto w = static_cast<size_t>(worker);
  if (w >= lastSent_.size()) lastSent_.resize(w + 1, -std::numeric_limits<double>::infinity());
  return lastSent_[w];
}

void MasterReactor::onMessage(int from, const Message& m, uint64_t bytes, double now) {
  if (!isWorker(from)) return;  // not one of ours: nothing to trust in it
  ++load_.received;
  if (std::holds_alternative<HeartbeatMsg>(m)) {
    ++load_.heartbeatsReceived;
  } else {
    log_->add({EventKind::MessageReceived, kMaster, now, now, 0, bytes, from, messageName(m)});
  }
  if (options_.results) {
    if (const auto* results = std::get_if<ResultsMsg>(&m)) options_.results(from, *results, now);
  }
  take(master_.onMessage(from, m, now), now);
}

void MasterReactor::onMalformed(int from, const std::string& what, double now) {
  if (!isWorker(from)) return;
  take(master_.onWorkerLost(from, now, "sent a malformed message: " + what), now);
}

void MasterReactor::onPeerLost(int from, double now) {
  if (!isWorker(from)) return;
  take(master_.onWorkerLost(from, now, "connection dropped"), now);
}

void MasterReactor::onPeerJoined(int from, double now) {
  if (from != master_.workerCount()) return;  // out of turn: not a worker we can number
  summaries_.emplace_back();
  log_->add({EventKind::WorkerJoined, from, now, now, 0, 0, kMaster, ""});
  take(master_.onWorkerJoined(from, now), now);
}

void MasterReactor::onSummary(int from, const Bytes& bytes) {
  if (!isWorker(from) || summaries_[static_cast<size_t>(from)]) return;
  try {
    onSummary(from, decodeSummary(bytes));
  } catch (const std::exception&) {
    // A summary that does not decode leaves the worker's times out of the report; the image
    // does not depend on it.
  }
}

void MasterReactor::onSummary(int from, WorkerSummary summary) {
  if (!isWorker(from)) return;
  auto& slot = summaries_[static_cast<size_t>(from)];
  if (!slot) slot = std::move(summary);
}

void MasterReactor::onDeadline(double now) {
  take(master_.expireLeases(now, options_.leaseSeconds), now);
  if (now >= nextBeat_) {
    heartbeat(now);
    nextBeat_ = now + options_.heartbeatSeconds;
  }
  if (master_.ledger().losses().size() > lossesLogged_) {
    logLosses();
    checkpoint("a worker was lost", now);
  }
  if (master_.rejections().size() > rejectionsLogged_) {
    // Its pixels are out of the image now: out of the checkpoint at once, too.
    logRejections();
    checkpoint("a worker was rejected", now);
  }
  if (options_.checkpoint && now >= nextCheckpoint_ && !master_.complete()) {
    checkpoint("periodic", now);
  }
}

void MasterReactor::finish(const std::string& failure, double now) {
  take(master_.stopIfComplete(), now);  // complete before any message: a full checkpoint
  logLosses();
  logRejections();
  if (!failure.empty()) checkpoint(failure, now);
}

void MasterReactor::checkpoint(const std::string& why, double now) {
  if (!options_.checkpoint) return;
  const double ended = options_.checkpoint(why, now);
  nextCheckpoint_ = ended + options_.checkpointEverySeconds;
}

void MasterReactor::logLosses() {
  const auto& losses = master_.ledger().losses();
  for (; lossesLogged_ < losses.size(); ++lossesLogged_) {
    const LostWorker& l = losses[lossesLogged_];
    log_->add({EventKind::WorkerLost, l.worker, l.atSeconds, l.atSeconds, 0, 0, 0, l.reason});
  }
}

void MasterReactor::logRejections() {
  const auto& rejections = master_.rejections();
  for (; rejectionsLogged_ < rejections.size(); ++rejectionsLogged_) {
    const RejectedWorker& r = rejections[rejectionsLogged_];
    // One rejected while live is among the losses already, with this reason.
    const auto& losses = master_.ledger().losses();
    const bool logged = std::any_of(losses.begin(), losses.end(), [&](const LostWorker& l) {
      return l.worker == r.worker && l.reason.rfind("rejected: ", 0) == 0;
    });
    if (logged) continue;
    log_->add({EventKind::WorkerLost, r.worker, r.atSeconds, r.atSeconds, 0, 0, 0,
              "rejected: " + r.reason});
  }
}

// A heartbeat to every worker the master has sent nothing to for a heartbeat interval, lost
// ones included, as Master::sendToAll does. A worker that hears from the master anyway needs
// none, which keeps the master's own traffic in proportion to the work, not to the number of
// workers.
void MasterReactor::heartbeat(double now) {
  for (int w = 0; w < master_.workerCount(); ++w) {
    double& last = lastSentTo(w);
    // A little early rather than a whole interval late: rounds come every interval.
    if (now - last < 0.75 * options_.heartbeatSeconds) continue;
    heartbeats_.push_back(w);
    last = now;
    ++load_.sent;
    ++load_.heartbeatsSent;
  }
}

}  // namespace prt
