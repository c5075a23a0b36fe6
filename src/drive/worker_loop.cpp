#include "drive/worker_loop.h"

#include <algorithm>
#include <new>
#include <stdexcept>
#include <string>

#include "drive/effect_thread.h"

namespace prt {
namespace {

struct MasterGone {};  // thrown from a batch to end the loop: the master's link is gone

WorkerLoopOptions withThreads(WorkerLoopOptions options, int threads) {
  options.threads = threads;
  return options;
}

class WorkerPump {
 public:
  WorkerPump(Transport& net, int id, Engine& engine, const WorkerLoopOptions& options,
             const WorkerFaultActions& faults)
      : net_(net),
        id_(id),
        engine_(engine),
        options_(withThreads(options, engine.threads())),
        faults_(faults),
        reactor_(id, options_) {}

  WorkerExit run() {
    try {
      return loop();
    } catch (const MasterGone&) {
      return WorkerExit::MasterLost;
    }
  }

 private:
  WorkerExit loop() {
    reactor_.begin(net_.now());
    sendOut();
    while (!reactor_.worker().stopped()) {
      const double now = net_.now();
      if (reactor_.masterSilent(now)) return WorkerExit::MasterLost;
      reactor_.onDeadline(now);
      sendOut();
      if (effects_.running()) {
        // Computing: mail waits for the state machine, but it still shows the master is there.
        const double wait =
            std::clamp(reactor_.nextDeadline() - now, 0.001, options_.heartbeatSeconds);
        if (effects_.waitFor(wait)) {
          finishEffect();
        } else if (!gatherMail()) {
          return WorkerExit::MasterLost;
        }
        continue;
      }
      const bool busy = reactor_.worker().needsSetup() || reactor_.worker().hasWork();
      Incoming in = net_.poll(busy ? now : std::min(reactor_.nextDeadline(), now + 0.25));
      if (in.kind == Incoming::Kind::Packet) {
        receive(in);
        continue;  // read all waiting mail before computing
      }
      if (in.kind == Incoming::Kind::PeerLost && in.from == kMaster) return WorkerExit::MasterLost;
      switch (reactor_.next(net_.now())) {
        case WorkerStep::Setup:
          startSetup();
          break;
        case WorkerStep::Batch:
          startBatch();
          break;
        case WorkerStep::Crash:
          if (faults_.crash) faults_.crash();
          return WorkerExit::Faulted;
        case WorkerStep::Hang:
          if (faults_.hang) faults_.hang();
          return WorkerExit::Faulted;
        case WorkerStep::Wait:
        case WorkerStep::Stop:
          break;
      }
    }
    net_.send(kMaster, Channel::Summary,
              encodeSummary(reactor_.summary(engine_.threads(), engine_.slowdown(),
                                            engine_.framesBuilt(),
                                            engine_.nonFiniteSamples())));
    net_.flush(options_.masterTimeoutSeconds);
    return WorkerExit::Stopped;
  }

  void sendOut() {
    const Outbox out = reactor_.takeOutbox();
    if (!out.empty()) sendOutbox(net_, id_, out, reactor_.log());
    // Heartbeats are the transport's keep-alive, not protocol traffic: not in the event log.
    if (reactor_.takeHeartbeat()) net_.send(kMaster, Channel::Protocol, encode(HeartbeatMsg{}));
  }

  void receive(const Incoming& in) {
    if (in.kind != Incoming::Kind::Packet || in.channel != Channel::Protocol) return;
    Message m;
    try {
      m = decode(in.bytes);
    } catch (const std::bad_alloc&) {
      throw;  // out of memory is not a bad message: main() reports it as such
    } catch (const std::exception& e) {
      reactor_.onMalformed(in.from, e.what());
      return;
    }
    reactor_.onMessage(in.from, std::move(m), in.bytes.size(), net_.now());
    sendOut();
  }

  // While computing: hands whatever has arrived to the reactor, which keeps it until the work
  // is done. False if the master is gone.
  bool gatherMail() {
    for (;;) {
      const Incoming in = net_.poll(net_.now() - 1);
      if (in.kind == Incoming::Kind::Timeout) return true;
      if (in.kind == Incoming::Kind::PeerLost) {
        if (in.from == kMaster) return false;
        continue;
      }
      receive(in);
    }
  }

  void startSetup() {
    doing_ = Doing::Setup;
    effects_.start([this] {
      engine_.load(reactor_.worker().scene());
      speedIndex_ = engine_.measureSpeedIndex();
    });
  }

  void startBatch() {
    doing_ = Doing::Batch;
    rays_ = 0;
    // A batch of several threads renders here too when the last one was short (the hand-off
    // would cost more than it saves), and on the effect thread when it may outlast a
    // heartbeat interval, so that heartbeats go out while it renders.
    const bool inline_ = engine_.threads() == 1 ||
                         reactor_.lastBatchSeconds() < options_.heartbeatSeconds / 4;
    if (inline_) {
      // One thread renders here, sending heartbeats between pieces: handing each batch to
      // another thread and back costs two wake-ups, which on small batches is more than the
      // batch (about 85 us a batch measured on this 2-core VM).
      rgb_ = engine_.render(reactor_.batch(), computeSeconds_, rays_, [this] {
        const double now = net_.now();
        if (now < reactor_.nextDeadline()) return;
        reactor_.onDeadline(now);
        sendOut();
        // And take in what arrived, as while an effect runs: the master's heartbeats keep
        // showing it is there through a long batch.
        masterGone_ = masterGone_ || !gatherMail();
      });
      finishBatch();
      if (masterGone_) throw MasterGone{};
      return;
    }
    effects_.start([this] { rgb_ = engine_.render(reactor_.batch(), computeSeconds_, rays_); });
  }

  void finishEffect() {
    effects_.take();  // rethrows what the effect threw: the loop ends, the driver reports it
    if (doing_ == Doing::Setup) {
      reactor_.onSetupDone(net_.now(), speedIndex_, engine_.taskCount(),
                           engine_.identity());
      doing_ = Doing::Nothing;
      sendOut();
    } else {
      finishBatch();
    }
  }

  void finishBatch() {
    reactor_.onBatchDone(net_.now(), std::move(rgb_), computeSeconds_, rays_);
    rgb_.clear();
    doing_ = Doing::Nothing;
    sendOut();
  }

  enum class Doing { Nothing, Setup, Batch };

  Transport& net_;
  int id_;
  Engine& engine_;
  const WorkerLoopOptions options_;
  const WorkerFaultActions& faults_;
  WorkerReactor reactor_;
  bool masterGone_ = false;  // the transport said so while a batch rendered here

  // The effect in progress; written by the effect thread, read here after it is done.
  Doing doing_ = Doing::Nothing;
  std::vector<float> rgb_;
  double computeSeconds_ = 0;
  uint64_t rays_ = 0;
  double speedIndex_ = 0;
  EffectThread effects_;  // last: joined before the state it writes goes away
};

}  // namespace

WorkerExit runWorkerLoop(Transport& net, int id, Engine& engine,
                         const WorkerLoopOptions& options, const WorkerFaultActions& faults) {
  return WorkerPump(net, id, engine, options, faults).run();
}

}  // namespace prt
