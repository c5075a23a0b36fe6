#include "drive/master_loop.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

#include "core/cpu_time.h"

namespace prt {
namespace {

class MasterLoop {
 public:
  MasterLoop(Transport& net, Master& master, const MasterLoopOptions& options)
      : net_(net), master_(master), options_(options) {
    result_.summaries.resize(static_cast<size_t>(master.workerCount()));
  }

  MasterLoopResult run() {
    const double start = net_.now();
    sendOut(master_.start(start));
    double nextBeat = start + options_.heartbeatSeconds;
    double nextCheckpoint = start + options_.checkpointEverySeconds;
    while (!master_.complete()) {
      if (master_.failed()) {
        result_.failure = "every worker was lost; the image cannot be finished";
        break;
      }
      if (options_.abandoned && options_.abandoned()) {
        result_.failure = "the run was stopped";
        break;
      }
      if (options_.interrupted) {
        if (const int sig = options_.interrupted()) {
          result_.interruptSignal = sig;
          result_.failure = "interrupted by signal " + std::to_string(sig);
          break;
        }
      }
      double deadline = std::min({nextBeat, master_.ledger().nextExpiry(options_.leaseSeconds),
                                  net_.now() + 0.25});
      if (options_.checkpoint) deadline = std::min(deadline, nextCheckpoint);
      receive(waitUntil(deadline));
      // Everything already waiting, before leases are judged: a long step of the master's own
      // (a spot check it renders) must not turn heartbeats still in the queue into losses.
      for (Incoming more = net_.poll(net_.now() - 1); more.kind != Incoming::Kind::Timeout;
           more = net_.poll(net_.now() - 1)) {
        receive(more);
        if (master_.complete()) break;
      }
      const double now = net_.now();
      if (options_.tick) options_.tick(now);
      sendOut(master_.expireLeases(now, options_.leaseSeconds));
      if (now >= nextBeat) {
        heartbeat(now);
        nextBeat = now + options_.heartbeatSeconds;
      }
      const size_t losses = master_.ledger().losses().size();
      if (losses > lossesLogged_) {
        logLosses();
        checkpoint("a worker was lost");
      }
      const size_t rejections = master_.rejections().size();
      if (rejections > rejectionsLogged_) {
        // Its pixels are out of the image now: out of the checkpoint at once, too.
        logRejections();
        checkpoint("a worker was rejected");
      }
      if (options_.checkpoint && now >= nextCheckpoint && !master_.complete()) {
        checkpoint("periodic");
        nextCheckpoint = net_.now() + options_.checkpointEverySeconds;
      }
    }
    result_.elapsedSeconds = net_.now() - start;
    sendOut(master_.stopIfComplete());  // complete before any message: a full checkpoint
    load_.busySeconds += threadCpuSeconds() - busyFrom_;
    result_.load = load_;
    logLosses();
    logRejections();
    if (!result_.failure.empty()) {
      checkpoint(result_.failure);
    } else {
      collectSummaries();
    }
    result_.log = std::move(log_);
    return std::move(result_);
  }

 private:
  void checkpoint(const std::string& why) {
    if (options_.checkpoint) options_.checkpoint(why);
  }

  void logLosses() {
    const auto& losses = master_.ledger().losses();
    for (; lossesLogged_ < losses.size(); ++lossesLogged_) {
      const LostWorker& l = losses[lossesLogged_];
      log_.add({EventKind::WorkerLost, l.worker, l.atSeconds, l.atSeconds, 0, 0, 0, l.reason});
    }
  }

  void logRejections() {
    const auto& rejections = master_.rejections();
    for (; rejectionsLogged_ < rejections.size(); ++rejectionsLogged_) {
      const RejectedWorker& r = rejections[rejectionsLogged_];
      // One rejected while live is among the losses already, with this reason.
      const auto& losses = master_.ledger().losses();
      const bool logged = std::any_of(losses.begin(), losses.end(), [&](const LostWorker& l) {
        return l.worker == r.worker && l.reason.rfind("rejected: ", 0) == 0;
      });
      if (logged) continue;
      log_.add({EventKind::WorkerLost, r.worker, r.atSeconds, r.atSeconds, 0, 0, 0,
                "rejected: " + r.reason});
    }
  }

  void sendOut(const Outbox& out) {
    if (out.empty()) return;
    sendOutbox(net_, kMaster, out, log_);
    const double now = net_.now();
    for (const Envelope& e : out) {
      if (e.to >= 0) lastSentTo(e.to) = now;
    }
    load_.sent += out.size();
  }

  // When the master last sent `worker` anything (never: -infinity).
  double& lastSentTo(int worker) {
    const auto w = static_cast<size_t>(worker);
    if (w >= lastSent_.size()) lastSent_.resize(w + 1, -std::numeric_limits<double>::infinity());
    return lastSent_[w];
  }

  // A heartbeat to every worker the master has sent nothing to for a heartbeat interval, lost
  // ones included, as Master::sendToAll does: one wrongly presumed lost must not conclude that
  // the master is gone. A worker that hears from the master anyway needs none, which keeps
  // the master's own traffic in proportion to the work, not to the number of workers.
  void heartbeat(double now) {
    const Bytes beat = encode(HeartbeatMsg{});
    for (int w = 0; w < master_.workerCount(); ++w) {
      double& last = lastSentTo(w);
      // A little early rather than a whole interval late: rounds come every interval.
      if (now - last < 0.75 * options_.heartbeatSeconds) continue;
      net_.send(w, Channel::Protocol, beat);
      last = now;
      ++load_.sent;
      ++load_.heartbeatsSent;
    }
  }

  // A wait for the next message: its time is not the master's work.
  Incoming waitUntil(double deadline) {
    load_.busySeconds += threadCpuSeconds() - busyFrom_;
    Incoming in = net_.poll(deadline);
    busyFrom_ = threadCpuSeconds();
    return in;
  }


  bool isWorker(int from) const { return from >= 0 && from < master_.workerCount(); }

  void receive(const Incoming& in) {
    const double now = net_.now();
    if (in.kind == Incoming::Kind::PeerJoined) {
      if (in.from != master_.workerCount()) return;  // out of turn: not a worker we can number
      result_.summaries.emplace_back();
      log_.add({EventKind::WorkerJoined, in.from, now, now, 0, 0, kMaster, ""});
      sendOut(master_.onWorkerJoined(in.from, now));
      return;
    }
    if (!isWorker(in.from)) return;  // not one of ours: nothing to trust in it
    if (in.kind == Incoming::Kind::PeerLost) {
      sendOut(master_.onWorkerLost(in.from, now, "connection dropped"));
      return;
    }
    if (in.kind != Incoming::Kind::Packet) return;
    if (in.channel == Channel::Summary) {
      storeSummary(in);
      return;
    }
    Message m;
    try {
      m = decode(in.bytes);
    } catch (const std::exception& e) {
      sendOut(master_.onWorkerLost(in.from, now, std::string("sent a malformed message: ") +
                                                     e.what()));
      return;
    }
    ++load_.received;
    if (std::holds_alternative<HeartbeatMsg>(m)) {
      ++load_.heartbeatsReceived;
    } else {
      log_.add({EventKind::MessageReceived, kMaster, now, now, 0, in.bytes.size(), in.from,
                messageName(m)});
    }
    if (options_.results) {
      if (const auto* results = std::get_if<ResultsMsg>(&m)) options_.results(in.from, *results, now);
    }
    sendOut(master_.onMessage(in.from, m, now));
  }

  void storeSummary(const Incoming& in) {
    auto& slot = result_.summaries[static_cast<size_t>(in.from)];
    if (slot) return;
    try {
      slot = decodeSummary(in.bytes);
    } catch (const std::exception&) {
      // A summary that does not decode leaves the worker's times out of the report; the image
      // does not depend on it.
    }
  }

  // Every worker got StopMsg with the last results; each live one answers with its summary.
  // One that joins meanwhile is told to stop at once, and its summary is waited for too.
  void collectSummaries() {
    std::vector<double> lastHeard;
    std::vector<bool> waiting;
    auto track = [&] {
      for (int w = static_cast<int>(waiting.size()); w < master_.workerCount(); ++w) {
        lastHeard.push_back(net_.now());
        waiting.push_back(master_.isLive(w));
      }
    };
    track();
    auto pending = [&] {
      for (size_t i = 0; i < waiting.size(); ++i) {
        if (waiting[i] && !result_.summaries[i] &&
            net_.now() - lastHeard[i] <= options_.leaseSeconds) {
          return true;
        }
      }
      return false;
    };
    while (pending()) {
      const Incoming in = net_.poll(net_.now() + 0.05);
      if (in.kind == Incoming::Kind::PeerJoined) {
        receive(in);  // too late to help: told to stop
        track();
        continue;
      }
      if (!isWorker(in.from)) continue;
      const auto i = static_cast<size_t>(in.from);
      if (in.kind == Incoming::Kind::PeerLost) {
        waiting[i] = false;
      } else if (in.kind == Incoming::Kind::Packet) {
        lastHeard[i] = net_.now();
        if (in.channel == Channel::Summary) storeSummary(in);
        // Protocol messages still in flight after the end (a last request) are dropped.
      }
    }
    net_.flush(options_.leaseSeconds);
  }

  Transport& net_;
  Master& master_;
  const MasterLoopOptions& options_;
  EventLog log_;
  MasterLoopResult result_;
  size_t lossesLogged_ = 0;
  size_t rejectionsLogged_ = 0;
  MasterLoad load_;
  double busyFrom_ = threadCpuSeconds();  // CPU time when the master last stopped waiting
  std::vector<double> lastSent_;          // per worker: when the master last sent it anything
};

}  // namespace

MasterLoopResult runMasterLoop(Transport& net, Master& master, const MasterLoopOptions& options) {
  return MasterLoop(net, master, options).run();
}

}  // namespace prt
