#include "drive/master_loop.h"

#include <algorithm>
#include <stdexcept>

#include "core/cpu_time.h"

namespace prt {
namespace {

class MasterPump {
 public:
  MasterPump(Transport& net, Master& master, const MasterLoopOptions& options)
      : net_(net), master_(master), options_(options), reactor_(master, options) {}

  MasterLoopResult run() {
    const double start = net_.now();
    reactor_.start(start);
    sendOut();
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
      receive(waitUntil(std::min(reactor_.nextDeadline(), net_.now() + 0.25)));
      // Everything already waiting, before leases are judged: a long step of the master's own
      // (a spot check it renders) must not turn heartbeats still in the queue into losses.
      for (Incoming more = net_.poll(net_.now() - 1); more.kind != Incoming::Kind::Timeout;
           more = net_.poll(net_.now() - 1)) {
        receive(more);
        if (master_.complete()) break;
      }
      const double now = net_.now();
      if (options_.tick) options_.tick(now);
      reactor_.onDeadline(now);
      sendOut();
    }
    result_.elapsedSeconds = net_.now() - start;
    reactor_.finish(result_.failure, net_.now());
    sendOut();
    MasterLoad& load = reactor_.load();
    load.busySeconds += threadCpuSeconds() - busyFrom_;
    result_.load = load;
    if (result_.failure.empty()) collectSummaries();
    result_.log = std::move(reactor_.log());
    result_.summaries = std::move(reactor_.summaries());
    return std::move(result_);
  }

 private:
  void sendOut() {
    Outbox out = reactor_.takeOutbox();
    if (!out.empty()) sendOutbox(net_, kMaster, out, reactor_.log());
    const std::vector<int> beats = reactor_.takeHeartbeats();
    if (beats.empty()) return;
    const Bytes beat = encode(HeartbeatMsg{});
    for (int w : beats) net_.send(w, Channel::Protocol, beat);
  }

  // A wait for the next message: its time is not the master's work.
  Incoming waitUntil(double deadline) {
    reactor_.load().busySeconds += threadCpuSeconds() - busyFrom_;
    Incoming in = net_.poll(deadline);
    busyFrom_ = threadCpuSeconds();
    return in;
  }

  void receive(const Incoming& in) {
    const double now = net_.now();
    switch (in.kind) {
      case Incoming::Kind::PeerJoined:
        reactor_.onPeerJoined(in.from, now);
        break;
      case Incoming::Kind::PeerLost:
        reactor_.onPeerLost(in.from, now);
        break;
      case Incoming::Kind::Packet:
        if (in.channel == Channel::Summary) {
          reactor_.onSummary(in.from, in.bytes);
          return;
        }
        if (!reactor_.isWorker(in.from)) return;
        try {
          const Message m = decode(in.bytes);
          reactor_.onMessage(in.from, m, in.bytes.size(), now);
        } catch (const std::exception& e) {
          reactor_.onMalformed(in.from, e.what(), now);
        }
        break;
      case Incoming::Kind::Timeout:
        return;
    }
    sendOut();
  }

  // Every worker got StopMsg with the last results; each live one answers with its summary.
  // One that joins meanwhile is told to stop at once, and its summary is waited for too. The
  // goodbye is bounded: a lease from the Stop (or from its joining) for each worker, whatever
  // it sends meanwhile — a worker that heartbeats on and never says goodbye cannot hold the
  // image back — and a stop signal ends it at once. A missing summary is noted, not waited for.
  void collectSummaries() {
    const auto& summaries = reactor_.summaries();
    std::vector<double> until;
    std::vector<bool> waiting;
    auto track = [&] {
      for (int w = static_cast<int>(waiting.size()); w < master_.workerCount(); ++w) {
        until.push_back(net_.now() + options_.leaseSeconds);
        waiting.push_back(master_.isLive(w));
      }
    };
    track();
    auto pending = [&] {
      for (size_t i = 0; i < waiting.size(); ++i) {
        if (waiting[i] && !summaries[i] && net_.now() <= until[i]) return true;
      }
      return false;
    };
    const auto signalled = [&] {
      if (options_.stopPending) return options_.stopPending();
      return options_.interrupted && options_.interrupted() != 0;
    };
    while (pending()) {
      if (signalled()) break;
      const Incoming in = net_.poll(net_.now() + 0.05);
      if (in.kind == Incoming::Kind::PeerJoined) {
        receive(in);  // too late to help: told to stop
        track();
        continue;
      }
      if (!reactor_.isWorker(in.from)) continue;
      const auto i = static_cast<size_t>(in.from);
      if (in.kind == Incoming::Kind::PeerLost) {
        waiting[i] = false;
      } else if (in.kind == Incoming::Kind::Packet && in.channel == Channel::Summary) {
        reactor_.onSummary(in.from, in.bytes);
      }
      // Protocol messages still in flight after the end (a last request, heartbeats) are
      // dropped.
    }
    net_.flush(signalled() ? 0.0 : options_.leaseSeconds);
  }

  Transport& net_;
  Master& master_;
  const MasterLoopOptions& options_;
  MasterReactor reactor_;
  MasterLoopResult result_;
  double busyFrom_ = threadCpuSeconds();  // CPU time when the master last stopped waiting
};

}  // namespace

MasterLoopResult runMasterLoop(Transport& net, Master& master, const MasterLoopOptions& options) {
  return MasterPump(net, master, options).run();
}

}  // namespace prt
