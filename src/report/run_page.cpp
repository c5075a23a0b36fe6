#include "report/run_page.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <map>
#include <optional>
#include <set>

#include "report/html_text.h"
#include "report/page_assets.h"
#include "report/page_fields.h"
#include "report/timeline_svg.h"
#include "report/worker_table.h"

namespace prt {
namespace {

using nlohmann::json;
using namespace page;  // the page's forgiving field access, chips, the worker table

std::string card(const std::string& key, const std::string& value, const std::string& label,
                 const std::string& tip, const json& raw, const std::string& cls = "") {
  return "<div class=\"card" + (cls.empty() ? "" : " " + cls) + "\" data-key=\"" + escapeHtml(key) +
         "\" data-value=\"" + escapeHtml(attributeJson(raw)) + "\"><div class=\"value\">" +
         escapeHtml(shortText(value)) + "</div><div class=\"label\">" + escapeHtml(label) +
         "</div><div class=\"tip\">" + escapeHtml(tip) + "</div></div>\n";
}

// Speed-up against the ideal: a bar up to the worker count, MASU and the speed-up marked.
std::string speedupGauge(double workers, double masu, std::optional<double> speedup) {
  const double top = std::max({workers, masu, speedup.value_or(0), 1.0});
  auto pct = [&](double v) { return formatNumber(100 * std::clamp(v / top, 0.0, 1.0), 4) + "%"; };
  std::string s = "<div class=\"gauge\"><div class=\"gauge-title\">speed-up <b>" +
                  (speedup ? formatNumber(*speedup) : std::string("unknown")) +
                  "</b> (the bar) against MASU, the most these workers' speeds allow (the "
                  "mark)</div><div class=\"gauge-track\">";
  if (speedup) {
    s += "<div class=\"gauge-fill\" style=\"width:" + pct(*speedup) + "\"></div>";
  }
  s += "<div class=\"gauge-mark\" style=\"left:" + pct(masu) + "\" title=\"MASU\"></div></div>";
  s += "<div class=\"gauge-legend\"><span>0</span><span class=\"gauge-masu\" style=\"left:" +
       pct(masu) + "\">MASU " + formatNumber(masu) + "</span><span class=\"gauge-end\">" +
       formatNumber(top) + (top == workers ? " (one per worker)" : "") + "</span></div></div>";
  return s;
}

double maxBusy(const json& workers) {
  double most = 0;
  for (const json& w : workers) most = std::max(most, numberOr(w, "busy_s", 0));
  return most;
}

// What balancing bought, estimated from each worker's seconds per pixel in this run: the time
// the slowest worker would have needed for an equal share of the pixels, against the time
// had every worker finished together. Empty unless every worker rendered and none was lost.
std::string balanceEstimate(const json& r) {
  const json& workers = r["workers"];
  if (workers.size() < 2) return "";
  double slowest = 0, speed = 0, pixels = 0;
  for (const json& w : workers) {
    const double busy = numberOr(w, "busy_s", 0), p = numberOr(w, "pixels", 0);
    if (!(busy > 0) || !(p > 0) || w.value("lost", false)) return "";
    slowest = std::max(slowest, busy / p);
    speed += p / busy;
    pixels += p;
  }
  const double equal = slowest * pixels / static_cast<double>(workers.size());
  const double together = pixels / speed;
  return "<li><b>What the balancing bought:</b> judging by each worker's time per pixel here, "
         "an equal share of the pixels would have kept the slowest one rendering about <b>" +
         formatSeconds(equal) +
         "</b>; with every worker finishing together it would take "
         "about <b>" +
         formatSeconds(together) +
         "</b>; this run's workers rendered for at "
         "most <b>" +
         formatSeconds(maxBusy(workers)) + "</b>.</li>";
}

// "Worker 3 (at 1.25 s) was lost</b>; ...", from the table and the timeline's marks.
std::string lostWorkers(const json& r) {
  std::string list;
  size_t lost = 0;
  for (const json& w : r["workers"]) {
    if (!w.is_object() || !w.value("lost", false)) continue;
    ++lost;
    const int id = w.value("worker", 0);
    if (!list.empty()) list += ", ";
    list += std::to_string(id);
    for (const json& row : r.value("timeline", json::object()).value("rows", json::array())) {
      for (const json& m : row.value("marks", json::array())) {
        if (m.value("kind", std::string()) == "worker_lost" && m.value("worker", -1) == id) {
          list += " (at " + formatSeconds(m.value("t_s", 0.0)) + ")";
        }
      }
    }
  }
  if (lost == 0) return "";
  return "<li><b class=\"fault-text\">" + std::string(lost == 1 ? "Worker " : "Workers ") + list +
         (lost == 1 ? " was" : " were") +
         " lost</b>; the master gave the unfinished tasks to the others.</li>";
}

// "Worker 2 was rejected at 1.20 s: a spot check of pixel ... failed; its 4,000 pixels were
// taken back and rendered again."
std::string rejectedWorkers(const json& r) {
  const json rejected = r.value("rejected_workers", json::array());
  std::string s;
  if (rejected.is_array()) {
    for (const json& x : rejected) {
      if (!x.is_object()) continue;
      s += "<li><b class=\"fault-text\">Worker " + std::to_string(x.value("worker", 0)) +
           " was rejected at " + formatSeconds(x.value("at_s", 0.0)) + "</b>: " +
           escapeHtml(x.value("reason", std::string())) + "; its " +
           formatCount(x.value("pixels_taken_back", uint64_t{0})) +
           " pixels were taken back and rendered again.</li>";
    }
  }
  const double percent = r.value("verify_percent", 0.0);
  if (percent > 0) {
    s += "<li>Spot checks (--verify " + genericValue(json(percent)) + "): " +
         formatCount(r.value("verified_pixels", uint64_t{0})) +
         " pixels rendered again elsewhere came out bit for bit the same";
    const std::string guarantee = r.value("verify_guarantee", std::string());
    s += guarantee.empty() ? std::string(".</li>") : ": " + escapeHtml(guarantee) + ".</li>";
  }
  return s;
}

// "Workers 1, 2 joined mid-render (at 0.50 s) ...", with the ideal for that schedule.
std::string joinedWorkers(const json& r) {
  const json joined = r.value("joined_workers", json::array());
  if (!joined.is_array() || joined.empty()) return "";
  std::string list;
  uint64_t pixels = 0;
  for (const json& j : joined) {
    if (!j.is_object()) continue;
    const int id = j.value("worker", 0);
    if (!list.empty()) list += ", ";
    list += std::to_string(id) + " (at " + formatSeconds(j.value("at_s", 0.0)) + ")";
    for (const json& w : r["workers"]) {
      if (w.is_object() && w.value("worker", -1) == id) pixels += w.value("pixels", uint64_t{0});
    }
  }
  std::string s = "<li>" + std::string(joined.size() == 1 ? "Worker " : "Workers ") + list +
                  " joined the running render and rendered <b>" + formatCount(pixels) +
                  "</b> pixels.";
  const auto ideal = number(r, "ideal_s");
  const double elapsed = numberOr(r, "elapsed_s", 0);
  if (ideal && *ideal > 0 && elapsed > 0) {
    s += " A perfect balance of the same work, each worker counted from its arrival, takes " +
         formatSeconds(*ideal) + ": this run took <b>" + formatNumber(elapsed / *ideal) +
         "×</b> that.";
  }
  return s + "</li>";
}

// How close together the workers (or groups) sent their last results: the balance itself.
std::string finishSpread(const json& r) {
  const double elapsed = numberOr(r, "elapsed_s", 0);
  if (!r.contains("timeline") || !r["timeline"].contains("rows") || !(elapsed > 0)) return "";
  std::vector<double> finished;
  for (const json& row : r["timeline"]["rows"]) {
    const double f = numberOr(row, "finished_s", 0);
    bool lost = false;
    for (const json& m : row.value("marks", json::array())) {
      lost = lost || m.value("kind", std::string()) == "worker_lost";
    }
    if (f > 0 && !lost) finished.push_back(f);
  }
  if (finished.size() < 2) return "";
  const auto [lo, hi] = std::minmax_element(finished.begin(), finished.end());
  const bool groups = r["timeline"].value("aggregated", false);
  return "<li>The " + std::string(groups ? "groups of workers" : "workers") +
         " sent their last results within <b>" + formatSeconds(*hi - *lo) +
         "</b> of one another (" + formatPercent((*hi - *lo) / elapsed) +
         " of the run): the smaller, the better the work was shared out.</li>";
}

std::string glance(const json& r) {
  const size_t workers = r["workers"].size();
  const auto speedup = number(r, "speedup");
  const double masu = numberOr(r, "masu", 0);
  const auto asu = number(r, "asu");
  std::string s = "<section class=\"glance\"><h2>At a glance</h2>";
  s += speedupGauge(static_cast<double>(workers), masu, speedup);
  s += "<ul class=\"glance-list\">";
  if (speedup) {
    s += "<li>The " + formatCount(workers) + " workers made the image <b>" +
         formatNumber(*speedup) +
         " times faster</b> than one machine alone (speed-up). Their "
         "speeds allow at most " +
         formatNumber(masu) + " (MASU): the run reached <b>" +
         (asu ? formatPercent(*asu) : std::string("n/a")) + "</b> of that ideal (ASU).</li>";
  } else {
    s += "<li>The workers' speeds allow a speed-up of at most " + formatNumber(masu) +
         " (MASU). This run has no serial time, so its own speed-up is unknown: rerun with "
         "<code>--measure-serial</code> or <code>--serial-seconds T</code>.</li>";
  }
  s += "<li>On average a worker was rendering <b>" + formatPercent(numberOr(r, "efficiency", 0)) +
       "</b> of the run (efficiency); the rest it waited for the scene, for work, or for the "
       "others to finish.</li>";
  s += lostWorkers(r) + rejectedWorkers(r) + joinedWorkers(r) + balanceEstimate(r) + finishSpread(r);
  return s + "</ul></section>\n";
}

const std::set<std::string> kKnownKeys = {"driver",
                                          "strategy",
                                          "width",
                                          "height",
                                          "samples_per_pixel",
                                          "drt",
                                          "workers_count",
                                          "elapsed_s",
                                          "ideal_s",
                                          "ideal_basis",
                                          "serial_s",
                                          "speedup",
                                          "efficiency",
                                          "masu",
                                          "asu",
                                          "master_speed_index_s",
                                          "messages",
                                          "bytes",
                                          "rays",
                                          "workers",
                                          "context",
                                          "timeline",
                                          "ownership_map",
                                          "verify_guarantee",  // both said in words at a glance
                                          "verify_lowest_percent"};

std::string measures(const json& r) {
  const bool simulated = text(r, "driver") == "simulated";
  const auto speedup = number(r, "speedup"), asu = number(r, "asu");
  std::string s = "<section><h2>Measures</h2><div class=\"cards\">\n";
  s += card("elapsed_s", formatSeconds(numberOr(r, "elapsed_s", 0)), "elapsed",
            simulated ? "virtual time from the first message to the last result"
                      : "wall time from sending the scene to the last result",
            r.value("elapsed_s", json()));
  if (const auto ideal = number(r, "ideal_s")) {
    s += card("ideal_s", formatSeconds(*ideal), "ideal",
              "a perfect balance of the run's work, each worker from its arrival (speeds by " +
                  text(r, "ideal_basis") + ")",
              r.value("ideal_s", json()));
  }
  s += card(
      "speedup", speedup ? formatNumber(*speedup) + " ×" : "n/a", "speed-up",
      "serial time " +
          (number(r, "serial_s") ? formatSeconds(*number(r, "serial_s")) : std::string("unknown")) +
          " / elapsed",
      r.value("speedup", json()));
  const double masu = numberOr(r, "masu", 0);
  s += card("masu", masu > 0 ? formatNumber(masu) : "n/a", "MASU",
            masu > 0 ? "most the speeds allow: sum over workers of serial speed index / worker's"
                     : "needs the serial time (--serial-seconds or --measure-serial) or a speed "
                       "index",
            r.value("masu", json()));
  s += card("asu", asu ? formatPercent(*asu) : "n/a", "ASU",
            "speed-up / MASU: how close the run came to that ideal", r.value("asu", json()));
  s += card("efficiency", formatPercent(numberOr(r, "efficiency", 0)), "efficiency",
            "workers' rendering time / the time each was there", r.value("efficiency", json()));
  s += card("messages", formatCount(count(r, "messages")), "messages",
            "sent by the master and the workers", r.value("messages", json()));
  s += card("bytes", formatBytes(count(r, "bytes")), "bytes", "their encoded size",
            r.value("bytes", json()));
  s += "</div>\n";
  // Every other measure, labelled and grouped; raw keys only in "all report fields".
  struct Label {
    const char* group;
    const char* label;
    const char* meaning;
  };
  static const char* kFaults = "Faults and recovery";
  static const char* kNetwork = "Network";
  static const char* kBalance = "How the ideal was measured";
  static const char* kFrames = "Animation";
  static const std::map<std::string, Label> kLabels = {
      {"lost_workers", {kFaults, "lost workers", "declared lost by the master; their tasks went to others"}},
      {"reissued_tasks", {kFaults, "reissued tasks", "handed out again after a loss"}},
      {"rejected_workers", {kFaults, "rejected workers", "results found wrong by a spot check: stopped, every pixel they delivered rendered again"}},
      {"verified_pixels", {kFaults, "verified pixels", "rendered again by another worker (or the master) and found bit for bit the same"}},
      {"verify_percent", {kFaults, "spot-check rate", "the share of each worker's pixels checked (--verify; more for new workers)"}},
      {"refused_joiners", {kFaults, "refused joiners", "jobs that tried to join without this render's invitation, or of another PRT version"}},
      {"verify_seed", {kFaults, "spot-check seed", "which pixels were checked: --verify-seed repeats the sample"}},
      {"referee_checks", {kFaults, "checks by the master", "spot checks the master rendered itself (no other worker to do them)"}},
      {"duplicate_pixels", {kFaults, "duplicate pixels", "results that came twice; the first was kept"}},
      {"endgame_copies", {kFaults, "endgame copies", "tasks copied to idle workers at the end (--endgame)"}},
      {"missing_summaries", {kFaults, "missing summaries", "live workers whose times never came: their rows lack busy and idle times"}},
      {"resumed_pixels", {kFaults, "resumed pixels", "taken from a checkpoint instead of rendered"}},
      {"non_finite_samples", {kFaults, "non-finite samples", "samples whose value was NaN or infinite: left out of their pixels' means"}},
      {"joined_workers", {kFaults, "joined workers", "arrived mid-render"}},
      {"worker_timeout_s", {kFaults, "worker lease", "silence after which a worker is lost (--worker-timeout)"}},
      {"master_busy_share", {kNetwork, "master busy", "the share of the run the master spent handling messages (its CPU time outside its waits; modelled in a simulation): near 100 % it cannot keep up"}},
      {"heartbeat_s", {kNetwork, "heartbeat", "how long a worker or the master may stay silent before it says it is alive"}},
      {"scene_bytes", {kNetwork, "scene size", "the scene as sent to each worker"}},
      {"scene_transfer_s", {kNetwork, "scene transfer", "until every worker had the scene"}},
      {"masu_basis", {kBalance, "MASU from", "the workers' speed indices, or their measured throughput when none ran"}},
      {"measured_masu", {kBalance, "MASU by throughput", "sum of the workers' measured rates / the serial rate"}},
      {"measured_asu", {kBalance, "ASU by throughput", "speed-up / MASU by throughput"}},
      {"speed_index_masu", {kBalance, "MASU by speed index", "the paper's: sum of serial speed index / worker's"}},
      {"speed_index_asu", {kBalance, "ASU by speed index", "speed-up / MASU by speed index"}},
      {"ideal_basis", {kBalance, "ideal from", "the speeds the ideal time assumes"}},
      {"frame_count", {kFrames, "frames", "in the sequence, rendered as one job"}},
      {"fps", {kFrames, "frames per second", "the animation's speed (--fps)"}},
      {"seconds_per_frame", {kFrames, "per frame", "the job's time over its frames"}}};
  static const std::set<std::string> kFaultKeys = {"lost_workers", "reissued_tasks", "rejected_workers", "refused_joiners",
                                                   "missing_summaries", "duplicate_pixels", "non_finite_samples"};
  const auto humanValue = [](const std::string& key, const json& value) {
    if (value.is_string()) {
      const std::string v = value.get<std::string>();
      if (v == "measured_throughput") return std::string("measured throughput");
      if (v == "speed_index") return std::string("speed indices");
      if (v == "slowdown") return std::string("--slowdown factors");
      return v;
    }
    if (value.is_number() && key.size() > 2 && key.substr(key.size() - 2) == "_s") {
      return formatSeconds(value.get<double>());
    }
    if (key == "scene_bytes" && value.is_number()) return formatBytes(value.get<uint64_t>());

    if (key == "master_busy_share" && value.is_number()) {
      char b[32];
      std::snprintf(b, sizeof b, "%.1f %%", 100 * value.get<double>());
      return std::string(b);
    }
    return genericValue(value);
  };
  std::map<std::string, std::string> groups;  // group -> its cards
  std::string raw;
  for (const auto& [key, value] : r.items()) {
    if (!value.is_object() && !(value.is_array() && key == "workers")) {
      raw += "<tr><th>" + escapeHtml(key) + "</th><td>" +
             escapeHtml(value.is_null() ? std::string("(none)") : value.dump().substr(0, 200)) +
             "</td></tr>";
    }
    if (kKnownKeys.count(key) || value.is_object() || value.is_null()) continue;
    if (hiddenWhileZero(key, value)) continue;
    const auto known = kLabels.find(key);
    const std::string group = known != kLabels.end() ? known->second.group : "Other measures";
    const std::string label = known != kLabels.end() ? known->second.label : humanKey(key);
    const std::string tip = known != kLabels.end() ? known->second.meaning : "from the report";
    const bool fault = kFaultKeys.count(key) && ((value.is_array() && !value.empty()) ||
                                                 (value.is_number() && value.get<double>() > 0));
    std::string shown = humanValue(key, value), detail = tip;
    if (key == "joined_workers" && value.is_array()) {
      shown = formatCount(value.size());
      for (const json& j : value) {
        if (!j.is_object()) continue;
        detail += (detail == tip ? ": " : ", ") + std::string("worker ") +
                  std::to_string(j.value("worker", 0)) + " at " +
                  formatSeconds(j.value("at_s", 0.0));
        if (detail.size() > 160) break;
      }
    } else if (value.is_array()) {  // a list (of workers, say): its length, the list in the tip
      shown = formatCount(value.size());
      if (!value.empty()) detail += ": " + value.dump().substr(0, 120);
    }
    groups[group] += card(key, shown, label, detail, value, fault ? "fault" : "");
  }
  for (const char* group : {kFaults, kNetwork, kBalance, kFrames, "Other measures"}) {
    const auto g = groups.find(group);
    if (g == groups.end()) continue;
    s += "<h3>" + std::string(group) + "</h3><div class=\"cards\">\n" + g->second + "</div>\n";
  }
  s += "<details class=\"raw\"><summary>All report fields</summary><table class=\"raw\">" +
       raw + "</table></details>\n";
  s += "</section>\n";
  return s;
}

std::string mapsSection(const json& r, const PagePicture& picture,
                        const std::vector<std::string>& colours) {
  std::string s = "<section><h2>Who rendered what</h2><div class=\"maps\">\n<figure>";
  if (!picture.png.empty()) {
    s += "<div class=\"frame\"><img id=\"picture\" alt=\"the image\" src=\"" +
         pngDataUri(picture.png) + "\"><canvas id=\"picture-overlay\"></canvas></div>";
    s += "<figcaption>" + escapeHtml(picture.caption) + "</figcaption>";
  } else {
    s += "<div class=\"frame empty\">" + escapeHtml(picture.missing) + "</div>";
  }
  s += "</figure>\n<figure>";
  if (r.contains("ownership_map")) {
    s += "<div class=\"frame\"><canvas id=\"ownership\"></canvas></div><figcaption>Each pixel "
         "in the colour of the worker that rendered it. Hover a worker to pick it out, click to "
         "keep it.";
    const int step = r["ownership_map"].value("step", 1);
    if (step > 1) {
      s += " (Every " + std::to_string(step) + "th pixel in each direction, of " +
           std::to_string(r["ownership_map"].value("source_width", 0)) + "×" +
           std::to_string(r["ownership_map"].value("source_height", 0)) + ".)";
    }
    s += "</figcaption>";
  } else {
    s += "<div class=\"frame empty\">This report has no ownership map (it was written by a "
         "prt that did not record one).</div>";
  }
  s += "</figure>\n</div>\n<div class=\"legend\" id=\"workers-legend\">";
  const size_t n = r["workers"].size();
  if (n <= kWorkersListed) {
    for (size_t w = 0; w < n; ++w) {
      s += "<button class=\"worker\" data-first=\"" + std::to_string(w) + "\" data-last=\"" +
           std::to_string(w) + "\">" + chip(colours[w]) + "worker " + std::to_string(w) +
           "</button>";
    }
  } else {
    s += "<span class=\"note\">" + formatCount(n) +
         " workers: too many for a legend; hover "
         "the map or a timeline row to find one.</span>";
  }
  s += "</div>\n<p id=\"picked\" class=\"picked\">Hover the map, the legend, a timeline row or a "
       "table row to pick a worker.</p></section>\n";
  return s;
}

std::string timelineSection(const json& r, const std::vector<std::string>& colours) {
  std::string s = "<section><h2>Timeline</h2>\n";
  if (!r.contains("timeline")) {
    return s +
           "<p class=\"note\">This report has no timeline (it was written by a prt that "
           "did not record one).</p></section>\n";
  }
  const json& t = r["timeline"];
  s += "<p class=\"lead\">Top: the share of the workers rendering at each moment; the white "
       "above it is time lost to waiting. Below: one row per " +
       std::string(t.value("aggregated", false) ? "group of workers" : "worker") +
       ". Hover anything for details.</p>\n";
  const json frames = r.contains("frames") ? r["frames"] : json();
  s += "<div class=\"timeline-box\">" + timelineSvg(t, colours, frames) + "</div>\n";
  s += "<div class=\"legend\"><span>" + chip("#4e79a7") +
       "rendering (in the worker's colour)</span>"
       "<span><span class=\"chip setup-chip\"></span>setting up (scene, speed index)</span>"
       "<span><span class=\"chip waiting-chip\"></span>waiting</span>"
       "<span><span class=\"chip tick-chip\"></span>communicating (a message sent or "
       "received)</span>"
       "<span><span class=\"chip lost-chip\"></span>lost</span>"
       "<span><span class=\"chip absent-chip\"></span>not there yet (joined later)</span>"
       "<span><span class=\"chip mark-chip\"></span>other events (reissued tasks, "
       "...)</span>" +
       std::string(frames.is_array() && !frames.empty()
                       ? "<span><span class=\"chip frame-chip\"></span>a frame complete "
                         "(labelled with its number)</span>"
                       : "") +
       "</div>\n";
  if (t.value("aggregated", false)) {
    s += "<p class=\"note\">" + formatCount(t.value("workers", 0)) +
         " workers are too many to draw one by one: each row stands for " +
         std::to_string(t.value("workers_per_row", 1)) +
         " consecutive workers, shaded by the share of their time spent rendering, and "
         "messages are not drawn.</p>\n";
  }
  if (t.value("marks_dropped", 0) > 0) {
    s += "<p class=\"note\">" + formatCount(t.value("marks_dropped", uint64_t{0})) +
         " more events are not drawn (at most " + std::to_string(100) + " per row).</p>\n";
  }
  return s + "</section>\n";
}

std::string detailsSection(const json& r) {
  const json context = r.value("context", json::object());
  std::string s = "<section><h2>How the run was made</h2><dl class=\"details\">\n";
  auto row = [&](const std::string& term, const std::string& html) {
    if (!html.empty()) s += "<dt>" + escapeHtml(term) + "</dt><dd>" + html + "</dd>\n";
  };
  std::string strategy = "<b>" + escapeHtml(text(r, "strategy")) + "</b>";
  const json parameters = context.value("parameters", json::object());
  if (!parameters.empty()) {
    strategy += "<ul class=\"params\">";
    for (const auto& [key, value] : parameters.items()) {
      strategy += "<li><code>" + escapeHtml(key) + "</code> " +
                  escapeHtml(value.is_string() ? value.get<std::string>() : value.dump()) + "</li>";
    }
    strategy += "</ul>";
  }
  row("strategy and parameters", strategy);
  row("scene", escapeHtml(text(context, "scene")));
  row("image", std::to_string(r.value("width", 0)) + " × " + std::to_string(r.value("height", 0)) +
                   " pixels, " + std::to_string(r.value("samples_per_pixel", 1)) +
                   (r.value("samples_per_pixel", 1) == 1 ? " sample" : " samples") +
                   " per pixel, DRT " + std::to_string(r.value("drt", 1)) +
                   (count(r, "rays") ? ", " + formatCount(count(r, "rays")) + " rays" : ""));
  const std::string driver = text(r, "driver");
  row("driver", escapeHtml(driver == "local"       ? "local: worker threads in one process"
                           : driver == "mpi"       ? "mpi: one rank per worker, rank 0 the master"
                           : driver == "simulated" ? "simulated: virtual time over a cost map"
                                                   : driver));
  if (const auto serial = number(r, "serial_s")) row("serial time", formatSeconds(*serial));
  const double masterIndex = numberOr(r, "master_speed_index_s", 0);
  row("serial machine's speed index",
      masterIndex > 0 && text(r, "masu_basis") != "measured_throughput"
          ? formatSeconds(masterIndex)
          : std::string("not measured (no speed index was run)"));
  if (!text(context, "command_line").empty()) {
    row("command line",
        "<code class=\"command\">" + escapeHtml(text(context, "command_line")) + "</code>");
  }
  row("machine", escapeHtml(text(context, "machine")) +
                     (driver == "mpi" ? " (the master's; workers may run elsewhere)" : ""));
  row("date", escapeHtml(text(context, "date")));
  const json outputs = context.value("outputs", json::object());
  std::string files;
  for (const auto& [key, value] : outputs.items()) {
    files += (files.empty() ? "" : ", ") + escapeHtml(key) + " <code>" +
             escapeHtml(value.is_string() ? value.get<std::string>() : value.dump()) + "</code>";
  }
  row("files written", files);
  return s + "</dl></section>\n";
}

}  // namespace

std::vector<std::string> workerColours(int workers) {
  static const char* kTableau[] = {"#1f78b5", "#ff800d", "#2ba12b", "#d62629", "#9466bd",
                                   "#8c564a", "#e378c2", "#808080", "#bdbd21", "#17bfcf"};
  std::vector<std::string> out;
  for (int w = 0; w < workers; ++w) {
    if (workers <= 10) {
      out.push_back(kTableau[w]);
      continue;
    }
    // HSL with hue by the golden angle, saturation 0.62, lightness 0.5 alternating 0.42.
    const double h = std::fmod(137.508 * w, 360.0) / 60, s = 0.62, l = w % 2 ? 0.42 : 0.52;
    const double c = (1 - std::fabs(2 * l - 1)) * s, x = c * (1 - std::fabs(std::fmod(h, 2) - 1));
    double rgb[3] = {0, 0, 0};
    const int sector = static_cast<int>(h) % 6;
    const int order[6][3] = {{0, 1, 2}, {1, 0, 2}, {2, 0, 1}, {2, 1, 0}, {1, 2, 0}, {0, 2, 1}};
    const double parts[3] = {c, x, 0};
    for (int i = 0; i < 3; ++i) rgb[i] = parts[order[sector][i]] + l - c / 2;
    char hex[8];
    std::snprintf(hex, sizeof hex, "#%02x%02x%02x", static_cast<int>(std::lround(rgb[0] * 255)),
                  static_cast<int>(std::lround(rgb[1] * 255)),
                  static_cast<int>(std::lround(rgb[2] * 255)));
    out.push_back(hex);
  }
  return out;
}

std::string runPageHtml(const json& r, const PagePicture& picture) {
  const size_t n = r.contains("workers") && r["workers"].is_array() ? r["workers"].size() : 0;
  const std::vector<std::string> colours = workerColours(static_cast<int>(n));
  const std::string driver = text(r, "driver");
  const std::string title = "PRT run: " + text(r, "strategy") + " on " + formatCount(n) +
                            " workers" + (driver.empty() ? "" : " (" + driver + ")");
  std::string body =
      "<header><h1>" + escapeHtml(title) + "</h1><p class=\"sub\">" +
      escapeHtml(text(r.value("context", json::object()), "scene")) + " · " +
      std::to_string(r.value("width", 0)) + "×" + std::to_string(r.value("height", 0)) + " · " +
      escapeHtml(text(r.value("context", json::object()), "date")) + "</p></header>\n<main>\n";
  body += glance(r);
  body += measures(r);
  body += mapsSection(r, picture, colours);
  body += timelineSection(r, colours);
  body += workersSection(r, colours);
  body += detailsSection(r);
  body +=
      "</main>\n<footer>Made by prt. The run's report is embedded in this file as JSON "
      "(<code>script#prt-run</code>); <code>prt report</code> draws this page again from "
      "the saved report.</footer>\n";

  double totalPixels = 0;
  for (const json& w : r["workers"]) totalPixels += numberOr(w, "pixels", 0);
  json info = json::array();
  for (const json& w : r["workers"]) info.push_back(workerInfo(w, r, totalPixels));
  const json page = {{"colours", colours}, {"info", info}, {"picture_is_render", picture.isRender}};
  // A report too large to embed whole (an edited or a hostile one) keeps its smaller parts.
  std::vector<std::string> leftOut;
  const json embedded = embeddableReport(r, kMaxEmbeddedReportBytes, leftOut);
  if (!leftOut.empty()) {
    std::string keys;
    for (const std::string& key : leftOut) keys += (keys.empty() ? "" : ", ") + shortText(key, 60);
    body += "<p class=\"note\">The report is larger than a page embeds (" +
            formatBytes(kMaxEmbeddedReportBytes) + "); left out of this page's copy: " +
            escapeHtml(keys) + ". The saved report holds them.</p>\n";
  }
  body += "<script type=\"application/json\" id=\"prt-run\">" + jsonForScript(embedded) +
          "</script>\n";
  body +=
      "<script type=\"application/json\" id=\"prt-page\">" + jsonForScript(page) + "</script>\n";
  body += "<script>\n" + std::string(kPageScript) + "</script>\n";
  return htmlDocument(title, body);
}

}  // namespace prt
