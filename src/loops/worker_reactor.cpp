#include "loops/worker_reactor.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <utility>

namespace prt {

WorkerReactor::WorkerReactor(int id, const WorkerReactorOptions& options, EventLog* log)
    : id_(id),
      options_(options),
      // A batch keeps every thread busy: batchPixels for each of them.
      worker_(id, WorkerOptions{options.batchPixels * static_cast<uint64_t>(options.threads),
                                options.batchSeconds}),
      log_(log != nullptr ? log : &own_) {}

void WorkerReactor::begin(double now) {
  lastFromMaster_ = now;
  nextBeat_ = std::isfinite(options_.heartbeatSeconds) ? now
                                                       : std::numeric_limits<double>::infinity();
  onDeadline(now);
}

void WorkerReactor::onMessage(int from, Message message, uint64_t bytes, double now) {
  if (from == kMaster) lastFromMaster_ = std::max(lastFromMaster_, now);
  if (std::holds_alternative<HeartbeatMsg>(message)) return;
  Mail mail{from, std::move(message), bytes};
  if (computing_) {
    inbox_.push_back(std::move(mail));
  } else {
    handle(mail, now);
  }
}

void WorkerReactor::onMalformed(int from, const std::string& what) {
  // From a peer (or anyone relaying through one): that message is dropped, nothing more.
  if (from != kMaster) {
    worker_.countRefused();
    return;
  }
  throw std::runtime_error("bad message from the master: " + what);
}

void WorkerReactor::handle(const Mail& mail, double now) {
  log_->add({EventKind::MessageReceived, id_, now, now, 0, mail.bytes, mail.from,
            messageName(mail.message)});
  take(worker_.onMessage(mail.from, mail.message), now);
}

void WorkerReactor::readMail(double now) {
  std::vector<Mail> mail = std::exchange(inbox_, {});
  for (const Mail& m : mail) handle(m, now);
}

void WorkerReactor::take(Outbox out, double now) {
  // Any message renews the lease: the next heartbeat is due an interval after the last word
  // to the master, so a worker that returns results often sends none.
  for (const Envelope& e : out) {
    if (e.to == kMaster && std::isfinite(options_.heartbeatSeconds)) {
      nextBeat_ = now + options_.heartbeatSeconds;
    }
  }
  if (outbox_.empty()) {
    outbox_ = std::move(out);
  } else {
    for (Envelope& e : out) outbox_.push_back(std::move(e));
  }
}

Outbox WorkerReactor::takeOutbox() { return std::exchange(outbox_, {}); }

bool WorkerReactor::takeHeartbeat() { return std::exchange(heartbeat_, false); }

void WorkerReactor::onDeadline(double now) {
  if (now < nextBeat_) return;
  heartbeat_ = true;
  nextBeat_ = now + options_.heartbeatSeconds;
}

WorkerStep WorkerReactor::next(double now) {
  if (computing_) return WorkerStep::Wait;
  if (worker_.stopped()) return WorkerStep::Stop;
  if (worker_.needsSetup()) {
    computing_ = true;
    workStart_ = now;
    return WorkerStep::Setup;
  }
  if (!worker_.hasWork()) return WorkerStep::Wait;
  const std::optional<FaultInjection>& fault = options_.fault;
  if (fault && fault->kind != FaultInjection::Kind::Corrupt && rendered_ >= fault->afterPixels) {
    return fault->kind == FaultInjection::Kind::Crash ? WorkerStep::Crash : WorkerStep::Hang;
  }
  batch_ = worker_.nextBatch();
  computing_ = true;
  workStart_ = now;
  return WorkerStep::Batch;
}

void WorkerReactor::onSetupDone(double now, double speedIndexSeconds,
                                std::optional<uint64_t> taskLimit, WorkerIdentity identity) {
  computing_ = false;
  log_->add({EventKind::Setup, id_, workStart_, now, 0, 0, 0, ""});
  if (taskLimit) worker_.limitTasks(*taskLimit);
  take(worker_.setupDone(speedIndexSeconds, std::move(identity)), now);
  readMail(now);
}

void WorkerReactor::onBatchDone(double now, std::vector<float> rgb, double computeSeconds,
                                uint64_t rays) {
  computing_ = false;
  // A corrupt machine corrupts everything it renders from then on, checks included.
  const std::optional<FaultInjection>& fault = options_.fault;
  if (fault && fault->kind == FaultInjection::Kind::Corrupt && rendered_ >= fault->afterPixels &&
      options_.colours) {
    corruptPixels(batch_, rgb);
  }
  lastBatchSeconds_ = computeSeconds;
  rays_ += rays;
  // A spot check is work of this worker's, but not its pixels: labelled apart.
  log_->add({EventKind::Compute, id_, workStart_, workStart_ + computeSeconds, batch_.size(), 0, 0,
            worker_.batchIsCheck() ? kCheckLabel : ""});
  rendered_ += batch_.size();
  take(options_.colours ? worker_.batchDone(batch_, std::move(rgb), computeSeconds)
                        : worker_.batchDone(batch_, computeSeconds),
       now);
  readMail(now);
}

WorkerSummary WorkerReactor::summary(int threads, double slowdown, uint64_t framesBuilt,
                                     uint64_t nonFiniteSamples) {
  return WorkerSummary{rays_,    worker_.tasksReceived(), threads,          slowdown,
                       std::move(own_.events), framesBuilt, nonFiniteSamples};
}

}  // namespace prt
