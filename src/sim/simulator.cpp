#include "sim/simulator.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <deque>
#include <numeric>
#include <optional>
#include <random>
#include <stdexcept>
#include <string>
#include <utility>

#include "cluster/master.h"
#include "cluster/worker.h"
#include "core/check.h"
#include "core/input_error.h"
#include "sim/event_queue.h"
#include "sim/worker_speeds.h"

namespace prt {
namespace {

struct Mail {
  int from = kMaster;
  uint64_t bytes = 0;
  Message message;
};

struct SimWorker {
  SimWorker(int id, WorkerOptions options, double speed_, double speedIndex_)
      : machine(id, options), speed(speed_), speedIndex(speedIndex_) {}
  Worker machine;
  double speed;       // relative to the cost map's machine
  double speedIndex;  // seconds; what it measures during setup
  std::vector<SpeedChange> speedChanges;  // its own, sorted
  bool busy = false;  // computing (setup or a batch): mail waits in the mailbox
  double lastToMaster = 0;    // when it last sent the master anything (heartbeats counted)
  double lastFromMaster = 0;  // when the master last sent it anything (heartbeats counted)
  bool inSetup = false;
  bool dead = false;      // failed: it reads, computes and sends nothing more
  bool crashed = false;   // its connection dropped (rather than going silent)
  bool lost = false;      // the master has been told
  double lastHeard = 0;   // failed: when the master last heard from it (heartbeats count)
  uint64_t rendered = 0;  // pixels rendered so far (for --inject-fault)
  std::optional<FaultInjection> fault;
  double workStart = 0;
  TaskSet batch;
  std::deque<Mail> mailbox;
};

MasterOptions masterOptions(const SimulationOptions& options) {
  MasterOptions m;
  m.endgame = options.endgame;
  return m;
}

SceneMsg sceneMessage(const SimulationOptions& options) {
  SceneMsg scene{std::string(options.sceneBytes, ' '), 1, 1};
  if (options.frames > 1) {
    scene.frames.last = static_cast<int64_t>(options.frames) - 1;
    scene.frames.animated = true;
  }
  return scene;
}

class Simulation {
 public:
  Simulation(const CostMap& costs, const SimulationOptions& options)
      : costs_(costs),
        options_(options),
        net_(workerCount(), options.network),
        master_(makeStrategy(options.strategy, options.strategyOptions), startingWorkers(),
                costs.pixelCount(), sceneMessage(options), nullptr,
                masterOptions(options)) {
    for (int w = 0; w < workerCount(); ++w) {
      const auto i = static_cast<size_t>(w);
      const double speed = options.speeds[i];
      const double speedIndex = options.speedIndexSeconds.empty()
                                    ? options.baseSpeedIndexSeconds / speed
                                    : options.speedIndexSeconds[i];
      workers_.emplace_back(w, WorkerOptions{options.batchPixels, options.batchSeconds}, speed,
                            speedIndex);
      workers_.back().speedChanges = changesOf(options.speedChanges, w);
      for (const FaultInjection& f : options.faults) {
        if (f.worker == w) workers_.back().fault = f;
      }
    }
  }

  SimulatedRun run() {
    send(kMaster, master_.start(now_));
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
    if (options_.checkpointEverySeconds > 0) pushCheckpoint(options_.checkpointEverySeconds);
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
          if (e.from != kMaster) e.endpoint = comeBack(e.from);  // a repaired machine
          log_.add({EventKind::WorkerJoined, e.endpoint, now_, now_, 0, 0, kMaster, ""});
          worker(e.endpoint).lastToMaster = now_;  // its silences start when it joins
          worker(e.endpoint).lastFromMaster = now_;
          send(kMaster, master_.onWorkerJoined(e.endpoint, now_));
          break;
        case SimEventKind::Fail:
          // A machine that has not joined yet, or has finished, fails unnoticed.
          if (e.endpoint < master_.workerCount() && !worker(e.endpoint).machine.stopped()) {
            die(e.endpoint, false);
          }
          break;
        case SimEventKind::Lost:
          lose(e.endpoint);
          break;
        case SimEventKind::Checkpoint:
          checkpoint();
          break;
      }
    }
    return report();
  }

 private:
  int workerCount() const { return static_cast<int>(options_.speeds.size()); }
  int startingWorkers() const { return workerCount() - joinerCount(options_.joins); }
  SimWorker& worker(int w) { return workers_[static_cast<size_t>(w)]; }

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
    workers_.emplace_back(id, WorkerOptions{options_.batchPixels, options_.batchSeconds}, speed,
                          speedIndex);
    net_.addWorker();
    if (options_.mtbfSeconds > 0) {
      std::exponential_distribution<double> lifetime(1.0 / options_.mtbfSeconds);
      pushFailure(id, now_ + lifetime(repairRandom_));
    }
    return id;
  }

  // Worker `id` fails now. A crash drops its connection: the master hears of it one latency
  // later. Otherwise it goes silent, and the master finds out a lease after it last heard from
  // it: its last message, or the last heartbeat it sent before it failed.
  void die(int id, bool crash) {
    SimWorker& w = worker(id);
    if (w.dead) return;
    w.dead = true;
    w.crashed = crash;
    w.busy = false;
    w.mailbox.clear();
    if (!crash && options_.repairSeconds > 0) {
      SimEvent back;
      back.time = now_ + options_.repairSeconds;
      back.kind = SimEventKind::Join;
      back.from = id;  // the machine it was
      queue_.push(std::move(back));
    }
    const double lastWord = w.lastToMaster;
    const uint64_t beats = beatsIn(w.lastToMaster);  // its silence ends here
    load_.heartbeatsReceived += beats;
    load_.received += beats;
    heartbeatLoad(beats);
    const double lastHeard = lastWord + static_cast<double>(beats) * options_.heartbeatSeconds();
    w.lastHeard = lastHeard + options_.network.latencySeconds;
    SimEvent lost;
    lost.time = crash ? now_ + options_.network.latencySeconds
                      : std::max(now_, lastHeard + options_.network.latencySeconds +
                                           options_.workerTimeoutSeconds);
    lost.kind = SimEventKind::Lost;
    lost.endpoint = id;
    queue_.push(std::move(lost));
  }

  void lose(int id) {
    SimWorker& w = worker(id);
    if (w.lost || finished_) return;
    w.lost = true;
    const uint64_t beats = beatsIn(w.lastFromMaster);  // the master stops heartbeating it
    load_.heartbeatsSent += beats;
    load_.sent += beats;
    heartbeatLoad(beats);
    char reason[64];
    if (w.crashed) {
      std::snprintf(reason, sizeof reason, "connection dropped");
    } else {
      std::snprintf(reason, sizeof reason, "silent for %.1f s", options_.workerTimeoutSeconds);
    }
    send(kMaster, master_.onWorkerLost(id, now_, reason));
    if (master_.failed()) {
      char text[128];
      std::snprintf(text, sizeof text,
                    "every worker was lost by %.1f s; the image cannot be finished", now_);
      throw std::runtime_error(text);
    }
  }

  // The master writes a checkpoint: after the message it is handling, if any, it takes none
  // for the time the write lasts; the next one comes an interval after this one ends.
  void checkpoint() {
    const double seconds =
        options_.checkpointSecondsPerPixel * static_cast<double>(master_.doneCount());
    ++load_.checkpoints;
    load_.checkpointSeconds += seconds;
    load_.busySeconds += seconds;
    double ends = now_ + seconds;
    if (masterBusy_) {
      checkpointDebt_ += seconds;  // finishService pays it
      ends = std::max(ends, now_ + checkpointDebt_);
    } else {
      masterBusy_ = true;
      pushMasterDone(ends);
    }
    pushCheckpoint(ends + options_.checkpointEverySeconds);
  }

  void pushCheckpoint(double at) {
    SimEvent checkpoint;
    checkpoint.time = at;
    checkpoint.kind = SimEventKind::Checkpoint;
    queue_.push(std::move(checkpoint));
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
    load_.busySeconds += seconds;
    heartbeatDebt_ += seconds;
  }

  void countHeartbeats(int from, const Envelope& e) {
    if (from == kMaster) {
      if (e.to < 0) return;
      const uint64_t beats = beatsIn(worker(e.to).lastFromMaster);
      load_.heartbeatsSent += beats;
      load_.sent += beats + 1;
      heartbeatLoad(beats);
    } else if (e.to == kMaster) {
      const uint64_t beats = beatsIn(worker(from).lastToMaster);
      load_.heartbeatsReceived += beats;
      load_.received += beats;  // the message itself is counted when the master takes it
      heartbeatLoad(beats);
    }
  }

  // At the end: the heartbeats of the silences still open, up to the last result.
  void closeSilences() {
    for (int w = 0; w < workerCount(); ++w) {
      SimWorker& sw = worker(w);
      if (w >= master_.workerCount()) continue;  // never joined in time
      if (sw.dead) {  // its own silence closed when it failed; the master's, when it knew
        if (!sw.lost) {
          const uint64_t out = beatsIn(sw.lastFromMaster);
          load_.heartbeatsSent += out;
          load_.sent += out;
          heartbeatLoad(out);
        }
        continue;
      }
      const uint64_t out = beatsIn(sw.lastFromMaster);
      load_.heartbeatsSent += out;
      load_.sent += out;
      const uint64_t in = beatsIn(sw.lastToMaster);
      load_.heartbeatsReceived += in;
      load_.received += in;
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

  void logReceived(int at, const Mail& mail) {
    log_.add({EventKind::MessageReceived, at, now_, now_, 0, mail.bytes, mail.from,
              messageName(mail.message)});
  }

  void deliver(int to, Mail mail) {
    if (to == kMaster) {
      masterInbox_.push_back(std::move(mail));
      if (!masterBusy_) startService();
      return;
    }
    SimWorker& w = worker(to);
    if (w.machine.stopped() || w.dead) return;  // a stopped or failed worker reads nothing more
    w.mailbox.push_back(std::move(mail));
    if (!w.busy) advance(to);
  }

  // The master takes the next message: it handles it at once, then stays busy for the
  // service time; its replies leave when it is done.
  void startService() {
    PRT_CHECK(!masterBusy_ && !masterInbox_.empty());
    const Mail mail = std::move(masterInbox_.front());
    masterInbox_.pop_front();
    logReceived(kMaster, mail);
    masterOut_ = master_.onMessage(mail.from, mail.message, now_);
    masterBusy_ = true;
    ++load_.received;
    load_.busySeconds += options_.network.masterServiceSeconds;
    // Heartbeats that came in while it was idle were handled then; the rest delay this one.
    heartbeatDebt_ = std::max(0.0, heartbeatDebt_ - (now_ - idleSince_));
    pushMasterDone(now_ + options_.network.masterServiceSeconds + heartbeatDebt_);
    heartbeatDebt_ = 0;
  }

  // The run ends when the master has handled the last results, as in the local driver.
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

  // The local driver's worker loop: read every waiting message, then set up or render the
  // next batch; with nothing to do, wait for mail.
  void advance(int id) {
    SimWorker& w = worker(id);
    while (!w.mailbox.empty() && !w.machine.stopped()) {
      const Mail mail = std::move(w.mailbox.front());
      w.mailbox.pop_front();
      logReceived(id, mail);
      send(id, w.machine.onMessage(mail.from, mail.message));
    }
    if (w.machine.stopped() || w.dead) return;
    double seconds = 0;
    if (w.fault && !w.machine.needsSetup() && w.machine.hasWork() &&
        w.rendered >= w.fault->afterPixels) {
      die(id, w.fault->kind == FaultInjection::Kind::Crash);  // as the worker loop fails
      return;
    }
    if (w.machine.needsSetup()) {
      w.inSetup = true;
      seconds = options_.speedIndexRun && !options_.oracleSpeedIndex ? w.speedIndex : 0.0;
    } else if (w.machine.hasWork()) {
      w.inSetup = false;
      w.batch = w.machine.nextBatch();
      seconds = workDoneAt(now_, costs_.seconds(w.batch) + options_.batchOverheadSeconds, w.speed,
                           w.speedChanges) -
                now_;
    } else {
      return;
    }
    w.busy = true;
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
    w.busy = false;
    if (w.inSetup) {
      log_.add({EventKind::Setup, id, w.workStart, now_, 0, 0, 0, ""});
      send(id, w.machine.setupDone(options_.speedIndexRun ? w.speedIndex
                                                          : options_.baseSpeedIndexSeconds));
    } else {
      log_.add({EventKind::Compute, id, w.workStart, now_, w.batch.size(), 0, 0, ""});
      w.batch.forEach([&](uint64_t pixel) { owner_[pixel] = id; });
      w.rendered += w.batch.size();
      send(id, w.machine.batchDone(w.batch, now_ - w.workStart));
    }
    advance(id);
  }

  SimulatedRun report() {
    SimulatedRun run;
    RunInfo info;
    info.driver = "simulated";
    info.strategy = options_.strategy;
    info.width = costs_.width();
    info.height = costs_.height();
    info.masterSpeedIndexSeconds = options_.baseSpeedIndexSeconds;
    info.workerSpeedIndexSeconds = master_.speedIndices();
    info.serialSeconds = costs_.totalSeconds();
    info.speedIndexRun = options_.speedIndexRun;
    info.faults.endgameCopies = master_.endgameCopies();
    info.faults.heartbeatSeconds = options_.heartbeatSeconds();
    info.faults.workerTimeoutSeconds = options_.workerTimeoutSeconds;
    for (const LostWorker& l : master_.ledger().losses()) {
      info.faults.lostWorkers.push_back({l.worker, l.atSeconds, l.reason, l.unfinished,
                                         worker(l.worker).lastHeard});
    }
    info.faults.reissuedTasks = master_.ledger().reissuedTasks();
    closeSilences();
    load_.basis = "modelled_service";
    info.master = load_;
    info.faults.duplicatePixels = master_.ledger().duplicates();
    for (int w = 0; w < master_.workerCount(); ++w) {  // those that joined in time included
      info.slowdowns.push_back(1.0 / worker(w).speed);
      info.tasksReceived.push_back(worker(w).machine.tasksReceived());
      info.joinedAt.push_back(master_.ledger().joinedAt(w));
    }
    run.report = makeReport(info, log_.events, now_);
    run.events = std::move(log_.events);
    run.simulationEvents = queue_.scheduled();
    run.owner = std::move(owner_);
    return run;
  }

  const CostMap& costs_;
  const SimulationOptions& options_;
  EventQueue queue_;
  NetworkModel net_;
  EventLog log_;
  Master master_;
  std::vector<SimWorker> workers_;
  std::vector<int32_t> owner_ = std::vector<int32_t>(costs_.pixelCount(), -1);
  std::deque<Mail> masterInbox_;
  bool masterBusy_ = false;
  Outbox masterOut_;
  MasterLoad load_;
  double heartbeatDebt_ = 0;  // heartbeat service not yet worked off
  double checkpointDebt_ = 0;  // a checkpoint due while the master was busy
  double idleSince_ = 0;      // when the master last finished a service
  double now_ = 0;
  bool finished_ = false;
  std::mt19937_64 repairRandom_{options_.seed ^ 0x9e3779b97f4a7c15ull};  // repaired lifetimes
};

}  // namespace

void validateSimulationOptions(const SimulationOptions& o, uint64_t pixelCount) {
  const auto workers = o.speeds.size();
  if (workers < 1) throw InputError("--workers must be at least 1");
  validateWorkerSpeeds(o.speeds, static_cast<int>(workers));
  validateRunPlan(o, static_cast<int>(workers));
  const int joiners = o.joinerCount();
  if (static_cast<size_t>(joiners) >= workers) {
    throw InputError("--join-at adds " + std::to_string(joiners) + " workers but the run has " +
                     std::to_string(workers) + " in all: at least one must start");
  }
  // The starting workers, as the thread driver counts them: joiners that find nothing left
  // simply get nothing.
  const size_t starting = workers - static_cast<size_t>(joiners);
  if (starting > pixelCount) {
    throw InputError("more workers (" + std::to_string(starting) + ") than pixels (" +
                     std::to_string(pixelCount) + ")");
  }
  if (!(o.batchSeconds >= 0 && o.batchSeconds <= 60)) {
    throw InputError("--batch-seconds must be in [0, 60] (0: batches of --batch pixels)");
  }
  if (!(o.batchOverheadSeconds >= 0) || !std::isfinite(o.batchOverheadSeconds)) {
    throw InputError("--batch-overhead-us must be finite and >= 0");
  }
  if (!(o.baseSpeedIndexSeconds > 0) || !std::isfinite(o.baseSpeedIndexSeconds)) {
    throw InputError("--speed-index must be a positive number of seconds");
  }
  if (!o.speedIndexSeconds.empty()) {
    if (o.speedIndexSeconds.size() != workers) {
      throw InputError("--speed-indices lists " + std::to_string(o.speedIndexSeconds.size()) +
                       " values for " + std::to_string(workers) + " workers; give one per worker");
    }
    for (double s : o.speedIndexSeconds) {
      if (!(s > 0) || !std::isfinite(s)) {
        throw InputError("--speed-indices values must be positive numbers of seconds");
      }
    }
  }
  for (const SpeedChange& c : o.speedChanges) {
    if (c.worker < 0 || static_cast<size_t>(c.worker) >= workers || !(c.value > 0) ||
        !std::isfinite(c.value) || !(c.atSeconds >= 0)) {
      throw InputError("--speed-at: worker " + std::to_string(c.worker) +
                       " is not one of the workers, or its time or speed is not positive");
    }
  }
  for (const FaultInjection& f : o.faults) {
    if (f.kind == FaultInjection::Kind::Corrupt) {
      throw InputError("--inject-fault: corrupt workers are not simulated (a simulated worker "
                       "renders no colours to check); crash and hang are");
    }
  }
  if (!(o.mtbfSeconds >= 0) || !std::isfinite(o.mtbfSeconds)) {
    throw InputError("--mtbf must be a positive number of seconds");
  }
  if (!(o.failShare >= 0 && o.failShare <= 1)) {
    throw InputError("--fail-share must be a fraction in [0, 1]");
  }
  if (!(o.repairSeconds >= 0) || !std::isfinite(o.repairSeconds)) {
    throw InputError("--repair must be a positive number of seconds");
  }
  if (o.repairSeconds > 0 && !o.joins.empty()) {
    throw InputError("--repair and --join-at cannot be combined: machines that come back join "
                     "after every other worker");
  }
  if (!(o.failAtSeconds >= 0) || !std::isfinite(o.failAtSeconds)) {
    throw InputError("--fail-at must be a time in seconds, 0 or more");
  }
  if (!(o.checkpointEverySeconds >= 0) || !std::isfinite(o.checkpointEverySeconds) ||
      !(o.checkpointSecondsPerPixel >= 0) || !std::isfinite(o.checkpointSecondsPerPixel)) {
    throw InputError("--checkpoint-every and the checkpoint's cost must be 0 or more seconds");
  }
  validateNetworkOptions(o.network);
}

SimulatedRun simulate(const CostMap& costs, const SimulationOptions& options) {
  validateSimulationOptions(options, costs.pixelCount());
  return Simulation(costs, options).run();
}

}  // namespace prt
