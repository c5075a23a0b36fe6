#include "mpi/mpi_driver.h"

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <stdexcept>
#include <string>
#include <thread>
#include <vector>

#include "cluster/master.h"
#include "cluster/worker.h"
#include "core/check.h"
#include "core/input_error.h"
#include "drive/worker_engine.h"
#include "mpi/mpi_comm.h"
#include "mpi/mpi_transport.h"
#include "mpi/worker_summary.h"

namespace prt {
namespace {

using namespace mpi_detail;
using Clock = std::chrono::steady_clock;

// Seconds since reset(), on this rank's steady clock.
class Stopwatch {
 public:
  void reset() { start_ = Clock::now(); }
  double now() const { return std::chrono::duration<double>(Clock::now() - start_).count(); }

 private:
  Clock::time_point start_ = Clock::now();
};

std::string rankName(int worker) {
  return "worker rank " + std::to_string(rankOf(worker)) + " (worker " + std::to_string(worker) +
         ")";
}

std::string seconds(double s) {
  char text[32];
  std::snprintf(text, sizeof text, "%.1f s", s);
  return text;
}

// Encodes, logs and sends every message of `out`, as the local driver's Network::send does.
void sendOutbox(MpiTransport& net, int from, const Outbox& out, EventLog& log,
                const Stopwatch& clock) {
  for (const Envelope& e : out) {
    Bytes bytes = encode(e.message);
    const double now = clock.now();
    log.add(
        {EventKind::MessageSent, from, now, now, 0, bytes.size(), e.to, messageName(e.message)});
    net.send(rankOf(e.to), kMessageTag, std::move(bytes));
  }
}

// The message for an MPI failure, naming the rank involved when MPI says which.
std::string describe(const MpiError& e) {
  if (e.rank() > 0) {
    return "MPI failed talking to " + rankName(endpointOf(e.rank())) + ": " + e.what();
  }
  if (e.rank() == 0) return std::string("MPI failed talking to the master (rank 0): ") + e.what();
  return std::string("MPI failed: ") + e.what();
}

// ---------------------------------------------------------------------------------------------
// Master (rank 0)

class MasterRank {
 public:
  MasterRank(MpiSession& session, const MpiRunRequest& request)
      : session_(session),
        request_(request),
        n_(request.options.workers),
        net_(session.comm().comm),
        assembler_(request.scene.image.width, request.scene.image.height),
        master_(makeStrategy(request.options.strategy, request.options.strategyOptions), n_,
                static_cast<uint64_t>(request.scene.image.width) * request.scene.image.height,
                makeSceneMessage(request.scene, request.settings),
                [this](int w, const TaskSet& t, const std::vector<float>& rgb) {
                  assembler_.add(w, t, rgb);
                }),
        lastContact_(static_cast<size_t>(n_), 0.0),
        summaries_(static_cast<size_t>(n_)) {}

  ParallelRun run() {
    double elapsed = 0;
    try {
      session_.comm().runStarted = true;
      clock_.reset();
      send(master_.start());
      while (!master_.complete()) {
        if (!receive(false)) pollPause();
        watchForSilence();
      }
      elapsed = clock_.now();
      collectSummaries();
    } catch (const MpiError& e) {
      session_.abort(describe(e) + "; aborting");
    } catch (const std::exception& e) {
      session_.abort(std::string(e.what()) + "; aborting");
    }
    return finish(elapsed);
  }

 private:
  // Silence is counted from the last exchange either way, as in the local driver: a worker
  // just handed new tasks after a long wait owes nothing yet.
  void send(const Outbox& out) {
    const double now = clock_.now();
    for (const Envelope& e : out) lastContact_[static_cast<size_t>(e.to)] = now;
    sendOutbox(net_, kMaster, out, log_, clock_);
  }

  // Handles one waiting message, if any; true if there was one. After the image is complete
  // (`draining`), protocol messages still in flight are logged and dropped, as the local
  // driver stops reading them.
  bool receive(bool draining) {
    std::optional<Packet> p = net_.poll();
    if (!p) return false;
    const double now = clock_.now();
    const int w = endpointOf(p->rank);
    if (w < 0 || w >= n_) {
      throw std::runtime_error("message from unexpected rank " + std::to_string(p->rank));
    }
    lastContact_[static_cast<size_t>(w)] = now;
    if (p->tag == kMessageTag) {
      Message m;
      try {
        m = decode(p->bytes);
      } catch (const std::exception& e) {
        throw std::runtime_error("bad message from " + rankName(w) + ": " + e.what());
      }
      log_.add(
          {EventKind::MessageReceived, kMaster, now, now, 0, p->bytes.size(), w, messageName(m)});
      if (!draining) send(master_.onMessage(w, m));
    } else if (p->tag == kSummaryTag && draining) {
      auto& slot = summaries_[static_cast<size_t>(w)];
      if (slot) throw std::runtime_error(rankName(w) + " sent two summaries");
      try {
        slot = decodeSummary(p->bytes);
      } catch (const std::exception& e) {
        throw std::runtime_error("bad summary from " + rankName(w) + ": " + e.what());
      }
      ++summariesIn_;
    } else if (p->tag == kSummaryTag) {
      throw std::runtime_error(rankName(w) + " stopped before the image was complete");
    } else {
      throw std::runtime_error("message with unexpected tag " + std::to_string(p->tag) + " from " +
                               rankName(w));
    }
    return true;
  }

  // A worker that owes the master an answer and stays silent is lost; under MPI the run
  // cannot recover it, so the job ends here.
  void watchForSilence() {
    const double now = clock_.now();
    for (int w = 0; w < n_; ++w) {
      const double silent = now - lastContact_[static_cast<size_t>(w)];
      if (master_.owesAnswer(w) && silent > request_.options.workerTimeoutSeconds) {
        session_.abort(rankName(w) + " stopped answering (no message for " + seconds(silent) +
                       "); aborting");
      }
    }
  }

  // Every worker got StopMsg with the last results; each answers with its summary.
  void collectSummaries() {
    const double stopped = clock_.now();
    while (summariesIn_ < n_) {
      if (!receive(true)) pollPause();
      const double now = clock_.now();
      for (int w = 0; w < n_; ++w) {
        const auto i = static_cast<size_t>(w);
        const double silent = now - std::max(lastContact_[i], stopped);
        if (!summaries_[i] && silent > request_.options.workerTimeoutSeconds) {
          session_.abort(rankName(w) + " sent no summary within " + seconds(silent) +
                         " of the image being complete; aborting");
        }
      }
    }
    if (!net_.flush(request_.options.workerTimeoutSeconds)) {
      throw std::runtime_error("messages to the workers were never delivered");
    }
  }

  ParallelRun finish(double elapsed) {
    const ParallelOptions& options = request_.options;
    ParallelRun run;
    run.events = log_.events;
    RunInfo info;
    info.driver = "mpi";
    info.strategy = options.strategy;
    info.width = request_.scene.image.width;
    info.height = request_.scene.image.height;
    info.samplesPerPixel = request_.settings.samplesPerPixel;
    info.drtRate = request_.settings.drtRate;
    info.masterSpeedIndexSeconds = request_.masterSpeedIndexSeconds;
    info.workerSpeedIndexSeconds = master_.speedIndices();
    info.serialSeconds = request_.serialSeconds;
    info.speedIndexRun = options.speedIndexKind != SpeedIndexKind::None;
    for (int w = 0; w < n_; ++w) {
      const WorkerSummary& s = *summaries_[static_cast<size_t>(w)];
      const double offset = workerClockOffset(log_.events, s.events, w);
      for (Event e : s.events) {
        e.start += offset;
        e.end += offset;
        run.events.push_back(std::move(e));
      }
      info.slowdowns.push_back(options.slowdownOf(w));
      info.tasksReceived.push_back(s.tasksReceived);
      info.rays += s.rays;
    }
    run.report = makeReport(info, run.events, elapsed);
    run.image = std::move(assembler_.image());
    run.owner = std::move(assembler_.owner());
    return run;
  }

  MpiSession& session_;
  const MpiRunRequest& request_;
  const int n_;
  MpiTransport net_;
  ImageAssembler assembler_;
  Master master_;
  EventLog log_;
  Stopwatch clock_;
  std::vector<double> lastContact_;  // per worker: last message either way, master clock
  std::vector<std::optional<WorkerSummary>> summaries_;
  int summariesIn_ = 0;
};

// ---------------------------------------------------------------------------------------------
// Workers (ranks >= 1)

[[noreturn]] void failAsInjected(const FaultInjection& fault, int id, uint64_t rendered) {
  const bool crash = fault.kind == FaultInjection::Kind::Crash;
  std::fprintf(stderr, "prt: %s: injected %s after %llu pixels; %s\n", rankName(id).c_str(),
               crash ? "crash" : "hang", static_cast<unsigned long long>(rendered),
               crash ? "exiting" : "no longer answering");
  std::fflush(stderr);
  if (crash) std::_Exit(3);  // as a machine dropping off the network: no goodbye to MPI
  for (;;) std::this_thread::sleep_for(std::chrono::milliseconds(100));
}

class WorkerRank {
 public:
  WorkerRank(MpiSession& session, const ParallelOptions& options)
      : id_(endpointOf(session.rank())),
        net_(session.comm().comm),
        worker_(id_, WorkerOptions{options.batchPixels}),
        // A slowdown list of the wrong length is the master's to report: it releases us.
        engine_(options.slowdowns.size() == static_cast<size_t>(session.workerCount())
                    ? options.slowdownOf(id_)
                    : 1.0,
                options.speedIndexKind, options.speedIndexDiscs,
                options.slowdownChangesOf(id_)) {
    for (const FaultInjection& f : options.faults) {
      if (f.worker == id_) fault_ = &f;
    }
  }

  // The same loop as the local driver's runWorker: read all waiting mail before computing,
  // pause briefly when idle.
  int run() {
    while (!worker_.stopped()) {
      if (std::optional<Packet> p = net_.poll()) {
        if (p->tag == kReleaseTag && p->rank == 0 && !sceneReceived_) return releaseCode(*p);
        if (p->tag != kMessageTag) {
          throw std::runtime_error("message with unexpected tag " + std::to_string(p->tag) +
                                   " from rank " + std::to_string(p->rank));
        }
        const Message m = decode(p->bytes);
        if (std::holds_alternative<SceneMsg>(m)) {
          clock_.reset();  // this worker's time 0 (see worker_summary.h)
          sceneReceived_ = true;
        }
        const double now = clock_.now();
        log_.add({EventKind::MessageReceived, id_, now, now, 0, p->bytes.size(),
                  endpointOf(p->rank), messageName(m)});
        send(worker_.onMessage(endpointOf(p->rank), m));
        continue;
      }
      if (worker_.needsSetup()) {
        setUp();
      } else if (worker_.hasWork()) {
        if (fault_ && rendered_ >= fault_->afterPixels) failAsInjected(*fault_, id_, rendered_);
        renderBatch();
      } else {
        pollPause();
      }
    }
    WorkerSummary summary{rays_, worker_.tasksReceived(), std::move(log_.events)};
    net_.send(rankOf(kMaster), kSummaryTag, encodeSummary(summary));
    if (!net_.flush(30.0)) throw std::runtime_error("the master did not take the summary");
    return 0;
  }

 private:
  void send(const Outbox& out) { sendOutbox(net_, id_, out, log_, clock_); }

  static int releaseCode(const Packet& p) {
    int32_t code = 1;
    if (p.bytes.size() == sizeof code) std::memcpy(&code, p.bytes.data(), sizeof code);
    return code;
  }

  // Loads the scene and times the Towers of Hanoi. Workers measure at the same time, as
  // separate machines would (and as the local driver's threads do).
  void setUp() {
    const double t0 = clock_.now();
    engine_.load(worker_.scene());
    const double speedIndex = engine_.measureSpeedIndex();
    log_.add({EventKind::Setup, id_, t0, clock_.now(), 0, 0, 0, ""});
    send(worker_.setupDone(speedIndex));
  }

  void renderBatch() {
    const TaskSet batch = worker_.nextBatch();
    const double t0 = clock_.now();
    double computeSeconds = 0;
    std::vector<float> rgb = engine_.render(batch, computeSeconds, rays_);
    log_.add({EventKind::Compute, id_, t0, t0 + computeSeconds, batch.size(), 0, 0, ""});
    rendered_ += batch.size();
    send(worker_.batchDone(batch, std::move(rgb), computeSeconds));
  }

  const int id_;
  MpiTransport net_;
  Worker worker_;
  WorkerEngine engine_;
  const FaultInjection* fault_ = nullptr;
  EventLog log_;
  Stopwatch clock_;
  bool sceneReceived_ = false;
  uint64_t rendered_ = 0;
  uint64_t rays_ = 0;
};

}  // namespace

ParallelRun renderMpiMaster(MpiSession& session, const MpiRunRequest& request) {
  PRT_CHECK(session.isMaster());
  const ParallelOptions& options = request.options;
  if (options.workers != session.workerCount()) {
    throw InputError("the run is set up for " + std::to_string(options.workers) +
                     " workers but mpirun started " + std::to_string(session.workerCount()));
  }
  validateParallelOptions(
      options, static_cast<uint64_t>(request.scene.image.width) * request.scene.image.height);
  MasterRank master(session, request);
  return master.run();
}

int runMpiWorker(MpiSession& session, const ParallelOptions& options) {
  PRT_CHECK(!session.isMaster());
  const int id = endpointOf(session.rank());
  try {
    WorkerRank worker(session, options);
    return worker.run();
  } catch (const MpiError& e) {
    session.abort(rankName(id) + ": " + describe(e) + "; aborting");
  } catch (const std::exception& e) {
    session.abort(rankName(id) + ": " + e.what() + "; aborting");
  }
}

}  // namespace prt
