#include "drive/local_driver.h"

#include <atomic>
#include <chrono>
#include <memory>
#include <stdexcept>
#include <thread>

#include "cluster/master.h"
#include "cluster/worker.h"
#include "drive/mailbox.h"
#include "drive/worker_engine.h"

namespace prt {
namespace {

using Clock = std::chrono::steady_clock;

struct Network {
  Clock::time_point start = Clock::now();
  Mailbox master;
  std::vector<std::unique_ptr<Mailbox>> workers;
  std::atomic<bool> shutdown{false};

  double now() const { return std::chrono::duration<double>(Clock::now() - start).count(); }
  Mailbox& boxOf(int endpoint) {
    return endpoint == kMaster ? master : *workers[static_cast<size_t>(endpoint)];
  }
  void send(int from, const Outbox& out, EventLog& log) {
    for (const Envelope& e : out) {
      Bytes bytes = encode(e.message);
      log.add({EventKind::MessageSent, from, now(), now(), 0, bytes.size(), e.to,
               messageName(e.message)});
      boxOf(e.to).push(Mail{from, std::move(bytes), false});
    }
  }
};

struct WorkerOutcome {
  EventLog log;
  uint64_t rays = 0;
  uint64_t tasksReceived = 0;
};

void runWorker(int id, const ParallelOptions& options, Network& net, WorkerOutcome& outcome) {
  Worker worker(id, WorkerOptions{options.batchPixels});
  WorkerEngine engine(options.slowdownOf(id), options.speedIndexKind, options.speedIndexDiscs,
                      options.slowdownChangesOf(id));
  Mailbox& box = *net.workers[static_cast<size_t>(id)];
  const FaultInjection* fault = nullptr;
  for (const FaultInjection& f : options.faults) {
    if (f.worker == id) fault = &f;
  }
  uint64_t rendered = 0;
  auto fail = [&] {
    if (fault->kind == FaultInjection::Kind::Crash) {
      net.master.push(Mail{id, {}, true});
      return;
    }
    while (!net.shutdown) std::this_thread::sleep_for(std::chrono::milliseconds(5));
  };
  while (!worker.stopped() && !net.shutdown) {
    const bool busy = worker.hasWork() || worker.needsSetup();
    std::optional<Mail> mail = busy ? box.tryPop() : box.pop(std::chrono::milliseconds(50));
    if (mail) {
      const Message m = decode(mail->bytes);
      outcome.log.add({EventKind::MessageReceived, id, net.now(), net.now(), 0,
                       mail->bytes.size(), mail->from, messageName(m)});
      net.send(id, worker.onMessage(mail->from, m), outcome.log);
      continue;  // read all waiting mail before computing
    }
    if (worker.needsSetup()) {
      const double t0 = net.now();
      engine.load(worker.scene());
      const double speedIndex = engine.measureSpeedIndex();
      outcome.log.add({EventKind::Setup, id, t0, net.now(), 0, 0, 0, ""});
      net.send(id, worker.setupDone(speedIndex), outcome.log);
    } else if (worker.hasWork()) {
      if (fault && rendered >= fault->afterPixels) return fail();
      const TaskSet batch = worker.nextBatch();
      const double t0 = net.now();
      double seconds = 0;
      std::vector<float> rgb = engine.render(batch, seconds, outcome.rays);
      outcome.log.add({EventKind::Compute, id, t0, t0 + seconds, batch.size(), 0, 0, ""});
      rendered += batch.size();
      net.send(id, worker.batchDone(batch, std::move(rgb), seconds), outcome.log);
    }
  }
  outcome.tasksReceived = worker.tasksReceived();
}

}  // namespace

ParallelRun renderLocal(const LocalRunRequest& request) {
  const Scene& scene = request.scene;
  const ParallelOptions& options = request.options;
  const uint64_t pixels = static_cast<uint64_t>(scene.image.width) * scene.image.height;
  validateParallelOptions(options, pixels);
  const int n = options.workers;

  Network net;
  for (int w = 0; w < n; ++w) net.workers.push_back(std::make_unique<Mailbox>());
  ImageAssembler assembler(scene.image.width, scene.image.height);
  Master master(makeStrategy(options.strategy, options.strategyOptions), n, pixels,
                makeSceneMessage(scene, request.settings),
                [&](int w, const TaskSet& t, const std::vector<float>& rgb) {
                  assembler.add(w, t, rgb);
                });
  EventLog masterLog;
  std::vector<WorkerOutcome> outcomes(static_cast<size_t>(n));
  std::vector<std::thread> threads;
  net.start = Clock::now();
  for (int w = 0; w < n; ++w) {
    threads.emplace_back(runWorker, w, std::cref(options), std::ref(net),
                         std::ref(outcomes[static_cast<size_t>(w)]));
  }
  // Silence is counted from the last exchange either way: a worker just handed new tasks after
  // a long wait owes nothing yet.
  std::vector<double> lastContact(static_cast<size_t>(n), 0.0);
  auto sendFromMaster = [&](const Outbox& out) {
    for (const Envelope& e : out) lastContact[static_cast<size_t>(e.to)] = net.now();
    net.send(kMaster, out, masterLog);
  };
  auto declareLost = [&](int w) {
    masterLog.add({EventKind::WorkerLost, w, net.now(), net.now(), 0, 0, 0, ""});
    sendFromMaster(master.onWorkerLost(w));
  };

  sendFromMaster(master.start());
  std::string failure;
  while (!master.complete()) {
    if (master.failed()) {
      failure = "every worker was lost; the image cannot be finished";
      break;
    }
    std::optional<Mail> mail = net.master.pop(std::chrono::milliseconds(20));
    const double now = net.now();
    if (mail) {
      lastContact[static_cast<size_t>(mail->from)] = now;
      if (mail->lost) {
        declareLost(mail->from);
      } else {
        const Message m = decode(mail->bytes);
        masterLog.add({EventKind::MessageReceived, kMaster, now, now, 0, mail->bytes.size(),
                       mail->from, messageName(m)});
        sendFromMaster(master.onMessage(mail->from, m));
      }
    }
    for (int w = 0; w < n; ++w) {
      if (master.owesAnswer(w) &&
          now - lastContact[static_cast<size_t>(w)] > options.workerTimeoutSeconds) {
        declareLost(w);
      }
    }
  }
  const double elapsed = net.now();
  net.shutdown = true;
  for (std::thread& t : threads) t.join();
  if (!failure.empty()) throw std::runtime_error(failure);

  ParallelRun run;
  run.events = std::move(masterLog.events);
  RunInfo info;
  info.driver = "local";
  info.strategy = options.strategy;
  info.width = scene.image.width;
  info.height = scene.image.height;
  info.samplesPerPixel = request.settings.samplesPerPixel;
  info.drtRate = request.settings.drtRate;
  info.masterSpeedIndexSeconds = request.masterSpeedIndexSeconds;
  info.workerSpeedIndexSeconds = master.speedIndices();
  info.serialSeconds = request.serialSeconds;
  info.speedIndexRun = options.speedIndexKind != SpeedIndexKind::None;
  for (int w = 0; w < n; ++w) {
    const WorkerOutcome& o = outcomes[static_cast<size_t>(w)];
    run.events.insert(run.events.end(), o.log.events.begin(), o.log.events.end());
    info.slowdowns.push_back(options.slowdownOf(w));
    info.tasksReceived.push_back(o.tasksReceived);
    info.rays += o.rays;
  }
  run.report = makeReport(info, run.events, elapsed);
  run.image = std::move(assembler.image());
  run.owner = std::move(assembler.owner());
  return run;
}

}  // namespace prt
