#include "drive/worker_loop.h"

#include <algorithm>
#include <deque>
#include <new>
#include <stdexcept>
#include <string>

#include "cluster/worker.h"
#include "core/machine.h"
#include "drive/build_info.h"
#include "drive/effect_thread.h"
#include "drive/worker_summary.h"
#include "metrics/events.h"

namespace prt {
namespace {

struct MasterGone {};  // thrown from a batch to end the loop: the master's link is gone

class WorkerLoop {
 public:
  WorkerLoop(Transport& net, int id, WorkerEngine& engine, const WorkerLoopOptions& options,
             const WorkerFaultActions& faults)
      : net_(net),
        id_(id),
        engine_(engine),
        options_(options),
        faults_(faults),
        // A batch keeps every thread busy: batchPixels for each of them.
        worker_(id, WorkerOptions{options.batchPixels * static_cast<uint64_t>(engine.threads()),
                                  options.batchSeconds}) {}

  WorkerExit run() {
    try {
      return loop();
    } catch (const MasterGone&) {
      return WorkerExit::MasterLost;
    }
  }

 private:
  WorkerExit loop() {
    lastFromMaster_ = net_.now();
    while (!worker_.stopped()) {
      const double now = net_.now();
      if (now - lastFromMaster_ > options_.masterTimeoutSeconds) return WorkerExit::MasterLost;
      heartbeatIfDue(now);
      if (effects_.running()) {
        // Computing: mail waits for the state machine, but it still shows the master is there.
        const double wait = std::clamp(nextBeat_ - now, 0.001, options_.heartbeatSeconds);
        if (effects_.waitFor(wait)) {
          finishEffect();
        } else if (!gatherMail()) {
          return WorkerExit::MasterLost;
        }
        continue;
      }
      if (!inbox_.empty()) {
        Incoming in = std::move(inbox_.front());
        inbox_.pop_front();
        handle(in);
        continue;
      }
      const bool busy = worker_.needsSetup() || worker_.hasWork();
      Incoming in = net_.poll(busy ? now : std::min(nextBeat_, now + 0.25));
      if (in.kind == Incoming::Kind::Packet) {
        handle(in);
        continue;  // read all waiting mail before computing
      }
      if (in.kind == Incoming::Kind::PeerLost && in.from == kMaster) return WorkerExit::MasterLost;
      if (worker_.needsSetup()) {
        startSetup();
      } else if (worker_.hasWork()) {
        if (failsNow()) return fail();
        startBatch();
      }
    }
    WorkerSummary summary{rays_, worker_.tasksReceived(), engine_.threads(), engine_.slowdown(),
                          std::move(log_.events)};
    net_.send(kMaster, Channel::Summary, encodeSummary(summary));
    net_.flush(options_.masterTimeoutSeconds);
    return WorkerExit::Stopped;
  }

  void heartbeatIfDue(double now) {
    if (now < nextBeat_) return;
    // Heartbeats are the transport's keep-alive, not protocol traffic: not in the event log.
    net_.send(kMaster, Channel::Protocol, encode(HeartbeatMsg{}));
    nextBeat_ = now + options_.heartbeatSeconds;
  }

  void sendOut(const Outbox& out) {
    sendOutbox(net_, id_, out, log_);
    // Any message renews the lease: the next heartbeat is due an interval after the last
    // word to the master, so a worker that returns results often sends none.
    for (const Envelope& e : out) {
      if (e.to == kMaster) nextBeat_ = net_.now() + options_.heartbeatSeconds;
    }
  }


  // While computing: takes whatever has arrived into the inbox. False if the master is gone.
  bool gatherMail() {
    for (;;) {
      Incoming in = net_.poll(net_.now() - 1);
      if (in.kind == Incoming::Kind::Timeout) return true;
      if (in.kind == Incoming::Kind::PeerLost) {
        if (in.from == kMaster) return false;
        continue;
      }
      if (in.from == kMaster) lastFromMaster_ = net_.now();
      inbox_.push_back(std::move(in));
    }
  }

  void handle(const Incoming& in) {
    if (in.kind != Incoming::Kind::Packet || in.channel != Channel::Protocol) return;
    const double now = net_.now();
    if (in.from == kMaster) lastFromMaster_ = std::max(lastFromMaster_, now);
    Message m;
    try {
      m = decode(in.bytes);
    } catch (const std::bad_alloc&) {
      throw;  // out of memory is not a bad message: main() reports it as such
    } catch (const std::exception& e) {
      // From a peer (or anyone relaying through one): that message is dropped, nothing more.
      if (in.from != kMaster) {
        worker_.countRefused();
        return;
      }
      throw std::runtime_error("bad message from the master: " + std::string(e.what()));
    }
    if (std::holds_alternative<HeartbeatMsg>(m)) return;
    log_.add({EventKind::MessageReceived, id_, now, now, 0, in.bytes.size(), in.from,
              messageName(m)});
    sendOut(worker_.onMessage(in.from, m));
  }

  void startSetup() {
    doing_ = Doing::Setup;
    effectStart_ = net_.now();
    effects_.start([this] {
      engine_.load(worker_.scene());
      speedIndex_ = engine_.measureSpeedIndex();
    });
  }

  void startBatch() {
    doing_ = Doing::Batch;
    batch_ = worker_.nextBatch();
    effectStart_ = net_.now();
    // A batch of several threads renders here too when the last one was short (the hand-off
    // would cost more than it saves), and on the effect thread when it may outlast a
    // heartbeat interval, so that heartbeats go out while it renders.
    const bool inline_ = engine_.threads() == 1 || lastBatchSeconds_ < options_.heartbeatSeconds / 4;
    if (inline_) {
      // One thread renders here, sending heartbeats between pieces: handing each batch to
      // another thread and back costs two wake-ups, which on small batches is more than the
      // batch (about 85 us a batch measured on this 2-core VM).
      rgb_ = engine_.render(batch_, computeSeconds_, rays_, [this] {
        const double now = net_.now();
        if (now < nextBeat_) return;
        heartbeatIfDue(now);
        // And take in what arrived, as while an effect runs: the master's heartbeats keep
        // showing it is there through a long batch.
        masterGone_ = masterGone_ || !gatherMail();
      });
      finishBatch();
      if (masterGone_) throw MasterGone{};
      return;
    }
    effects_.start([this] { rgb_ = engine_.render(batch_, computeSeconds_, rays_); });
  }

  void finishEffect() {
    effects_.take();  // rethrows what the effect threw: the loop ends, the driver reports it
    if (doing_ == Doing::Setup) {
      log_.add({EventKind::Setup, id_, effectStart_, net_.now(), 0, 0, 0, ""});
      worker_.limitTasks(engine_.taskCount());
      sendOut(worker_.setupDone(speedIndex_, {buildDescription(), hostName()}));
      doing_ = Doing::Nothing;
    } else {
      finishBatch();
    }
  }

  bool failsNow() const {
    return options_.fault && options_.fault->kind != FaultInjection::Kind::Corrupt &&
           rendered_ >= options_.fault->afterPixels;
  }

  void finishBatch() {
    // A corrupt machine corrupts everything it renders from then on, checks included.
    if (options_.fault && options_.fault->kind == FaultInjection::Kind::Corrupt &&
        rendered_ >= options_.fault->afterPixels) {
      corruptPixels(batch_, rgb_);
    }
    lastBatchSeconds_ = computeSeconds_;
    // A spot check is work of this worker's, but not its pixels: labelled apart.
    log_.add({EventKind::Compute, id_, effectStart_, effectStart_ + computeSeconds_,
              batch_.size(), 0, 0, worker_.batchIsCheck() ? kCheckLabel : ""});
    rendered_ += batch_.size();
    sendOut(worker_.batchDone(batch_, std::move(rgb_), computeSeconds_));
    rgb_.clear();
    doing_ = Doing::Nothing;
  }

  WorkerExit fail() {
    if (options_.fault->kind == FaultInjection::Kind::Crash) {
      if (faults_.crash) faults_.crash();
    } else if (faults_.hang) {
      faults_.hang();
    }
    return WorkerExit::Faulted;
  }

  enum class Doing { Nothing, Setup, Batch };

  Transport& net_;
  int id_;
  WorkerEngine& engine_;
  const WorkerLoopOptions& options_;
  const WorkerFaultActions& faults_;
  Worker worker_;
  EventLog log_;
  std::deque<Incoming> inbox_;
  double lastFromMaster_ = 0;
  double nextBeat_ = 0;  // the first heartbeat goes out at once
  uint64_t rendered_ = 0;
  uint64_t rays_ = 0;
  bool masterGone_ = false;  // the transport said so while a batch rendered here
  double lastBatchSeconds_ = 1e9;  // the last batch's time (none yet: assume a long one)

  // The effect in progress; written by the effect thread, read here after it is done.
  Doing doing_ = Doing::Nothing;
  double effectStart_ = 0;
  TaskSet batch_;
  std::vector<float> rgb_;
  double computeSeconds_ = 0;
  double speedIndex_ = 0;
  EffectThread effects_;  // last: joined before the state it writes goes away
};

}  // namespace

WorkerExit runWorkerLoop(Transport& net, int id, WorkerEngine& engine,
                         const WorkerLoopOptions& options, const WorkerFaultActions& faults) {
  return WorkerLoop(net, id, engine, options, faults).run();
}

}  // namespace prt
