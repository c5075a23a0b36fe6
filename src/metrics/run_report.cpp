#include "metrics/run_report.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <nlohmann/json.hpp>

namespace prt {

double maximumAchievableSpeedup(double serialSpeedIndex, const std::vector<double>& speedIndices) {
  double masu = 0;
  for (double s : speedIndices) {
    if (s > 0) masu += serialSpeedIndex / s;
  }
  return masu;
}

std::string spotCheckGuarantee(const FaultInfo& f) {
  char text[512];
  if (f.verifyPercent <= 0) {
    return "no spot checks (--verify 0): wrong pixels from a worker would not be noticed";
  }
  const double p = f.verifyLowestPercent / 100;
  if (p >= 1) {
    std::snprintf(text, sizeof text,
                  "every pixel a worker delivered was rendered again by another and compared "
                  "bit for bit (--verify %g): any wrong pixel was caught",
                  f.verifyPercent);
    return text;
  }
  const auto caught = [p](double k) {
    const double chance = 1 - std::pow(1 - p, k);
    char out[32];
    if (chance > 0.999) return std::string("over 99.9 %");
    std::snprintf(out, sizeof out, "%.3g %%", 100 * chance);
    return std::string(out);
  };
  std::snprintf(text, sizeof text,
                "each pixel a worker delivered was checked with probability at least %g %% "
                "(--verify %g, halved for a trusted worker): a worker that returned k wrong "
                "pixels would have been caught with probability at least 1 - (1 - %g)^k (%s for "
                "k = 10, %s for k = 100); --verify 100 checks every pixel",
                100 * p, f.verifyPercent, p, caught(10).c_str(), caught(100).c_str());
  return text;
}

std::optional<double> balancedFinishSeconds(const std::vector<double>& rates,
                                            const std::vector<double>& arrivals, double pixels,
                                            const std::vector<double>& departures) {
  // Water filling over the arrivals and departures in time order: between two of them the
  // workers present render at their summed rate.
  struct Step {
    double at;
    double rate;  // added (an arrival) or taken away (a departure)
  };
  std::vector<Step> steps;
  for (size_t i = 0; i < rates.size(); ++i) {
    if (!(rates[i] > 0)) continue;
    const double from = arrivals[i];
    const double to = i < departures.size() ? departures[i] : HUGE_VAL;
    if (!(to > from)) continue;
    steps.push_back({from, rates[i]});
    if (to < HUGE_VAL) steps.push_back({to, -rates[i]});
  }
  if (steps.empty()) return std::nullopt;
  std::stable_sort(steps.begin(), steps.end(),
                   [](const Step& a, const Step& b) { return a.at < b.at; });
  double rate = 0;
  double left = pixels;
  double t = steps.front().at;
  for (size_t k = 0; k < steps.size(); ++k) {
    rate += steps[k].rate;
    if (rate < 1e-12 * std::abs(steps[k].rate)) rate = 0;  // every one present has left
    t = steps[k].at;
    const double next = k + 1 < steps.size() ? steps[k + 1].at : HUGE_VAL;
    if (rate > 0) {
      if (next == HUGE_VAL || rate * (next - t) >= left) return t + left / rate;
      left -= rate * (next - t);
    }
  }
  return std::nullopt;  // every worker left before the work was done
}

RunReport makeReport(const RunInfo& info, const std::vector<Event>& events,
                     double elapsedSeconds) {
  RunReport r;
  r.info = info;
  r.elapsedSeconds = elapsedSeconds;
  const size_t n = info.workerSpeedIndexSeconds.size();
  r.workers.resize(n);
  for (size_t w = 0; w < n; ++w) {
    WorkerReport& wr = r.workers[w];
    wr.worker = static_cast<int>(w);
    wr.speedIndexSeconds = info.workerSpeedIndexSeconds[w];
    wr.slowdown = w < info.slowdowns.size() ? info.slowdowns[w] : 1.0;
    wr.tasks = w < info.tasksReceived.size() ? info.tasksReceived[w] : 0;
    wr.threads = w < info.threads.size() ? info.threads[w] : 1;
    wr.framesBuilt = w < info.framesBuilt.size() ? info.framesBuilt[w] : 0;
    wr.nonFiniteSamples = w < info.nonFiniteSamples.size() ? info.nonFiniteSamples[w] : 0;
    if (w < info.hosts.size()) wr.host = info.hosts[w];
    if (w < info.kernels.size()) wr.kernels = info.kernels[w];
    if (w < info.joinedAt.size()) wr.joinedAtSeconds = info.joinedAt[w];
  }
  // Per worker, from the master's sending of the scene to it to its receipt (a worker that
  // joined later got it later); the report keeps the longest.
  std::vector<double> sceneSent(n, -1), sceneReceived(n, -1);
  for (const Event& e : events) {
    if (e.label != "Scene") continue;
    if (e.kind == EventKind::MessageSent && e.worker < 0) {
      r.sceneBytes = std::max(r.sceneBytes, e.bytes);
      if (e.peer >= 0 && static_cast<size_t>(e.peer) < n) sceneSent[static_cast<size_t>(e.peer)] = e.start;
    } else if (e.kind == EventKind::MessageReceived && e.worker >= 0 &&
               static_cast<size_t>(e.worker) < n) {
      sceneReceived[static_cast<size_t>(e.worker)] = e.start;
    }
  }
  for (size_t w = 0; w < n; ++w) {
    if (sceneSent[w] >= 0 && sceneReceived[w] >= sceneSent[w]) {
      r.sceneTransferSeconds = std::max(r.sceneTransferSeconds, sceneReceived[w] - sceneSent[w]);
    }
  }
  for (const Event& e : events) {
    if (e.kind == EventKind::WorkerLost) {
      if (e.worker >= 0 && static_cast<size_t>(e.worker) < n) {
        r.workers[static_cast<size_t>(e.worker)].lost = true;
      }
      continue;
    }
    if (e.kind == EventKind::MessageSent) {
      ++r.messages;
      r.bytes += e.bytes;
    }
    if (e.worker < 0 || static_cast<size_t>(e.worker) >= n) continue;
    WorkerReport& wr = r.workers[static_cast<size_t>(e.worker)];
    switch (e.kind) {
      case EventKind::Compute:
        wr.busySeconds += e.end - e.start;
        if (e.label == kCheckLabel) {
          wr.checkPixels += e.pixels;
        } else {
          wr.pixels += e.pixels;
        }
        break;
      case EventKind::MessageSent:
        ++wr.messagesSent;
        wr.bytesSent += e.bytes;
        break;
      case EventKind::MessageReceived:
        ++wr.messagesReceived;
        wr.bytesReceived += e.bytes;
        break;
      default:
        break;
    }
  }
  // A worker whose events never came (lost, or its summary missing) rendered at least the
  // pixels the master accepted from it.
  for (size_t w = 0; w < n && w < info.acceptedPixels.size(); ++w) {
    WorkerReport& wr = r.workers[w];
    if (wr.pixels == 0 && wr.busySeconds == 0) wr.pixels = info.acceptedPixels[w];
  }
  // Each worker is part of the run from its arrival until the end, or until it was last heard
  // from before it was lost (what the lease waited for is not its time).
  std::vector<double> departures(r.workers.size(), elapsedSeconds);
  for (const LostWorkerInfo& l : info.faults.lostWorkers) {
    if (l.worker >= 0 && static_cast<size_t>(l.worker) < departures.size()) {
      departures[static_cast<size_t>(l.worker)] =
          std::clamp(std::min(l.lastHeardSeconds, l.atSeconds), 0.0, elapsedSeconds);
    }
  }
  double busy = 0;
  double present = 0;
  std::vector<double> arrivals;
  for (size_t w = 0; w < r.workers.size(); ++w) {
    WorkerReport& wr = r.workers[w];
    const double from = std::clamp(wr.joinedAtSeconds.value_or(0.0), 0.0, elapsedSeconds);
    const double to = std::max(from, departures[w]);
    wr.idleSeconds = std::max(0.0, to - from - wr.busySeconds);
    busy += wr.busySeconds;
    present += to - from;
    arrivals.push_back(from);
    if (departures[w] >= elapsedSeconds) departures[w] = HUGE_VAL;  // present to the end
  }
  r.efficiency = present > 0 ? busy / present : 0;
  // The ideal: each worker's relative speed, the work done in speed-weighted busy seconds,
  // and that work perfectly balanced over the workers while they were part of the run (from
  // their arrivals until last heard from, for those lost).
  const bool emulated = std::any_of(r.workers.begin(), r.workers.end(),
                                    [](const WorkerReport& w) { return w.slowdown != 1.0; });
  std::vector<double> speeds;
  double work = 0;
  for (const WorkerReport& wr : r.workers) {
    double speed = 0;
    if (emulated) {
      speed = wr.slowdown > 0 ? 1.0 / wr.slowdown : 0.0;
    } else if (info.speedIndexRun) {
      speed = wr.speedIndexSeconds > 0 ? 1.0 / wr.speedIndexSeconds : 0.0;
    } else {
      speed = wr.busySeconds > 0 ? static_cast<double>(wr.pixels) / wr.busySeconds : 0.0;
    }
    speeds.push_back(speed);
    work += emulated || info.speedIndexRun ? wr.busySeconds * speed : static_cast<double>(wr.pixels);
  }
  r.idealBasis = emulated ? "slowdown" : info.speedIndexRun ? "speed_index" : "measured_throughput";
  if (work > 0) r.idealSeconds = balancedFinishSeconds(speeds, arrivals, work, departures);
  if (info.speedIndexRun) {
    r.speedIndexMasu =
        maximumAchievableSpeedup(info.masterSpeedIndexSeconds, info.workerSpeedIndexSeconds);
  }
  uint64_t pixels = 0;
  for (const WorkerReport& wr : r.workers) pixels += wr.pixels;
  if (info.serialSeconds && *info.serialSeconds > 0 && pixels > 0) {
    const double serialRate = static_cast<double>(pixels) / *info.serialSeconds;
    double rates = 0;
    for (const WorkerReport& wr : r.workers) {
      if (wr.busySeconds > 0) rates += static_cast<double>(wr.pixels) / wr.busySeconds;
    }
    r.measuredMasu = rates / serialRate;
  }
  if (info.serialSeconds && elapsedSeconds > 0) {
    r.speedup = *info.serialSeconds / elapsedSeconds;
    if (r.speedIndexMasu && *r.speedIndexMasu > 0) r.speedIndexAsu = *r.speedup / *r.speedIndexMasu;
    if (r.measuredMasu && *r.measuredMasu > 0) r.measuredAsu = *r.speedup / *r.measuredMasu;
  }
  if (r.speedIndexMasu) {
    r.masu = *r.speedIndexMasu;
    r.asu = r.speedIndexAsu;
  } else {
    r.masuBasis = "measured_throughput";
    r.masu = r.measuredMasu.value_or(0.0);
    r.asu = r.measuredAsu;
  }
  return r;
}

std::string nonFiniteSamplesLine(uint64_t count) {
  return std::to_string(count) + (count == 1 ? " sample was" : " samples were") +
         " not finite (NaN or infinite) and left out of their pixels' means";
}

uint64_t RunReport::nonFiniteSamples() const {
  uint64_t count = 0;
  for (const WorkerReport& w : workers) count += w.nonFiniteSamples;
  return count;
}

std::string RunReport::toJson() const {
  using nlohmann::json;
  json j;
  j["driver"] = info.driver;
  j["strategy"] = info.strategy;
  j["width"] = info.width;
  j["height"] = info.height;
  j["samples_per_pixel"] = info.samplesPerPixel;
  j["drt"] = info.drtRate;
  j["workers_count"] = workers.size();
  j["elapsed_s"] = elapsedSeconds;
  j["serial_s"] = info.serialSeconds ? json(*info.serialSeconds) : json(nullptr);
  j["speedup"] = speedup ? json(*speedup) : json(nullptr);
  j["efficiency"] = efficiency;
  auto orNull = [](const std::optional<double>& v) { return v ? json(*v) : json(nullptr); };
  j["masu"] = masu;
  j["asu"] = orNull(asu);
  j["masu_basis"] = masuBasis;
  j["speed_index_masu"] = orNull(speedIndexMasu);
  j["speed_index_asu"] = orNull(speedIndexAsu);
  j["measured_masu"] = orNull(measuredMasu);
  j["measured_asu"] = orNull(measuredAsu);
  j["master_speed_index_s"] = info.masterSpeedIndexSeconds;
  j["messages"] = messages;
  j["bytes"] = bytes;
  j["scene_bytes"] = sceneBytes;
  j["scene_transfer_s"] = sceneTransferSeconds;
  j["rays"] = info.rays;
  j["non_finite_samples"] = nonFiniteSamples();
  json ws = json::array();
  for (const WorkerReport& w : workers) {
    ws.push_back({{"worker", w.worker},
                  {"speed_index_s", w.speedIndexSeconds},
                  {"slowdown", w.slowdown},
                  {"tasks", w.tasks},
                  {"threads", w.threads},
                  {"frames_built", w.framesBuilt},
                  {"non_finite_samples", w.nonFiniteSamples},
                  {"host", w.host},
                  {"kernels", w.kernels},
                  {"pixels", w.pixels},
                  {"check_pixels", w.checkPixels},
                  {"busy_s", w.busySeconds},
                  {"idle_s", w.idleSeconds},
                  {"messages_sent", w.messagesSent},
                  {"messages_received", w.messagesReceived},
                  {"bytes_sent", w.bytesSent},
                  {"bytes_received", w.bytesReceived},
                  {"lost", w.lost},
                  {"joined_at_s", w.joinedAtSeconds ? json(*w.joinedAtSeconds) : json(nullptr)}});
  }
  j["workers"] = ws;
  json joined = json::array();
  for (const WorkerReport& w : workers) {
    if (w.joinedAtSeconds) joined.push_back({{"worker", w.worker}, {"at_s", *w.joinedAtSeconds}});
  }
  j["joined_workers"] = joined;
  j["ideal_s"] = orNull(idealSeconds);
  j["ideal_basis"] = idealBasis;
  const FaultInfo& f = info.faults;
  json lost = json::array();
  for (const LostWorkerInfo& l : f.lostWorkers) {
    lost.push_back({{"worker", l.worker},
                    {"at_s", l.atSeconds},
                    {"reason", l.reason},
                    {"unfinished_tasks", l.unfinished},
                    {"last_heard_s", l.lastHeardSeconds}});
  }
  j["lost_workers"] = lost;
  json rejected = json::array();
  for (const RejectedWorkerInfo& r : f.rejectedWorkers) {
    rejected.push_back({{"worker", r.worker},
                        {"at_s", r.atSeconds},
                        {"reason", r.reason},
                        {"pixels_taken_back", r.pixelsTakenBack},
                        {"host", r.host}});
  }
  j["rejected_workers"] = rejected;
  json refused = json::array();
  for (const std::string& why : f.refusedJoiners) refused.push_back({{"reason", why}});
  j["refused_joiners"] = refused;
  j["verify_percent"] = f.verifyPercent;
  j["verify_seed"] = f.verifySeed;
  j["verify_lowest_percent"] = f.verifyLowestPercent;
  j["verify_guarantee"] = spotCheckGuarantee(f);
  j["verified_pixels"] = f.verifiedPixels;
  j["referee_checks"] = f.refereeChecks;
  j["reissued_tasks"] = f.reissuedTasks;
  j["duplicate_pixels"] = f.duplicatePixels;
  j["endgame_copies"] = f.endgameCopies;
  j["resumed_pixels"] = f.resumedPixels;
  j["worker_timeout_s"] = f.workerTimeoutSeconds;
  j["heartbeat_s"] = f.heartbeatSeconds;
  j["missing_summaries"] = f.missingSummaries;
  // The master's own load (null when it was not measured).
  j["master_busy_share"] = orNull(masterBusyShare());
  if (info.master) {
    const MasterLoad& m = *info.master;
    const uint64_t handled = m.received + m.sent;
    j["master"] = {{"busy_s", m.busySeconds},
                   {"basis", m.basis},
                   {"messages_received", m.received},
                   {"messages_sent", m.sent},
                   {"heartbeats_received", m.heartbeatsReceived},
                   {"heartbeats_sent", m.heartbeatsSent},
                   {"checkpoints", m.checkpoints},
                   {"checkpoint_s", m.checkpointSeconds},
                   {"us_per_message", handled > 0 ? json(1e6 * m.busySeconds /
                                                         static_cast<double>(handled))
                                                  : json(nullptr)}};
  } else {
    j["master"] = nullptr;
  }
  if (!info.frames.empty()) {
    // A sequence: each frame's pixels rendered in this run, when its first and last came in
    // (null: complete from a checkpoint), and the time between (its span in the job).
    json frames = json::array();
    for (const FrameInfo& fr : info.frames) {
      frames.push_back({{"frame", fr.number},
                        {"pixels", fr.pixels},
                        {"started_s", orNull(fr.firstSeconds)},
                        {"completed_s", orNull(fr.doneSeconds)},
                        {"span_s", fr.firstSeconds && fr.doneSeconds
                                       ? json(*fr.doneSeconds - *fr.firstSeconds)
                                       : json(nullptr)}});
    }
    j["frames"] = frames;
    j["frame_count"] = info.frames.size();
    j["fps"] = info.fps;
    j["seconds_per_frame"] = elapsedSeconds / static_cast<double>(info.frames.size());
  }
  return j.dump(2) + "\n";
}

std::optional<double> RunReport::masterBusyShare() const {
  if (!info.master || !(elapsedSeconds > 0)) return std::nullopt;
  return info.master->busySeconds / elapsedSeconds;
}

std::string RunReport::toTable() const {
  std::string out;
  char line[256];
  std::snprintf(line, sizeof line, "%-11s %9s %8s %6s %9s %9s %9s %7s %10s\n", "worker",
                "speed_s", "slowdown", "tasks", "pixels", "busy_s", "idle_s", "msgs", "bytes");
  out += line;
  // A speed index that was not run is shown as not measured, never as a number.
  const auto speed = [&](double seconds) {
    if (!info.speedIndexRun || seconds <= 0) return std::string("-");
    char b[32];
    std::snprintf(b, sizeof b, "%.4f", seconds);
    return std::string(b);
  };
  // Past kTableWorkers workers, rows of groups: sums of counts, means of the rest.
  const size_t n = workers.size();
  const size_t group = n > kTableWorkers ? (n + kTableGroups - 1) / kTableGroups : 1;
  for (size_t first = 0; first < n; first += group) {
    const size_t last = std::min(n, first + group) - 1;
    WorkerReport sum;
    std::vector<double> speeds;
    bool lost = false;
    for (size_t i = first; i <= last; ++i) {
      const WorkerReport& w = workers[i];
      speeds.push_back(w.speedIndexSeconds);
      sum.slowdown += w.slowdown;
      sum.tasks += w.tasks;
      sum.pixels += w.pixels;
      sum.busySeconds += w.busySeconds;
      sum.idleSeconds += w.idleSeconds;
      sum.messagesSent += w.messagesSent + w.messagesReceived;
      sum.bytesSent += w.bytesSent + w.bytesReceived;
      lost = lost || w.lost;
    }
    sum.slowdown -= 1;  // the default 1 the sum started from
    const auto count = static_cast<double>(last - first + 1);
    std::sort(speeds.begin(), speeds.end());
    const std::string name =
        (group == 1 ? std::to_string(workers[first].worker)
                    : std::to_string(workers[first].worker) + "-" +
                          std::to_string(workers[last].worker)) +
        (lost ? "!" : "");
    std::snprintf(line, sizeof line, "%-11s %9s %8.2f %6llu %9llu %9.3f %9.3f %7llu %10llu\n",
                  name.c_str(), speed(speeds[speeds.size() / 2]).c_str(), sum.slowdown / count,
                  static_cast<unsigned long long>(sum.tasks),
                  static_cast<unsigned long long>(sum.pixels), sum.busySeconds / count,
                  sum.idleSeconds / count, static_cast<unsigned long long>(sum.messagesSent),
                  static_cast<unsigned long long>(sum.bytesSent));
    out += line;
  }
  if (group > 1) {
    out += "(" + std::to_string(n) + " workers in groups of " + std::to_string(group) +
           ": tasks, pixels, messages and bytes summed; speed_s the median; slowdown, busy_s "
           "and idle_s the means; ! a group with a lost worker)\n";
  }
  if (!info.speedIndexRun) out += "(speed_s: no speed index was run, so none is shown)\n";
  auto opt = [](const std::optional<double>& v, const char* fmt) {
    if (!v) return std::string("n/a");
    char b[32];
    std::snprintf(b, sizeof b, fmt, *v);
    return std::string(b);
  };
  std::snprintf(line, sizeof line,
                "strategy %s (%s), %zu workers: elapsed %.3f s, speed-up %s, efficiency %.1f%%, "
                "MASU %s, ASU %s, %llu messages, %llu bytes\n",
                info.strategy.c_str(), info.driver.c_str(), workers.size(), elapsedSeconds,
                opt(speedup, "%.2f").c_str(), 100 * efficiency,
                masu > 0 ? opt(masu, "%.2f").c_str() : "n/a",
                asu ? opt(std::optional<double>(100 * *asu), "%.1f%%").c_str() : "n/a",
                static_cast<unsigned long long>(messages), static_cast<unsigned long long>(bytes));
  out += line;
  if (const std::optional<double> share = masterBusyShare()) {
    const MasterLoad& m = *info.master;
    std::snprintf(line, sizeof line,
                  "master: busy %.1f%% of the run (%s), %llu messages in and %llu out, "
                  "heartbeats %llu in and %llu out\n",
                  100 * *share, m.basis == "measured_cpu" ? "CPU time" : "modelled",
                  static_cast<unsigned long long>(m.received),
                  static_cast<unsigned long long>(m.sent),
                  static_cast<unsigned long long>(m.heartbeatsReceived),
                  static_cast<unsigned long long>(m.heartbeatsSent));
    out += line;
    if (m.checkpoints > 0) {
      std::snprintf(line, sizeof line, "master: %llu checkpoints written in %.2f s\n",
                    static_cast<unsigned long long>(m.checkpoints), m.checkpointSeconds);
      out += line;
    }
  }
  std::snprintf(line, sizeof line,
                "scene: %llu bytes, with every worker %.3f s after it was sent\n",
                static_cast<unsigned long long>(sceneBytes), sceneTransferSeconds);
  out += line;
  if (!info.frames.empty()) {
    // When frames came out: the first and the last completed, and the median frame's span.
    std::vector<double> done, spans;
    for (const FrameInfo& fr : info.frames) {
      if (fr.doneSeconds) done.push_back(*fr.doneSeconds);
      if (fr.firstSeconds && fr.doneSeconds) spans.push_back(*fr.doneSeconds - *fr.firstSeconds);
    }
    std::sort(done.begin(), done.end());
    std::sort(spans.begin(), spans.end());
    std::snprintf(line, sizeof line,
                  "%zu frames, %.3f s per frame in the job; first complete at %s, last at %s; "
                  "median frame open for %s\n",
                  info.frames.size(), elapsedSeconds / static_cast<double>(info.frames.size()),
                  done.empty() ? "n/a" : opt(done.front(), "%.2f s").c_str(),
                  done.empty() ? "n/a" : opt(done.back(), "%.2f s").c_str(),
                  spans.empty() ? "n/a" : opt(spans[spans.size() / 2], "%.2f s").c_str());
    out += line;
  }
  if (!speedup) {
    out += masu > 0 ? "(speed-up and ASU need --serial-seconds T or --measure-serial)\n"
                    : "(speed-up, MASU and ASU need --serial-seconds T or --measure-serial)\n";
  }
  if (masuBasis != "speed_index") {
    out += "(no speed index was run: MASU and ASU are from the measured throughput)\n";
  }
  for (const LostWorkerInfo& l : info.faults.lostWorkers) {
    if (l.reason.rfind("rejected: ", 0) == 0) continue;  // said below, with what it cost
    std::snprintf(line, sizeof line,
                  "worker %d was lost at %.2f s (%s); its %llu unfinished tasks were reissued\n",
                  l.worker, l.atSeconds, l.reason.c_str(),
                  static_cast<unsigned long long>(l.unfinished));
    out += line;
  }
  for (const RejectedWorkerInfo& r : info.faults.rejectedWorkers) {
    std::snprintf(line, sizeof line, "worker %d was REJECTED at %.2f s: ", r.worker, r.atSeconds);
    out += line + r.reason + "; its " + std::to_string(r.pixelsTakenBack) +
           " pixels were taken back and rendered again\n";
  }
  for (const std::string& why : info.faults.refusedJoiners) {
    out += "a joining job was refused: " + why + "\n";
  }
  if (info.faults.verifyPercent > 0) {
    std::snprintf(
        line, sizeof line, "spot checks: %llu pixels verified bit for bit (--verify %g): ",
        static_cast<unsigned long long>(info.faults.verifiedPixels), info.faults.verifyPercent);
    out += line + spotCheckGuarantee(info.faults) + "\n";
  }
  for (int w : info.faults.missingSummaries) {
    out += "worker " + std::to_string(w) + " sent no summary: its times are missing\n";
  }
  if (const uint64_t bad = nonFiniteSamples(); bad > 0) {
    out += nonFiniteSamplesLine(bad) + "\n";
  }
  bool anyJoined = false;
  for (const WorkerReport& w : workers) {
    if (!w.joinedAtSeconds) continue;
    anyJoined = true;
    std::snprintf(line, sizeof line, "worker %d joined at %.2f s and rendered %llu pixels\n",
                  w.worker, *w.joinedAtSeconds, static_cast<unsigned long long>(w.pixels));
    out += line;
  }
  if (anyJoined && idealSeconds) {
    std::snprintf(line, sizeof line,
                  "a perfect balance of the same work, each worker from its arrival (speeds "
                  "by %s), takes %.3f s: this run took %.2fx that\n",
                  idealBasis.c_str(), *idealSeconds, elapsedSeconds / *idealSeconds);
    out += line;
  }
  if (info.faults.resumedPixels > 0) {
    out += std::to_string(info.faults.resumedPixels) + " pixels came from the checkpoint\n";
  }
  return out;
}

}  // namespace prt
