#include "cluster/master.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <optional>

#include "core/check.h"

namespace prt {

Master::Master(std::unique_ptr<Strategy> strategy, int workerCount, uint64_t pixelCount,
               SceneMsg scene, ResultSink sink, MasterOptions options)
    : strategy_(std::move(strategy)),
      scene_(std::move(scene)),
      sink_(std::move(sink)),
      options_(std::move(options)),
      ledger_(workerCount, pixelCount),
      map_(options_.resumedDone.empty() ? TaskMap(pixelCount)
                                        : TaskMap(pixelCount, options_.resumedDone)),
      speedIndices_(static_cast<size_t>(workerCount), 0.0),
      speedIndicesMissing_(workerCount),
      startingMissing_(workerCount),
      startingWorkers_(workerCount),
      answered_(static_cast<size_t>(workerCount), false),
      queueLengths_(static_cast<size_t>(workerCount), 0),
      untrusted_(static_cast<size_t>(workerCount), false),
      endgameServed_(static_cast<size_t>(workerCount), false),
      // Checks compare colours: none without them (the simulator) or without a referee.
      checks_(sink_ && options_.referee ? options_.checks : SpotCheckOptions{0, 0}, workerCount),
      identities_(static_cast<size_t>(workerCount)),
      taskLeases_(options_.taskLease, workerCount),
      openOrders_(static_cast<size_t>(workerCount)),
      inbound_(static_cast<size_t>(workerCount), 0) {
  PRT_CHECK(strategy_ != nullptr);
  ledger_.seedDone(options_.resumedDone);
  resumed_ = ledger_.doneCount();
  if (options_.endgame) {
    endgameOrder_.grow(workerCount);
    for (int w = 0; w < workerCount; ++w) endgameOrder_.setEligible(w, true);
  }
  options_.resumedDone = TaskSet{};
}

Outbox Master::start(double now) {
  now_ = now;
  ledger_.startLeases(now);
  Outbox out;
  sendToAll(scene_, out);
  return out;
}

// Every worker, lost or not: a worker wrongly presumed lost still needs its StopMsg to end,
// and a message to one that is really gone is harmless.
void Master::sendToAll(const Message& m, Outbox& out) {
  for (int w = 0; w < workerCount(); ++w) out.push_back({w, m});
}

void Master::assign(int worker, const TaskSet& pixels, Outbox& out) {
  if (pixels.empty()) return;
  taskLeases_.given(worker, now_, !ledger_.holdsWork(worker));
  ledger_.gave(worker, pixels);
  if (options_.endgame) endgameOrder_.gave(worker, pixels.size());
  out.push_back({worker, TasksMsg{pixels}});
}

void Master::apply(const Decisions& decisions, Outbox& out) {
  for (const Decision& d : decisions) {
    if (const auto* a = std::get_if<Assign>(&d)) {
      if (a->tasks.empty()) continue;
      if (!isLive(a->worker)) {
        // Tasks for a worker lost before the strategy learnt of it (at the start): they are
        // that worker's leftovers, and go back to the strategy for the live ones.
        ledger_.reissuedLate(a->tasks);
        returnToStrategy(a->worker, a->tasks, out);
        continue;
      }
      assign(a->worker, map_.toPixels(a->tasks), out);
    } else if (std::holds_alternative<QueryQueues>(d)) {
      if (queryOpen_) continue;
      queryOpen_ = true;
      // Only the workers the strategy knows of: a joiner still measuring its speed index
      // would answer once measured, holding the round up that long, and its length is not
      // passed on anyway (strategyQueueLengths).
      for (int w = 0; w < workerCount(); ++w) {
        const bool ask = isLive(w) && w < strategyWorkers_;
        answered_[static_cast<size_t>(w)] = !ask;
        queueLengths_[static_cast<size_t>(w)] = 0;
        if (ask) out.push_back({w, QueryQueueMsg{}});
      }
    } else if (const auto* t = std::get_if<Transfer>(&d)) {
      // A transfer from or to a lost worker is moot: its tasks come back through
      // onWorkerLost, and a sender simply keeps what it would have sent.
      // A worker refuses an order to send to itself, and would leave it unanswered.
      if (isLive(t->from) && isLive(t->to) && t->from != t->to) {
        openOrders_[static_cast<size_t>(t->from)].push_back({t->to, t->count});
        inbound_[static_cast<size_t>(t->to)] += t->count;
        out.push_back({t->from, TransferOrderMsg{t->to, t->count}});
      }
    } else if (const auto* n = std::get_if<NoMoreWork>(&d)) {
      // Nothing left to hand out: in the endgame, a copy of what will finish last.
      if (options_.endgame && started_ && !stopped_ && isLive(n->worker) &&
          !ledger_.holdsWork(n->worker)) {
        endgameCopy(n->worker, out);
      }
    }
  }
}

// The live worker expected to finish last is the one whose unfinished tasks take longest at
// its speed index; the asking worker gets a copy of the back of that worker's queue (which
// that worker renders last), sized so that both would finish together at their speed indices.
// Each task is copied at most once, so the waste is bounded by one copy of the endgame. The
// candidates are indexed (EndgameOrder): no request walks every worker.
void Master::endgameCopy(int worker, Outbox& out) {
  const int slowest =
      endgameOrder_.pick(worker, [&](int v) { return ledger_.unfinishedCount(v); });
  if (slowest < 0) return;
  TaskSet candidates = ledger_.unfinished(slowest);
  if (candidates.size() < 2) return;
  const double mine = std::max(speedIndices_[static_cast<size_t>(worker)], 1e-12);
  const double theirs = std::max(speedIndices_[static_cast<size_t>(slowest)], 1e-12);
  // Rates are 1 / speed index: my share of what is left is theirs / (mine + theirs).
  const double share = theirs / (mine + theirs);
  const auto count = std::clamp<uint64_t>(
      static_cast<uint64_t>(std::ceil(share * static_cast<double>(candidates.size()))), 1,
      candidates.size() - 1);
  TaskSet copy = candidates.takeBack(count);
  endgameServed_[static_cast<size_t>(slowest)] = true;  // its tail is covered now
  endgameOrder_.setEligible(slowest, false);
  endgameCopies_ += copy.size();
  assign(worker, copy, out);
}

// The slowest speed index in (0 while none is): what the strategy is told of a worker lost
// before it measured its own, so that its arithmetic stays finite.
double Master::slowestSpeedIndex() const {
  double slowest = 0;
  for (double s : speedIndices_) slowest = std::max(slowest, s);
  return slowest;
}

// The strategy starts once every worker there has reported its speed index (or is lost),
// joiners that arrived before the start included. Once the starting workers have (`force`,
// a lease later: expireLeases), it starts without the joiners still measuring, which are
// introduced when they report (introduceJoiners): a joiner that never reports cannot hold the
// start up. Only when no starting worker is left does the start wait for joiners.
void Master::startIfReady(Outbox& out, bool force) {
  if (started_ || (force ? startingMissing_ : speedIndicesMissing_) > 0) return;
  int known = startingWorkers_;
  while (known < workerCount() &&
         (!isLive(known) || speedIndices_[static_cast<size_t>(known)] > 0)) {
    ++known;
  }
  bool live = false;
  for (int w = 0; w < known && !live; ++w) live = isLive(w);
  if (live) startStrategy(known, out);
}

// A worker there before the start has reported its speed index, or is lost before it did.
void Master::measured(int worker, double now) {
  --speedIndicesMissing_;
  if (worker < startingWorkers_ && --startingMissing_ == 0) startingReadyAt_ = now;
}

void Master::startStrategy(int known, Outbox& out) {
  started_ = true;
  // The strategy sees workers 0 .. known-1; one lost before the start gets the slowest live
  // speed so its arithmetic stays finite, and is reported lost straight away.
  std::vector<double> speeds(speedIndices_.begin(), speedIndices_.begin() + known);
  const double slowest = slowestSpeedIndex();
  for (int w = 0; w < known; ++w) {
    if (!isLive(w)) speeds[static_cast<size_t>(w)] = slowest;
  }
  strategyWorkers_ = known;
  StartInfo info{map_.taskCount(), speeds};
  // A sequence's frames, as the strategy's tasks hold them. A resumed run's frames are
  // shorter by what was done, each by its own amount: the strategy gets each one's tasks, so
  // that its hand-outs keep to frames (one that spanned frames would make a worker prepare
  // them over and over).
  const uint64_t frames = scene_.frames.count();
  if (frames > 1) {
    info.frameTasks = std::max<uint64_t>(1, map_.taskCount() / frames);
    if (!map_.isIdentity()) {
      const uint64_t perFrame = ledger_.taskCount() / frames;  // the ledger counts pixels
      for (uint64_t i = 0; i < frames; ++i) {
        info.frameTaskCounts.push_back(map_.tasksBefore((i + 1) * perFrame) -
                                       map_.tasksBefore(i * perFrame));
      }
    }
  }
  apply(strategy_->start(info), out);
  for (int w = 0; w < known; ++w) {
    if (!isLive(w)) apply(strategy_->onWorkerLost(w, TaskSet{}), out);
  }
  // A worker given nothing at the start has, in the paper's words, finished its assigned
  // tasks: it asks for more. Entering that request here means every idle worker is known to
  // the strategy, so tasks that come back from a lost worker always find a taker.
  for (int w = 0; w < known; ++w) {
    if (isLive(w)) checks_.setEligible(w, true);
  }
  for (int w = 0; w < known && !ledger_.complete(); ++w) {
    if (isLive(w) && !ledger_.holdsWork(w)) apply(strategy_->onRequest(w), out);
  }
  finishIfComplete(out);  // an image with no tasks left
}

Outbox Master::stopIfComplete() {
  Outbox out;
  finishIfComplete(out);
  return out;
}

void Master::finishIfComplete(Outbox& out) {
  if (complete() && !stopped_) {
    stopped_ = true;
    sendToAll(StopMsg{}, out);
  }
}

void Master::answerQueryIfComplete(Outbox& out) {
  if (!queryOpen_) return;
  for (int w = 0; w < workerCount(); ++w) {
    if (!answered_[static_cast<size_t>(w)]) return;
  }
  queryOpen_ = false;
  if (stopped_) return;
  apply(strategy_->onQueueLengths(strategyQueueLengths()), out);
}

// The lengths of the workers the strategy knows of (a joiner it has not heard of yet is left
// out; one it heard of during the query was not asked, and holds 0).
std::vector<uint64_t> Master::strategyQueueLengths() const {
  return {queueLengths_.begin(), queueLengths_.begin() + strategyWorkers_};
}

Outbox Master::onWorkerJoined(int worker, double now) {
  PRT_CHECK(worker == workerCount());
  Outbox out;
  now_ = now;
  ledger_.addWorker(now);
  taskLeases_.addWorker();
  openOrders_.emplace_back();
  inbound_.push_back(0);
  speedIndices_.push_back(0.0);
  answered_.push_back(true);  // not asked by a query already open
  queueLengths_.push_back(0);
  untrusted_.push_back(false);
  endgameServed_.push_back(false);
  if (options_.endgame) endgameOrder_.setEligible(worker, true);
  checks_.addWorker();
  identities_.emplace_back();
  if (stopped_) {
    out.push_back({worker, StopMsg{}});
    return out;
  }
  if (!started_) ++speedIndicesMissing_;  // one of the workers the start waits for, then
  out.push_back({worker, scene_});
  return out;
}

// A lost worker's unfinished `tasks` (in the strategy's numbering) go back to the strategy for
// its live workers. When it has none left, the live workers being joiners it has not heard
// of yet, it is told of the loss alone and the tasks wait for the next joiner it hears of: a
// strategy with no live worker would drop them, and the image would never be finished.
void Master::returnToStrategy(int worker, const TaskSet& tasks, Outbox& out) {
  bool known = false;
  for (int w = 0; w < strategyWorkers_ && !known; ++w) known = isLive(w);
  if (known) {
    apply(strategy_->onWorkerLost(worker, tasks), out);
    return;
  }
  apply(strategy_->onWorkerLost(worker, TaskSet{}), out);
  orphans_.append(tasks);
  orphanOf_ = worker;
}

// Joiners whose speed index is in are introduced to the strategy in index order (a lost one
// is introduced and lost at once, so the numbering stays whole); each then asks, as a
// starting worker given nothing does.
void Master::introduceJoiners(Outbox& out) {
  if (!started_) return;
  while (strategyWorkers_ < workerCount()) {
    const int w = strategyWorkers_;
    const double speed = speedIndices_[static_cast<size_t>(w)];
    if (isLive(w) && speed == 0.0) return;  // still measuring
    ++strategyWorkers_;
    if (stopped_) continue;
    if (!isLive(w)) {
      const double slowest = slowestSpeedIndex();
      apply(strategy_->onWorkerJoined(w, slowest > 0 ? slowest : 1.0), out);
      apply(strategy_->onWorkerLost(w, TaskSet{}), out);
      continue;
    }
    apply(strategy_->onWorkerJoined(w, speed), out);
    checks_.setEligible(w, true);
    if (!orphans_.empty()) {
      // The tasks of the workers lost while only joiners were left: the strategy has a live
      // worker again.
      const TaskSet tasks = std::move(orphans_);
      orphans_ = TaskSet{};
      apply(strategy_->onWorkerLost(orphanOf_, tasks), out);
    }
    if (isLive(w) && !ledger_.holdsWork(w) && !ledger_.complete()) {
      apply(strategy_->onRequest(w), out);
    }
  }
}

// A message that decodes but cannot be true: pixels outside the image, colours that do not
// match them, a transfer to no worker. Such a worker is lost, as one whose bytes do not decode.
bool Master::plausible(const Message& message) const {
  if (const auto* r = std::get_if<ResultsMsg>(&message)) {
    const bool coloured = r->rgb.size() == 3 * r->tasks.size();
    for (const float c : r->rgb) {
      if (!std::isfinite(c)) return false;  // no render of PRT's gives such a colour
    }
    // Without a sink (the simulator) results carry no colours; otherwise they must.
    return r->tasks.allBelow(taskCount()) && (coloured || (!sink_ && r->rgb.empty()));
  }
  if (const auto* n = std::get_if<TransferNoticeMsg>(&message)) {
    return n->to >= 0 && n->to < workerCount() && n->tasks.allBelow(taskCount());
  }
  if (const auto* s = std::get_if<SpeedIndexMsg>(&message)) {
    return std::isfinite(s->seconds) && s->seconds > 0;
  }
  if (const auto* c = std::get_if<CheckResultsMsg>(&message)) {
    for (const float v : c->rgb) {
      if (!std::isfinite(v)) return false;
    }
    return c->tasks.allBelow(taskCount()) && c->rgb.size() == 3 * c->tasks.size();
  }
  return true;
}

// Why a live worker's transfer notice cannot be true, or "" when it can: it must answer the
// oldest order the master sent it (workers act on orders in the order they arrive, and answer
// each), and move only tasks it holds. A peer ordered to send it tasks may have done so
// before the master has that peer's notice: that many tasks it may move unrecorded.
std::string Master::unordered(int from, const TransferNoticeMsg& notice) {
  std::vector<TransferOrderMsg>& open = openOrders_[static_cast<size_t>(from)];
  const std::string moves = "a transfer notice of " + std::to_string(notice.tasks.size()) +
                            " tasks to worker " + std::to_string(notice.to);
  if (open.empty()) return "it sent " + moves + " that no order asked for";
  const TransferOrderMsg order = open.front();
  if (notice.to != order.to || notice.tasks.size() > order.count) {
    return "it sent " + moves + " for an order of at most " + std::to_string(order.count) +
           " to worker " + std::to_string(order.to);
  }
  open.erase(open.begin());
  uint64_t& coming = inbound_[static_cast<size_t>(order.to)];
  coming -= std::min(coming, order.count);
  const uint64_t missing = ledger_.notHeld(from, notice.tasks);
  if (missing > inbound_[static_cast<size_t>(from)]) {
    return "it sent " + moves + ", " + std::to_string(missing) + " of which it does not hold";
  }
  return "";
}

ResultsMsg Master::onlyHandedOut(const ResultsMsg& r) const {
  ResultsMsg out;
  out.computeSeconds = r.computeSeconds;
  size_t i = 0;
  r.tasks.forEach([&](uint64_t t) {
    if (ledger_.handedOut(t)) {
      out.tasks.append(TaskRun{t, 1, 1});
      if (!r.rgb.empty()) {
        const auto at = r.rgb.begin() + static_cast<std::ptrdiff_t>(3 * i);
        out.rgb.insert(out.rgb.end(), at, at + 3);
      }
    }
    ++i;
  });
  return out;
}

Outbox Master::onMessage(int from, const Message& message, double now) {
  Outbox out;
  PRT_CHECK(from >= 0 && from < workerCount());
  const auto w = static_cast<size_t>(from);
  if (untrusted_[w]) return out;  // nothing from it counts any more, late results included
  now_ = now;
  ledger_.heard(from, now);
  if (!plausible(message)) {
    // What it delivered before is as doubtful: rejected, as by a failed spot check.
    reject(from, now, std::string("it sent an invalid ") + messageName(message) + " message", out);
    finishIfComplete(out);
    return out;
  }
  if (const auto* given = std::get_if<ResultsMsg>(&message)) {
    // Pixels nobody was handed yet cannot be this run's: dropped. Not the sender's fault
    // necessarily (another process may have sent it those tasks as a peer's transfer), so it
    // is not rejected; what it rendered of its own counts.
    std::optional<ResultsMsg> filtered;
    if (!ledger_.allHandedOut(given->tasks)) filtered = onlyHandedOut(*given);
    const ResultsMsg* r = filtered ? &*filtered : given;
    // Results count from anyone, lost or not: the first copy of a pixel wins.
    const TaskSet fresh = ledger_.accept(from, r->tasks);
    if (isLive(from)) taskLeases_.returned(from, now, r->computeSeconds, !fresh.empty());
    // Adaptive strategies learn the worker's rate from every batch it rendered, copies
    // included (it spent the time on them); a lost worker's batches teach nothing useful.
    if (started_ && !stopped_ && isLive(from)) {
      apply(strategy_->onResults(from, map_.toTasks(r->tasks), r->computeSeconds), out);
    }
    if (!fresh.empty() && sink_) {
      if (fresh.size() == r->tasks.size()) {
        sink_(from, r->tasks, r->rgb);
        check(from, fresh, r->rgb);
      } else {
        std::vector<float> rgb;
        if (!r->rgb.empty()) {
          rgb.reserve(3 * fresh.size());
          // Walk both in order: `fresh` is a subsequence of `r->tasks`.
          std::vector<uint64_t> all = r->tasks.toVector();
          std::vector<uint64_t> kept = fresh.toVector();
          size_t k = 0;
          for (size_t j = 0; j < all.size() && k < kept.size(); ++j) {
            if (all[j] != kept[k]) continue;
            rgb.insert(rgb.end(), r->rgb.begin() + static_cast<std::ptrdiff_t>(3 * j),
                       r->rgb.begin() + static_cast<std::ptrdiff_t>(3 * j + 3));
            ++k;
          }
        }
        sink_(from, fresh, rgb);
        check(from, fresh, rgb);
      }
    }
    dispatchChecks(from, now, out);
    if (endgameServed_[w] && !ledger_.holdsWork(from)) {
      endgameServed_[w] = false;
      if (options_.endgame) endgameOrder_.setEligible(from, isLive(from));
    }
    finishIfComplete(out);
    return out;
  }
  if (!isLive(from)) return out;  // a worker presumed lost: nothing else from it counts
  if (const auto* s = std::get_if<SpeedIndexMsg>(&message)) {
    // Text from the network, bound for reports and terminals: printable ASCII, bounded.
    const auto clean = [](const std::string& text) {
      std::string shown;
      for (const char c : text.substr(0, 120)) shown += (c >= 32 && c < 127) ? c : '?';
      return shown;
    };
    identities_[w] = {clean(s->identity.build), clean(s->identity.host)};
    if (options_.admit) {
      if (const std::string why = options_.admit(identities_[w]); !why.empty()) {
        reject(from, now, why, out);
        finishIfComplete(out);
        return out;
      }
    }
    const bool first = speedIndices_[w] == 0.0;
    speedIndices_[w] = s->seconds;
    taskLeases_.setSpeedIndex(from, s->seconds);
    if (options_.endgame) endgameOrder_.setWeight(from, s->seconds);
    if (!started_) {
      if (first) measured(from, now);
      startIfReady(out, false);
    }
    introduceJoiners(out);
  } else if (std::holds_alternative<RequestMsg>(message)) {
    if (started_ && !stopped_) apply(strategy_->onRequest(from), out);
  } else if (const auto* q = std::get_if<QueueLengthMsg>(&message)) {
    if (queryOpen_ && !answered_[w]) {
      answered_[w] = true;
      queueLengths_[w] = q->length;
      answerQueryIfComplete(out);
    }
  } else if (const auto* n = std::get_if<TransferNoticeMsg>(&message)) {
    if (const std::string why = unordered(from, *n); !why.empty()) {
      reject(from, now, why, out);
      finishIfComplete(out);
      return out;
    }
    ledger_.movedOut(from, n->tasks);
    if (isLive(n->to)) {
      taskLeases_.given(n->to, now, !ledger_.holdsWork(n->to));
      ledger_.gave(n->to, n->tasks);
      if (options_.endgame) endgameOrder_.gave(n->to, n->tasks.size());
    } else {
      // Sent to a worker already lost: the tasks come back to the strategy as its leftovers.
      TaskSet left;
      n->tasks.forEach([&](uint64_t t) {
        if (!ledger_.isDone(t)) left.append(TaskRun{t, 1, 1});
      });
      ledger_.reissuedLate(left);
      if (!stopped_) returnToStrategy(n->to, map_.toTasks(left), out);
    }
  } else if (const auto* c = std::get_if<CheckResultsMsg>(&message)) {
    taskLeases_.renew(from, now);
    settle(checks_.results(from, c->tasks, c->rgb), now, out);
  }
  // HeartbeatMsg: the lease is renewed above. Whatever it was, the sender is between batches:
  // the checks waiting for it go now.
  dispatchChecks(from, now, out);
  finishIfComplete(out);
  return out;
}

// Spot checks of a batch of fresh pixels `author` delivered (colours `rgb`).
void Master::check(int author, const TaskSet& fresh, const std::vector<float>& rgb) {
  if (!checks_.enabled() || rgb.empty() || stopped_) return;
  checks_.sample(author, fresh, rgb);
}

// Sends the waiting checks to the workers that can take them now: the one just heard from
// (it is between batches), idle ones, and everyone once every pixel is in (nothing else is
// left to wait for). The referee's are rendered here, at once.
void Master::dispatchChecks(int heardFrom, double now, Outbox& out) {
  if (!checks_.enabled() || dispatching_) return;
  dispatching_ = true;  // settle() may reject, and a rejection moves checks: loop, not recurse
  for (bool again = true; again;) {
    again = false;
    const std::vector<int> waiting = checks_.checkersWaiting();
    for (const int c : waiting) {
      if (c == SpotChecks::kReferee) {
        const TaskSet pixels = checks_.take(c, now);
        if (pixels.empty()) continue;
        settle(checks_.results(c, pixels, options_.referee(pixels)), now, out);
        again = true;
      } else if (c == heardFrom || ledger_.complete() || !ledger_.holdsWork(c)) {
        TaskSet pixels = checks_.take(c, now);
        if (!pixels.empty()) out.push_back({c, CheckMsg{std::move(pixels)}});
      }
    }
  }
  dispatching_ = false;
}

namespace {

bool sameBits(const Rgb& a, const Rgb& b) { return std::memcmp(a.data(), b.data(), sizeof a) == 0; }

std::string colourText(const Rgb& c) {
  char text[96];
  std::snprintf(text, sizeof text, "(%.9g, %.9g, %.9g)", static_cast<double>(c[0]),
                static_cast<double>(c[1]), static_cast<double>(c[2]));
  return text;
}

}  // namespace

// Two renders of a pixel differ: a third, the master's own, decides. Whoever differs from it
// is rejected (a checker that is the master itself is right by definition).
void Master::settle(const std::vector<Disagreement>& disagreements, double now, Outbox& out) {
  for (const Disagreement& d : disagreements) {
    Rgb truth = d.checkerRgb;
    if (d.checker != SpotChecks::kReferee) {
      const std::vector<float> rgb = options_.referee(TaskSet::range(d.pixel, 1));
      PRT_CHECK(rgb.size() == 3);
      std::memcpy(truth.data(), rgb.data(), sizeof truth);
    }
    const std::string pixel = "pixel " + std::to_string(d.pixel);
    if (!sameBits(d.authorRgb, truth)) {
      reject(d.author, now,
             "a spot check of " + pixel + " failed: it sent " + colourText(d.authorRgb) +
                 ", the master renders " + colourText(truth),
             out);
    }
    if (d.checker != SpotChecks::kReferee && !sameBits(d.checkerRgb, truth)) {
      reject(d.checker, now,
             "its spot check of " + pixel + " was wrong: it sent " + colourText(d.checkerRgb) +
                 ", the master renders " + colourText(truth),
             out);
    }
  }
}

bool Master::rejected(int worker) const {
  return std::any_of(rejections_.begin(), rejections_.end(),
                     [&](const RejectedWorker& r) { return r.worker == worker; });
}

// A worker found wrong: stopped, ignored from now on, its pixels taken back and reissued.
void Master::reject(int worker, double now, const std::string& reason, Outbox& out) {
  if (rejected(worker)) return;
  untrusted_[static_cast<size_t>(worker)] = true;
  checks_.workerGone(worker, true);
  if (isLive(worker)) lose(worker, now, "rejected: " + reason, out);
  const TaskSet back = ledger_.takeBack(worker);
  // Its pixels are undone again: other workers' unfinished counts may have grown.
  if (options_.endgame && !back.empty()) endgameOrder_.invalidate();
  rejections_.push_back({worker, now, reason, back.size(),
                         identities_[static_cast<size_t>(worker)].host});
  if (options_.rejected) options_.rejected(rejections_.back());
  if (!back.empty()) {
    if (options_.takenBack) options_.takenBack(worker, back);
    returnToStrategy(worker, map_.toTasks(back), out);
  }
  out.push_back({worker, StopMsg{}});
}

void Master::lose(int worker, double now, const std::string& reason, Outbox& out) {
  const auto w = static_cast<size_t>(worker);
  const TaskSet unfinished = ledger_.markLost(worker, now, reason);
  taskLeases_.drop(worker);
  // Its open orders die with it; what peers were ordered to send it stays allowed for: their
  // tasks may be on the way.
  openOrders_[w].clear();
  endgameServed_[w] = false;
  if (options_.endgame) endgameOrder_.setEligible(worker, false);
  if (!started_) {
    if (speedIndices_[w] == 0.0) measured(worker, now);  // it never will now
    speedIndices_[w] = 0.0;
    startIfReady(out, false);  // without it, once everyone else has reported
    return;
  }
  if (queryOpen_ && !answered_[w]) {
    answered_[w] = true;
    queueLengths_[w] = 0;
  }
  checks_.workerGone(worker, false);  // what it was to check goes to another
  if (worker >= strategyWorkers_) {
    introduceJoiners(out);  // a joiner the strategy had not heard of: it held nothing
  } else if (!stopped_ && ledger_.liveCount() > 0) {
    returnToStrategy(worker, map_.toTasks(unfinished), out);
  }
  answerQueryIfComplete(out);
  dispatchChecks(-1, now, out);
}

Outbox Master::onWorkerLost(int worker, double now, const std::string& reason) {
  Outbox out;
  now_ = now;
  if (isLive(worker)) lose(worker, now, reason, out);
  finishIfComplete(out);
  return out;
}

Outbox Master::expireLeases(double now, double leaseSeconds) {
  Outbox out;
  if (stopped_) return out;
  now_ = now;
  if (!started_ && startingMissing_ == 0 && now - startingReadyAt_ > leaseSeconds) {
    startIfReady(out, true);  // joiners still measuring a lease after the starting workers
  }
  // A check unanswered for a lease (its checker there, but silent on it) is the master's.
  if (checks_.expire(now, leaseSeconds) > 0) dispatchChecks(-1, now, out);
  for (int w : ledger_.expired(now, leaseSeconds)) {
    char reason[64];
    std::snprintf(reason, sizeof reason, "silent for %.1f s", ledger_.silentSeconds(w, now));
    lose(w, now, reason, out);
  }
  // Task leases: there, but returning nothing for what it holds.
  for (int w : taskLeases_.expired(now)) {
    if (!isLive(w) || stopped_) continue;
    const uint64_t held = ledger_.unfinishedCount(w);
    if (held == 0) continue;  // nothing left to wait for: the lease starts with its next tasks
    // Only when another live worker shows the time was there to work — it returned a fresh
    // result in the last half of this lease, or holds nothing and waits — so that a machine
    // too busy for every worker (a load spike) costs time, never the workers of a run. Not
    // acted on, the lease is looked at again half a lease later: those windows tile the time,
    // so another worker's next fresh result is seen within half a lease.
    const double half = taskLeases_.leaseOf(w) / 2;
    const double recent = std::max(now - half, taskLeases_.since(w));
    bool others = false;
    for (int v = 0; v < workerCount() && !others; ++v) {
      others = v != w && isLive(v) && !untrusted_[static_cast<size_t>(v)] &&
               (taskLeases_.lastFresh(v) > recent || !ledger_.holdsWork(v));
    }
    if (!others) {
      taskLeases_.postpone(w, now, half);
      continue;
    }
    char reason[160];
    std::snprintf(reason, sizeof reason,
                  "returned no result for %.1f s while holding %llu unfinished tasks "
                  "(its task lease: %.1f s)",
                  now - taskLeases_.since(w), static_cast<unsigned long long>(held),
                  taskLeases_.leaseOf(w));
    lose(w, now, reason, out);
  }
  finishIfComplete(out);
  return out;
}

}  // namespace prt
