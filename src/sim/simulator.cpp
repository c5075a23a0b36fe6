#include "sim/simulator.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <deque>
#include <limits>
#include <numeric>
#include <optional>
#include <random>
#include <stdexcept>
#include <string>
#include <utility>

#include "cluster/master.h"
#include "core/check.h"
#include "loops/master_reactor.h"
#include "loops/run_info.h"
#include "loops/worker_reactor.h"
#include "sim/event_queue.h"
#include "sim/worker_speeds.h"

namespace prt {
namespace {

constexpr double kNever = std::numeric_limits<double>::infinity();

struct Mail {
  int from = kMaster;
  uint64_t bytes = 0;
  Message message;
};

// The reactor of a simulated worker: the drivers' rules, in virtual time. Heartbeats are the
// virtual network's (counted from silences), so the reactor sends none and never finds the
// master silent.
WorkerReactorOptions workerOptions(const SimulationOptions& o, int w) {
  WorkerReactorOptions r;
  r.batchPixels = o.batchPixels;
  r.batchSeconds = o.batchSeconds;
  r.heartbeatSeconds = kNever;
  r.masterTimeoutSeconds = kNever;
  r.colours = false;
  for (const FaultInjection& f : o.faults) {
    if (f.worker == w) r.fault = f;
  }
  return r;
}

// A simulated machine: the worker reactor every driver pumps, its speed, and what the virtual
// network knows of it.
struct SimWorker {
  SimWorker(int id, const SimulationOptions& options, EventLog& log, double speed_,
            double speedIndex_)
      : reactor(id, workerOptions(options, id), &log), speed(speed_), speedIndex(speedIndex_) {}
  WorkerReactor reactor;
  double speed;       // relative to the cost map's machine
  double speedIndex;  // seconds; what it measures during setup
  std::vector<SpeedChange> speedChanges;  // its own, sorted
  bool inSetup = false;       // computing its setup (else a batch)
  double workStart = 0;
  double lastToMaster = 0;    // when it last sent the master anything (heartbeats counted)
  double lastFromMaster = 0;  // when the master last sent it anything (heartbeats counted)
  bool dead = false;          // failed: it reads, computes and sends nothing more
  bool lost = false;          // the master knows: it heartbeats it no more
};

SceneMsg sceneMessage(const SimulationOptions& options) {
  SceneMsg scene{std::string(options.sceneBytes, ' '), 1, 1};
  if (options.frames > 1) {
    scene.frames.last = static_cast<int64_t>(options.frames) - 1;
    scene.frames.animated = true;
  }
  return scene;
}

MasterOptions masterOptions(const SimulationOptions& options) {
  MasterOptions m;
  m.endgame = options.endgame;
  return m;
}

// The virtual network and machines that pump the reactors: an agenda of timed events
// (messages reaching their receiver, the master's services ending, work ending, joins,
// failures, the master's deadlines), the network model, and the master's service time.
class Simulation {
 public:
  Simulation(const CostMap& costs, const SimulationOptions& options)
      : costs_(costs),
        options_(options),
        net_(workerCount(), options.network),
        master_(makeStrategy(options.strategy, options.strategyOptions), startingWorkers(),
                costs.pixelCount(), sceneMessage(options), nullptr, masterOptions(options)),
        reactorOptions_(reactorOptions()),
        reactor_(master_, reactorOptions_, &log_) {
    for (int w = 0; w < workerCount(); ++w) {
      const auto i = static_cast<size_t>(w);
      const double speed = options.speeds[i];
      const double speedIndex = options.speedIndexSeconds.empty()
                                    ? options.baseSpeedIndexSeconds / speed
                                    : options.speedIndexSeconds[i];
      workers_.emplace_back(w, options, log_, speed, speedIndex);
      workers_.back().speedChanges = changesOf(options.speedChanges, w);
    }
  }

  SimulatedRun run() {
    reactor_.start(now_);
    send(kMaster, reactor_.takeOutbox());
    for (int w = 0; w < startingWorkers(); ++w) worker(w).reactor.begin(now_);
    int next = startingWorkers();
    for (const JoinWave& wave : options_.joins) {
      for (int k = 0; k < wave.count; ++k) {
        SimEvent join;
        join.time = wave.atSeconds;
        join.kind = SimEventKind::Join;
        join.endpoint = next++;
        queue_.push(std::move(join));
      }
    }
    scheduleFailures();
    scheduleDeadline();
    while (!finished_) {
      if (queue_.empty()) {
        throw std::runtime_error("simulation stalled with " +
                                 std::to_string(costs_.pixelCount() - master_.doneCount()) +
                                 " pixels left (a protocol or strategy bug)");
      }
      SimEvent e = queue_.pop();
      now_ = e.time;
      switch (e.kind) {
        case SimEventKind::Reach:
          e.time = net_.arrive(e.endpoint, e.bytes, now_);
          e.kind = SimEventKind::Deliver;
          queue_.push(std::move(e));
          break;
        case SimEventKind::Deliver:
          deliver(e.endpoint, Mail{e.from, e.bytes, std::move(e.message)});
          break;
        case SimEventKind::MasterDone:
          finishService();
          break;
        case SimEventKind::WorkerDone:
          finishWork(e.endpoint);
          break;
        case SimEventKind::Join:
          join(e.from != kMaster ? comeBack(e.from) : e.endpoint);
          break;
        case SimEventKind::Fail:
          // A machine that has not joined yet, or has finished, fails unnoticed.
          if (e.endpoint < master_.workerCount() &&
              !worker(e.endpoint).reactor.worker().stopped()) {
            die(e.endpoint, false);
          }
          break;
        case SimEventKind::Lost:
          reactor_.onPeerLost(e.endpoint, now_);
          deadline();
          break;
        case SimEventKind::Deadline:
          if (e.time == deadlineAt_) {
            deadlineAt_ = kNever;
            deadline();
          }
          break;
      }
    }
    return report();
  }

 private:
  int workerCount() const { return static_cast<int>(options_.speeds.size()); }
  int startingWorkers() const { return workerCount() - joinerCount(options_.joins); }
  SimWorker& worker(int w) { return workers_[static_cast<size_t>(w)]; }

  // The master's reactor: the lease and the checkpoints of the plan; heartbeats are the
  // virtual network's, counted from silences, and a checkpoint's cost is modelled.
  MasterReactorOptions reactorOptions() {
    MasterReactorOptions m;
    m.leaseSeconds = options_.workerTimeoutSeconds;
    m.heartbeatSeconds = kNever;
    m.checkpointEverySeconds = options_.checkpointEverySeconds;
    if (options_.checkpointEverySeconds > 0) {
      m.checkpoint = [this](const std::string&, double now) { return checkpoint(now); };
    }
    return m;
  }

  // What follows anything the master does outside a service (a join, a loss, a deadline):
  // its messages leave at once, losses close the master's silences towards the lost, and a
  // run with no worker left fails.
  void afterMaster() {
    send(kMaster, reactor_.takeOutbox());
    const auto& losses = master_.ledger().losses();
    for (; lossesSeen_ < losses.size(); ++lossesSeen_) {
      SimWorker& w = worker(losses[lossesSeen_].worker);
      if (w.lost) continue;
      w.lost = true;
      const uint64_t beats = beatsIn(w.lastFromMaster);  // the master stops heartbeating it
      reactor_.load().heartbeatsSent += beats;
      reactor_.load().sent += beats;
      heartbeatLoad(beats);
    }
    if (master_.failed()) {
      char text[128];
      std::snprintf(text, sizeof text,
                    "every worker was lost by %.1f s; the image cannot be finished", now_);
      throw std::runtime_error(text);
    }
    scheduleDeadline();
  }

  // The master's deadline: first the heartbeats of every live machine renew its lease (they
  // are counted, not sent), so only the silent ones run out.
  void deadline() {
    for (int w : master_.ledger().expired(now_, options_.workerTimeoutSeconds)) {
      if (!worker(w).dead) reactor_.onKeepAlive(w, now_);
    }
    reactor_.onDeadline(now_);
    afterMaster();
  }

  // Just after the reactor's next deadline (a lease runs out once it is exceeded).
  void scheduleDeadline() {
    const double due = reactor_.nextDeadline();
    if (!std::isfinite(due)) return;
    const double at = std::nextafter(std::max(due, now_), kNever);
    if (at >= deadlineAt_) return;  // one comes sooner; it schedules the next
    deadlineAt_ = at;
    SimEvent e;
    e.time = at;
    e.kind = SimEventKind::Deadline;
    queue_.push(std::move(e));
  }

  // A worker joins (--join-at, or a repaired machine): the master admits it as it does a
  // PeerJoined notice.
  void join(int id) {
    SimWorker& w = worker(id);
    w.lastToMaster = now_;  // its silences start when it joins
    w.lastFromMaster = now_;
    w.reactor.begin(now_);
    reactor_.onPeerJoined(id, now_);
    afterMaster();
  }

  // --mtbf and --fail-share: the machines' failure times, drawn once (deterministic per seed).
  void scheduleFailures() {
    std::mt19937_64 random(options_.seed);
    const int starting = startingWorkers();
    if (options_.mtbfSeconds > 0) {
      std::exponential_distribution<double> lifetime(1.0 / options_.mtbfSeconds);
      for (int w = 0; w < starting; ++w) pushFailure(w, lifetime(random));
    }
    if (options_.failShare > 0) {
      std::vector<int> order(static_cast<size_t>(starting));
      std::iota(order.begin(), order.end(), 0);
      std::shuffle(order.begin(), order.end(), random);
      const auto count = static_cast<size_t>(std::llround(options_.failShare * starting));
      for (size_t i = 0; i < count; ++i) pushFailure(order[i], options_.failAtSeconds);
    }
  }

  void pushFailure(int w, double at) {
    SimEvent fail;
    fail.time = at;
    fail.kind = SimEventKind::Fail;
    fail.endpoint = w;
    queue_.push(std::move(fail));
  }

  // A repaired machine, once worker `was`, joins as a new worker with its speed; it may fail
  // again. Returns its endpoint.
  int comeBack(int was) {
    const SimWorker& old = worker(was);
    const int id = static_cast<int>(workers_.size());
    const double speed = old.speed, speedIndex = old.speedIndex;
    workers_.emplace_back(id, options_, log_, speed, speedIndex);
    net_.addWorker();
    if (options_.mtbfSeconds > 0) {
      std::exponential_distribution<double> lifetime(1.0 / options_.mtbfSeconds);
      pushFailure(id, now_ + lifetime(repairRandom_));
    }
    return id;
  }

  // Worker `id` fails now. A crash drops its connection: the master hears of it one latency
  // later. Otherwise it goes silent: the master last heard its last message, or the last
  // heartbeat it sent before it failed, and its lease runs out a lease after that.
  void die(int id, bool crash) {
    SimWorker& w = worker(id);
    if (w.dead) return;
    w.dead = true;
    if (!crash && options_.repairSeconds > 0) {
      SimEvent back;
      back.time = now_ + options_.repairSeconds;
      back.kind = SimEventKind::Join;
      back.from = id;  // the machine it was
      queue_.push(std::move(back));
    }
    const double lastWord = w.lastToMaster;
    const uint64_t beats = beatsIn(w.lastToMaster);  // its silence ends here
    reactor_.load().heartbeatsReceived += beats;
    reactor_.load().received += beats;
    heartbeatLoad(beats);
    if (crash) {
      SimEvent lost;
      lost.time = now_ + options_.network.latencySeconds;
      lost.kind = SimEventKind::Lost;
      lost.endpoint = id;
      queue_.push(std::move(lost));
      return;
    }
    const double lastBeat = lastWord + static_cast<double>(beats) * options_.heartbeatSeconds();
    reactor_.onKeepAlive(id, lastBeat + options_.network.latencySeconds);
    scheduleDeadline();
  }

  // The master writes a checkpoint (MasterReactor asks): after the message it is handling,
  // if any, it takes none for the time the write lasts. Returns when the write ends.
  double checkpoint(double now) {
    const double seconds =
        options_.checkpointSecondsPerPixel * static_cast<double>(master_.doneCount());
    MasterLoad& load = reactor_.load();
    ++load.checkpoints;
    load.checkpointSeconds += seconds;
    load.busySeconds += seconds;
    double ends = now + seconds;
    if (masterBusy_) {
      checkpointDebt_ += seconds;  // finishService pays it
      ends = std::max(ends, now + checkpointDebt_);
    } else {
      masterBusy_ = true;
      pushMasterDone(ends);
    }
    return ends;
  }

  void pushMasterDone(double at) {
    SimEvent done;
    done.time = at;
    done.kind = SimEventKind::MasterDone;
    queue_.push(std::move(done));
  }

  // The heartbeats that a silence between `last` and `now` holds (one per interval), and the
  // silence restarts now.
  uint64_t beatsIn(double& last) {
    const double gap = now_ - last;
    last = now_;
    const double h = options_.heartbeatSeconds();
    return gap >= h ? static_cast<uint64_t>(gap / h) : 0;
  }

  // Heartbeats cost the master half a service each; those of a silence are worked off in its
  // idle time first (startService).
  void heartbeatLoad(uint64_t beats) {
    const double seconds = 0.5 * options_.network.masterServiceSeconds * static_cast<double>(beats);
    reactor_.load().busySeconds += seconds;
    heartbeatDebt_ += seconds;
  }

  void countHeartbeats(int from, const Envelope& e) {
    MasterLoad& load = reactor_.load();
    if (from == kMaster) {
      if (e.to < 0) return;
      const uint64_t beats = beatsIn(worker(e.to).lastFromMaster);
      load.heartbeatsSent += beats;
      load.sent += beats;  // the message itself was counted by the reactor
      heartbeatLoad(beats);
    } else if (e.to == kMaster) {
      const uint64_t beats = beatsIn(worker(from).lastToMaster);
      load.heartbeatsReceived += beats;
      load.received += beats;  // the message itself is counted when the master takes it
      heartbeatLoad(beats);
    }
  }

  // At the end: the heartbeats of the silences still open, up to the last result.
  void closeSilences() {
    MasterLoad& load = reactor_.load();
    for (int w = 0; w < master_.workerCount(); ++w) {  // those that joined in time
      SimWorker& sw = worker(w);
      if (sw.lost) continue;  // both silences closed: when it failed, and when the master knew
      const uint64_t out = beatsIn(sw.lastFromMaster);
      load.heartbeatsSent += out;
      load.sent += out;
      uint64_t in = 0;
      if (!sw.dead) {  // a failed worker's silence closed when it failed
        in = beatsIn(sw.lastToMaster);
        load.heartbeatsReceived += in;
        load.received += in;
      }
      heartbeatLoad(out + in);
    }
  }

  void send(int from, Outbox out) {
    for (Envelope& e : out) {
      countHeartbeats(from, e);
      const uint64_t bytes = messageBytes(e.message);
      log_.add({EventKind::MessageSent, from, now_, now_, 0, bytes, e.to, messageName(e.message)});
      SimEvent reach;
      reach.time = net_.depart(from, bytes, now_);
      reach.kind = SimEventKind::Reach;
      reach.endpoint = e.to;
      reach.from = from;
      reach.bytes = bytes;
      reach.message = std::move(e.message);
      queue_.push(std::move(reach));
    }
  }

  void deliver(int to, Mail mail) {
    if (to == kMaster) {
      masterInbox_.push_back(std::move(mail));
      if (!masterBusy_) startService();
      return;
    }
    SimWorker& w = worker(to);
    if (w.dead || w.reactor.worker().stopped()) return;  // it reads nothing more
    w.reactor.onMessage(mail.from, std::move(mail.message), mail.bytes, now_);
    send(to, w.reactor.takeOutbox());
    if (!w.reactor.computing()) advance(to);
  }

  // The master takes the next message: it handles it at once, then stays busy for the
  // service time; its replies leave when it is done.
  void startService() {
    PRT_CHECK(!masterBusy_ && !masterInbox_.empty());
    const Mail mail = std::move(masterInbox_.front());
    masterInbox_.pop_front();
    reactor_.onMessage(mail.from, mail.message, mail.bytes, now_);
    masterOut_ = reactor_.takeOutbox();
    masterBusy_ = true;
    reactor_.load().busySeconds += options_.network.masterServiceSeconds;
    // Heartbeats that came in while it was idle were handled then; the rest delay this one.
    heartbeatDebt_ = std::max(0.0, heartbeatDebt_ - (now_ - idleSince_));
    pushMasterDone(now_ + options_.network.masterServiceSeconds + heartbeatDebt_);
    heartbeatDebt_ = 0;
  }

  // The run ends when the master has handled the last results, as in the drivers.
  void finishService() {
    masterBusy_ = false;
    idleSince_ = now_;
    send(kMaster, std::move(masterOut_));
    masterOut_.clear();
    if (master_.complete()) {
      finished_ = true;
    } else if (checkpointDebt_ > 0) {  // a checkpoint came meanwhile: written now
      masterBusy_ = true;
      pushMasterDone(now_ + checkpointDebt_);
      checkpointDebt_ = 0;
    } else if (!masterInbox_.empty()) {
      startService();
    }
  }

  // What the reactor does next: set up (the speed index's time), a batch (its cost at the
  // worker's speed), or fail as injected.
  void advance(int id) {
    SimWorker& w = worker(id);
    if (w.dead) return;
    double seconds = 0;
    switch (w.reactor.next(now_)) {
      case WorkerStep::Setup:
        w.inSetup = true;
        seconds = options_.speedIndexRun && !options_.oracleSpeedIndex ? w.speedIndex : 0.0;
        break;
      case WorkerStep::Batch:
        w.inSetup = false;
        seconds = workDoneAt(now_, costs_.seconds(w.reactor.batch()) + options_.batchOverheadSeconds,
                             w.speed, w.speedChanges) -
                  now_;
        break;
      case WorkerStep::Crash:  // as the worker loop fails
        die(id, true);
        return;
      case WorkerStep::Hang:
        die(id, false);
        return;
      case WorkerStep::Wait:
      case WorkerStep::Stop:
        return;
    }
    w.workStart = now_;
    SimEvent done;
    done.time = now_ + seconds;
    done.kind = SimEventKind::WorkerDone;
    done.endpoint = id;
    queue_.push(std::move(done));
  }

  void finishWork(int id) {
    SimWorker& w = worker(id);
    if (w.dead) return;  // it failed mid-batch: the batch is lost with it
    if (w.inSetup) {
      w.reactor.onSetupDone(now_,
                            options_.speedIndexRun ? w.speedIndex : options_.baseSpeedIndexSeconds,
                            std::nullopt, {});
    } else {
      w.reactor.batch().forEach([&](uint64_t pixel) { owner_[pixel] = id; });
      w.reactor.onBatchDone(now_, {}, now_ - w.workStart, 0);
    }
    send(id, w.reactor.takeOutbox());
    advance(id);
  }

  SimulatedRun report() {
    closeSilences();
    RunInfo info;
    info.driver = "simulated";
    info.strategy = options_.strategy;
    info.width = costs_.width();
    info.height = costs_.height();
    info.masterSpeedIndexSeconds = options_.baseSpeedIndexSeconds;
    info.serialSeconds = costs_.totalSeconds();
    info.speedIndexRun = options_.speedIndexRun;
    std::vector<Event> events = std::move(log_.events);  // everyone's, as they happened
    auto& summaries = reactor_.summaries();
    for (int w = 0; w < master_.workerCount(); ++w) {
      summaries[static_cast<size_t>(w)] = worker(w).reactor.summary(1, 1.0 / worker(w).speed);
    }
    recordMaster(info, {master_, summaries, events, true, options_.workerTimeoutSeconds,
                        options_.heartbeatSeconds(), nullptr});
    MasterLoad load = reactor_.load();
    load.basis = "modelled_service";
    info.master = load;
    SimulatedRun run;
    run.report = makeReport(info, events, now_);
    run.events = std::move(events);
    run.simulationEvents = queue_.scheduled();
    run.owner = std::move(owner_);
    return run;
  }

  const CostMap& costs_;
  const SimulationOptions& options_;
  EventQueue queue_;
  NetworkModel net_;
  Master master_;
  EventLog log_;  // every event of the run, the master's and the workers', in order
  MasterReactorOptions reactorOptions_;
  MasterReactor reactor_;
  std::deque<SimWorker> workers_;
  std::vector<int32_t> owner_ = std::vector<int32_t>(costs_.pixelCount(), -1);
  std::deque<Mail> masterInbox_;
  bool masterBusy_ = false;
  Outbox masterOut_;
  double heartbeatDebt_ = 0;   // heartbeat service not yet worked off
  double checkpointDebt_ = 0;  // a checkpoint due while the master was busy
  double idleSince_ = 0;       // when the master last finished a service
  double deadlineAt_ = kNever;  // the master's next deadline event
  size_t lossesSeen_ = 0;
  double now_ = 0;
  bool finished_ = false;
  std::mt19937_64 repairRandom_{options_.seed ^ 0x9e3779b97f4a7c15ull};  // repaired lifetimes
};

}  // namespace

SimulatedRun simulate(const CostMap& costs, const SimulationOptions& options) {
  validateSimulationOptions(options, costs.pixelCount());
  return Simulation(costs, options).run();
}

}  // namespace prt
