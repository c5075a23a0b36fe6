#include "cluster/master.h"

#include <algorithm>

#include "core/check.h"

namespace prt {

Master::Master(std::unique_ptr<Strategy> strategy, int workerCount, uint64_t taskCount,
               SceneMsg scene, ResultSink sink)
    : strategy_(std::move(strategy)),
      taskCount_(taskCount),
      scene_(std::move(scene)),
      sink_(std::move(sink)),
      live_(static_cast<size_t>(workerCount), true),
      liveCount_(workerCount),
      speedIndices_(static_cast<size_t>(workerCount), 0.0),
      speedIndicesMissing_(workerCount),
      done_(taskCount, false),
      given_(static_cast<size_t>(workerCount)),
      movedOut_(static_cast<size_t>(workerCount)),
      returned_(static_cast<size_t>(workerCount), 0),
      answered_(static_cast<size_t>(workerCount), false),
      queueLengths_(static_cast<size_t>(workerCount), 0) {
  PRT_CHECK(workerCount >= 1);
  PRT_CHECK(strategy_ != nullptr);
}

Outbox Master::start() {
  Outbox out;
  sendToLive(scene_, out);
  return out;
}

void Master::sendToLive(const Message& m, Outbox& out) {
  for (int w = 0; w < workerCount(); ++w) {
    if (isLive(w)) out.push_back({w, m});
  }
}

bool Master::holdsWork(int worker) const {
  const auto w = static_cast<size_t>(worker);
  return live_[w] && given_[w].size() > movedOut_[w].size() + returned_[w];
}

bool Master::owesAnswer(int worker) const {
  const auto w = static_cast<size_t>(worker);
  if (!live_[w] || stopped_) return false;
  return (!started_ && speedIndices_[w] == 0.0) || holdsWork(worker) ||
         (queryOpen_ && !answered_[w]);
}

void Master::apply(const Decisions& decisions, Outbox& out) {
  for (const Decision& d : decisions) {
    if (const auto* a = std::get_if<Assign>(&d)) {
      if (a->tasks.empty()) continue;
      if (!isLive(a->worker)) {
        // Tasks for a worker lost before the strategy learnt of it (at the start): they are
        // that worker's leftovers, and go back to the strategy for the live ones.
        apply(strategy_->onWorkerLost(a->worker, a->tasks), out);
        continue;
      }
      given_[static_cast<size_t>(a->worker)].append(a->tasks);
      out.push_back({a->worker, TasksMsg{a->tasks}});
    } else if (std::holds_alternative<QueryQueues>(d)) {
      if (queryOpen_) continue;
      queryOpen_ = true;
      for (int w = 0; w < workerCount(); ++w) {
        answered_[static_cast<size_t>(w)] = !isLive(w);
        queueLengths_[static_cast<size_t>(w)] = 0;
      }
      sendToLive(QueryQueueMsg{}, out);
    } else if (const auto* t = std::get_if<Transfer>(&d)) {
      // A transfer from or to a lost worker is moot: its tasks come back through
      // onWorkerLost, and a sender simply keeps what it would have sent.
      if (isLive(t->from) && isLive(t->to)) {
        out.push_back({t->from, TransferOrderMsg{t->to, t->count}});
      }
    }
    // NoMoreWork: the worker simply waits; nothing to send.
  }
}

void Master::startStrategy(Outbox& out) {
  started_ = true;
  // The strategy sees every worker; one lost before the start gets the slowest live speed so
  // its arithmetic stays finite, and is reported lost straight away.
  std::vector<double> speeds = speedIndices_;
  double slowest = 0;
  for (double s : speeds) slowest = std::max(slowest, s);
  for (int w = 0; w < workerCount(); ++w) {
    if (!isLive(w)) speeds[static_cast<size_t>(w)] = slowest;
  }
  apply(strategy_->start(StartInfo{taskCount_, speeds}), out);
  for (int w = 0; w < workerCount(); ++w) {
    if (!isLive(w)) apply(strategy_->onWorkerLost(w, TaskSet{}), out);
  }
  finishIfComplete(out);  // an image with no tasks
}

void Master::finishIfComplete(Outbox& out) {
  if (complete() && !stopped_) {
    stopped_ = true;
    sendToLive(StopMsg{}, out);
  }
}

void Master::answerQueryIfComplete(Outbox& out) {
  if (!queryOpen_) return;
  for (int w = 0; w < workerCount(); ++w) {
    if (!answered_[static_cast<size_t>(w)]) return;
  }
  queryOpen_ = false;
  if (stopped_) return;
  apply(strategy_->onQueueLengths(queueLengths_), out);
}

Outbox Master::onMessage(int from, const Message& message) {
  Outbox out;
  PRT_CHECK(from >= 0 && from < workerCount());
  const auto w = static_cast<size_t>(from);
  if (!live_[w]) return out;  // a worker presumed lost: ignore it
  if (const auto* s = std::get_if<SpeedIndexMsg>(&message)) {
    if (speedIndices_[w] == 0.0) --speedIndicesMissing_;
    speedIndices_[w] = s->seconds;
    if (speedIndicesMissing_ == 0 && !started_) startStrategy(out);
  } else if (const auto* r = std::get_if<ResultsMsg>(&message)) {
    PRT_CHECK(r->rgb.size() == 3 * r->tasks.size() || r->rgb.empty());  // empty: simulated
    returned_[w] += r->tasks.size();
    apply(strategy_->onResults(from, r->tasks, r->computeSeconds), out);
    r->tasks.forEach([&](uint64_t task) {
      PRT_CHECK(task < taskCount_);
      if (!done_[task]) {
        done_[task] = true;
        ++doneCount_;
      }
    });
    // A batch may repeat pixels already delivered by a worker declared lost too early; passing
    // them on is harmless, as a pixel renders to the same bits wherever it is rendered.
    if (sink_) sink_(from, r->tasks, r->rgb);
    finishIfComplete(out);
  } else if (std::holds_alternative<RequestMsg>(message)) {
    if (started_ && !stopped_) apply(strategy_->onRequest(from), out);
  } else if (const auto* q = std::get_if<QueueLengthMsg>(&message)) {
    if (queryOpen_ && !answered_[w]) {
      answered_[w] = true;
      queueLengths_[w] = q->length;
      answerQueryIfComplete(out);
    }
  } else if (const auto* n = std::get_if<TransferNoticeMsg>(&message)) {
    movedOut_[w].append(n->tasks);
    if (isLive(n->to)) {
      given_[static_cast<size_t>(n->to)].append(n->tasks);
    } else {
      // Sent to a worker already lost: the tasks come back to the strategy as its leftovers.
      apply(strategy_->onWorkerLost(n->to, n->tasks), out);
    }
  }
  return out;
}

Outbox Master::onWorkerLost(int worker) {
  Outbox out;
  const auto w = static_cast<size_t>(worker);
  if (!live_[w]) return out;
  live_[w] = false;
  --liveCount_;
  if (!started_) {
    if (speedIndices_[w] == 0.0) --speedIndicesMissing_;
    speedIndices_[w] = 0.0;
    // Start without it once everyone else has reported.
    if (speedIndicesMissing_ == 0 && liveCount_ > 0) startStrategy(out);
    return out;
  }
  // Unfinished: everything it was given, less what it moved to peers and what came back.
  std::vector<bool> excluded(taskCount_, false);
  movedOut_[w].forEach([&](uint64_t t) { excluded[t] = true; });
  TaskSet unfinished;
  given_[w].forEach([&](uint64_t t) {
    if (!excluded[t] && !done_[t]) unfinished.append(TaskRun{t, 1, 1});
  });
  if (queryOpen_ && !answered_[w]) {
    answered_[w] = true;
    queueLengths_[w] = 0;
  }
  if (!stopped_ && liveCount_ > 0) apply(strategy_->onWorkerLost(worker, unfinished), out);
  answerQueryIfComplete(out);
  return out;
}

}  // namespace prt
