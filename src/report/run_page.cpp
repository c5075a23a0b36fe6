#include "report/run_page.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <map>
#include <optional>
#include <set>

#include "report/html_text.h"
#include "report/page_assets.h"
#include "report/timeline_svg.h"

namespace prt {
namespace {

using nlohmann::json;

constexpr size_t kWorkersListed = 64;  // beyond: a summary by speed class first

std::optional<double> number(const json& j, const char* key) {
  if (!j.is_object() || !j.contains(key) || !j[key].is_number()) return std::nullopt;
  return j[key].get<double>();
}
double numberOr(const json& j, const char* key, double fallback) {
  return number(j, key).value_or(fallback);
}
std::string text(const json& j, const char* key) {
  return j.is_object() && j.contains(key) && j[key].is_string() ? j[key].get<std::string>() : "";
}
uint64_t count(const json& j, const char* key) {
  const auto v = number(j, key);
  return v && *v > 0 ? static_cast<uint64_t>(std::llround(*v)) : 0;
}
std::string humanKey(std::string key) {
  std::replace(key.begin(), key.end(), '_', ' ');
  return key;
}
// A JSON value of a key nobody told the page about, readably.
std::string genericValue(const json& v) {
  if (v.is_array()) return std::to_string(v.size()) + (v.empty() ? "" : ": " + v.dump());
  if (v.is_string()) return v.get<std::string>();
  if (v.is_number_float()) return formatNumber(v.get<double>(), 4);
  return v.dump();
}

std::string card(const std::string& key, const std::string& value, const std::string& label,
                 const std::string& tip, const json& raw, const std::string& cls = "") {
  return "<div class=\"card" + (cls.empty() ? "" : " " + cls) + "\" data-key=\"" +
         escapeHtml(key) + "\" data-value=\"" + escapeHtml(raw.dump()) + "\"><div class=\"value\">" +
         escapeHtml(value) + "</div><div class=\"label\">" + escapeHtml(label) +
         "</div><div class=\"tip\">" + escapeHtml(tip) + "</div></div>\n";
}

std::string chip(const std::string& colour) {
  return "<span class=\"chip\" style=\"background:" + colour + "\"></span>";
}

// Speed-up against the ideal: a bar up to the worker count, MASU and the speed-up marked.
std::string speedupGauge(double workers, double masu, std::optional<double> speedup) {
  const double top = std::max({workers, masu, speedup.value_or(0), 1.0});
  auto pct = [&](double v) { return formatNumber(100 * std::clamp(v / top, 0.0, 1.0), 4) + "%"; };
  std::string s = "<div class=\"gauge\"><div class=\"gauge-track\">";
  if (speedup) {
    s += "<div class=\"gauge-fill\" style=\"width:" + pct(*speedup) + "\"></div>";
  }
  s += "<div class=\"gauge-mark\" style=\"left:" + pct(masu) + "\" title=\"MASU\"></div></div>";
  s += "<div class=\"gauge-legend\"><span>0</span><span class=\"gauge-masu\" style=\"left:" +
       pct(masu) + "\">MASU " + formatNumber(masu) + "</span><span class=\"gauge-end\">" +
       formatNumber(top) + (top == workers ? " (one per worker)" : "") + "</span></div></div>";
  return s;
}

std::string glance(const json& r) {
  const size_t workers = r["workers"].size();
  const double elapsed = numberOr(r, "elapsed_s", 0);
  const auto speedup = number(r, "speedup");
  const double masu = numberOr(r, "masu", 0);
  const auto asu = number(r, "asu");
  const double efficiency = numberOr(r, "efficiency", 0);
  std::string s = "<section class=\"glance\"><h2>At a glance</h2>";
  s += speedupGauge(static_cast<double>(workers), masu, speedup);
  s += "<p>";
  if (speedup) {
    s += "The " + formatCount(workers) + " workers finished the image <b>" +
         formatNumber(*speedup) + " times faster</b> than one machine alone (speed-up). Their "
         "speeds allowed at most " + formatNumber(masu) + " (MASU), so the balancing reached <b>" +
         (asu ? formatPercent(*asu) : std::string("n/a")) + "</b> of the ideal (ASU). ";
  } else {
    s += "The workers' speeds allow a speed-up of at most " + formatNumber(masu) +
         " (MASU). This run has no serial time, so its own speed-up is unknown: rerun with "
         "<code>--measure-serial</code> or <code>--serial-seconds T</code>. ";
  }
  s += "On average a worker was rendering <b>" + formatPercent(efficiency) +
       "</b> of the run (efficiency); the rest it waited for work, for the scene, or for the "
       "others to finish.";
  // Lost workers, from the table and the timeline's marks.
  std::string lostList;
  size_t lostCount = 0;
  for (const json& w : r["workers"]) {
    if (!w.is_object() || !w.value("lost", false)) continue;
    ++lostCount;
    const int id = w.value("worker", 0);
    if (!lostList.empty()) lostList += ", ";
    lostList += std::to_string(id);
    for (const json& row : r.value("timeline", json::object()).value("rows", json::array())) {
      for (const json& m : row.value("marks", json::array())) {
        if (m.value("kind", std::string()) == "worker_lost" && m.value("worker", -1) == id) {
          lostList += " (at " + formatSeconds(m.value("t_s", 0.0)) + ")";
        }
      }
    }
  }
  if (lostCount > 0) {
    s += " <b class=\"fault-text\">" + std::string(lostCount == 1 ? "Worker " : "Workers ") +
         lostList + (lostCount == 1 ? " was" : " were") +
         " lost</b>; the master gave the unfinished tasks to the others.";
  }
  // How close together the workers ran out of work: the balance itself.
  if (r.contains("timeline") && r["timeline"].contains("rows")) {
    std::vector<double> finished;
    for (const json& row : r["timeline"]["rows"]) {
      const double f = numberOr(row, "finished_s", 0);
      bool lost = false;
      for (const json& m : row.value("marks", json::array())) {
        lost = lost || m.value("kind", std::string()) == "worker_lost";
      }
      if (f > 0 && !lost) finished.push_back(f);
    }
    if (finished.size() >= 2 && elapsed > 0) {
      const auto [lo, hi] = std::minmax_element(finished.begin(), finished.end());
      const bool groups = r["timeline"].value("aggregated", false);
      s += " The " + std::string(groups ? "groups of workers" : "workers") +
           " sent their last results within <b>" + formatSeconds(*hi - *lo) + "</b> of one "
           "another (" + formatPercent((*hi - *lo) / elapsed) +
           " of the run): the smaller, the better the work was shared out.";
    }
  }
  s += "</p></section>\n";
  return s;
}

const std::set<std::string> kKnownKeys = {
    "driver", "strategy", "width", "height", "samples_per_pixel", "drt", "workers_count",
    "elapsed_s", "serial_s", "speedup", "efficiency", "masu", "asu", "master_speed_index_s",
    "messages", "bytes", "rays", "workers", "context", "timeline", "ownership_map"};

std::string measures(const json& r) {
  const bool simulated = text(r, "driver") == "simulated";
  const auto speedup = number(r, "speedup"), asu = number(r, "asu");
  std::string s = "<section><h2>Measures</h2><div class=\"cards\">\n";
  s += card("elapsed_s", formatSeconds(numberOr(r, "elapsed_s", 0)), "elapsed",
            simulated ? "virtual time from the first message to the last result"
                      : "wall time from sending the scene to the last result",
            r.value("elapsed_s", json()));
  s += card("speedup", speedup ? formatNumber(*speedup) + " ×" : "n/a", "speed-up",
            "serial time " + (number(r, "serial_s") ? formatSeconds(*number(r, "serial_s"))
                                                    : std::string("unknown")) +
                " / elapsed",
            r.value("speedup", json()));
  s += card("masu", formatNumber(numberOr(r, "masu", 0)), "MASU",
            "most the speeds allow: sum over workers of serial speed index / worker's",
            r.value("masu", json()));
  s += card("asu", asu ? formatPercent(*asu) : "n/a", "ASU",
            "speed-up / MASU: how close the run came to that ideal", r.value("asu", json()));
  s += card("efficiency", formatPercent(numberOr(r, "efficiency", 0)), "efficiency",
            "workers' rendering time / (elapsed × workers)", r.value("efficiency", json()));
  s += card("messages", formatCount(count(r, "messages")), "messages",
            "sent by the master and the workers", r.value("messages", json()));
  s += card("bytes", formatBytes(count(r, "bytes")), "bytes", "their encoded size",
            r.value("bytes", json()));
  s += "</div>\n";
  // Fault and recovery counts and any measure added after this page was written.
  static const std::map<std::string, std::pair<std::string, std::string>> kLabels = {
      {"lost_workers", {"lost workers", "declared lost by the master; their tasks went to others"}},
      {"reissued_tasks", {"reissued tasks", "handed out again after a loss or as duplicates"}},
      {"resumed_pixels", {"resumed pixels", "taken from a checkpoint instead of rendered"}}};
  std::string extra;
  for (const auto& [key, value] : r.items()) {
    if (kKnownKeys.count(key) || value.is_object() || value.is_null()) continue;
    const auto known = kLabels.find(key);
    const std::string label = known != kLabels.end() ? known->second.first : humanKey(key);
    const std::string tip = known != kLabels.end() ? known->second.second : "from the report";
    const bool fault = known != kLabels.end() &&
                       ((value.is_array() && !value.empty()) || (value.is_number() && value.get<double>() > 0));
    std::string shown = genericValue(value), detail = tip;
    if (value.is_array()) {  // a list (of workers, say): its length, the list in the tip
      shown = formatCount(value.size());
      if (!value.empty()) detail += ": " + value.dump().substr(0, 120);
    }
    extra += card(key, shown, label, detail, value, fault ? "fault" : "");
  }
  if (!extra.empty()) s += "<h3>Faults, recovery and other measures</h3><div class=\"cards\">\n" + extra + "</div>\n";
  s += "</section>\n";
  return s;
}

std::string workerInfo(const json& w, const json& r, double totalPixels) {
  const int id = w.value("worker", 0);
  const double elapsed = numberOr(r, "elapsed_s", 0);
  std::string s = "worker " + std::to_string(id) + ": " + formatCount(count(w, "pixels")) +
                  " pixels (" + formatPercent(totalPixels > 0 ? numberOr(w, "pixels", 0) / totalPixels : 0) +
                  "), rendering " + formatPercent(elapsed > 0 ? numberOr(w, "busy_s", 0) / elapsed : 0) +
                  " of the run, speed index " + formatSeconds(numberOr(w, "speed_index_s", 0)) +
                  ", slowdown " + formatNumber(numberOr(w, "slowdown", 1)) + "×";
  if (w.value("lost", false)) s += ", lost";
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
    s += "<span class=\"note\">" + formatCount(n) + " workers: too many for a legend; hover "
         "the map or a timeline row to find one.</span>";
  }
  s += "</div>\n<p id=\"picked\" class=\"picked\">Hover the map, the legend, a timeline row or a "
       "table row to pick a worker.</p></section>\n";
  return s;
}

std::string timelineSection(const json& r, const std::vector<std::string>& colours) {
  std::string s = "<section><h2>Timeline</h2>\n";
  if (!r.contains("timeline")) {
    return s + "<p class=\"note\">This report has no timeline (it was written by a prt that "
               "did not record one).</p></section>\n";
  }
  const json& t = r["timeline"];
  s += "<p class=\"lead\">Top: the share of the workers rendering at each moment; the white "
       "above it is time lost to waiting. Below: one row per " +
       std::string(t.value("aggregated", false) ? "group of workers" : "worker") +
       ". Hover anything for details.</p>\n";
  s += "<div class=\"timeline-box\">" + timelineSvg(t, colours) + "</div>\n";
  s += "<div class=\"legend\"><span>" + chip("#4e79a7") + "rendering (in the worker's colour)</span>"
       "<span><span class=\"chip setup-chip\"></span>setting up (scene, speed index)</span>"
       "<span><span class=\"chip waiting-chip\"></span>waiting</span>"
       "<span><span class=\"chip tick-chip\"></span>communicating (a message sent or received)</span>"
       "<span><span class=\"chip lost-chip\"></span>lost</span>"
       "<span><span class=\"chip mark-chip\"></span>other events (reissued tasks, ...)</span></div>\n";
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

const std::set<std::string> kKnownWorkerKeys = {
    "worker", "speed_index_s", "slowdown", "tasks", "pixels", "busy_s", "idle_s",
    "messages_sent", "messages_received", "bytes_sent", "bytes_received", "lost"};

std::string workerRow(const json& w, const json& r, double totalPixels, double elapsed,
                      const std::vector<std::string>& extraKeys, const std::string& colour) {
  const int id = w.value("worker", 0);
  const double masterIndex = numberOr(r, "master_speed_index_s", 0);
  const double index = numberOr(w, "speed_index_s", 0);
  const double busyShare = elapsed > 0 ? numberOr(w, "busy_s", 0) / elapsed : 0;
  std::string s = "<tr class=\"worker" + std::string(w.value("lost", false) ? " lost-row" : "") +
                  "\" data-first=\"" + std::to_string(id) + "\" data-last=\"" +
                  std::to_string(id) + "\">";
  auto cell = [&](const std::string& shown, const json& raw, const char* key) {
    s += "<td data-key=\"" + std::string(key) + "\" data-value=\"" + escapeHtml(raw.dump()) +
         "\">" + shown + "</td>";
  };
  cell(chip(colour) + std::to_string(id), w.value("worker", json()), "worker");
  cell(escapeHtml(formatSeconds(index)), w.value("speed_index_s", json()), "speed_index_s");
  cell(masterIndex > 0 && index > 0 ? formatNumber(masterIndex / index) : "n/a",
       masterIndex > 0 && index > 0 ? json(masterIndex / index) : json(), "relative_speed");
  cell(formatNumber(numberOr(w, "slowdown", 1)) + "×", w.value("slowdown", json()), "slowdown");
  cell(formatCount(count(w, "tasks")), w.value("tasks", json()), "tasks");
  cell(formatCount(count(w, "pixels")) + " <small>" +
           formatPercent(totalPixels > 0 ? numberOr(w, "pixels", 0) / totalPixels : 0) + "</small>",
       w.value("pixels", json()), "pixels");
  cell(escapeHtml(formatSeconds(numberOr(w, "busy_s", 0))), w.value("busy_s", json()), "busy_s");
  cell(escapeHtml(formatSeconds(numberOr(w, "idle_s", 0))), w.value("idle_s", json()), "idle_s");
  cell("<span class=\"bar\"><span style=\"width:" +
           formatNumber(100 * std::clamp(busyShare, 0.0, 1.0), 4) + "%;background:" + colour +
           "\"></span></span>" + formatPercent(busyShare),
       json(busyShare), "busy_share");
  cell(formatCount(count(w, "messages_sent") + count(w, "messages_received")),
       json(count(w, "messages_sent") + count(w, "messages_received")), "messages");
  cell(formatBytes(count(w, "bytes_sent") + count(w, "bytes_received")),
       json(count(w, "bytes_sent") + count(w, "bytes_received")), "bytes");
  cell(w.value("lost", false) ? "<b class=\"fault-text\">lost</b>" : "", w.value("lost", json()), "lost");
  for (const std::string& key : extraKeys) {
    cell(w.contains(key) ? escapeHtml(genericValue(w[key])) : "", w.value(key, json()),
         key.c_str());
  }
  return s + "</tr>\n";
}

std::string workerTable(const json& r, const std::vector<std::string>& colours, double totalPixels,
                        const std::string& id) {
  const double elapsed = numberOr(r, "elapsed_s", 0);
  std::vector<std::string> extraKeys;
  for (const json& w : r["workers"]) {
    if (!w.is_object()) continue;
    for (const auto& [key, value] : w.items()) {
      if (!kKnownWorkerKeys.count(key) &&
          std::find(extraKeys.begin(), extraKeys.end(), key) == extraKeys.end()) {
        extraKeys.push_back(key);
      }
    }
  }
  std::string s = "<table class=\"workers\" id=\"" + id + "\"><thead><tr><th>worker</th>"
                  "<th title=\"time of its speed-index run: lower is faster\">speed index</th>"
                  "<th title=\"serial machine's speed index / this worker's\">relative speed</th>"
                  "<th title=\"--slowdown: k times slower than the machine\">slowdown</th>"
                  "<th title=\"task messages received\">tasks</th><th>pixels</th>"
                  "<th>rendering</th><th>waiting</th><th>busy share</th><th>messages</th>"
                  "<th>bytes</th><th></th>";
  for (const std::string& key : extraKeys) s += "<th>" + escapeHtml(humanKey(key)) + "</th>";
  s += "</tr></thead><tbody>\n";
  for (const json& w : r["workers"]) {
    if (!w.is_object()) continue;
    const int worker = w.value("worker", 0);
    const std::string colour = worker >= 0 && static_cast<size_t>(worker) < colours.size()
                                   ? colours[static_cast<size_t>(worker)]
                                   : "#888888";
    s += workerRow(w, r, totalPixels, elapsed, extraKeys, colour);
  }
  return s + "</tbody></table>\n";
}

// Past kWorkersListed workers: one row per speed class (distinct slowdowns, or ten bands).
std::string speedClasses(const json& r, double totalPixels) {
  const double elapsed = numberOr(r, "elapsed_s", 0);
  std::map<double, std::vector<const json*>> classes;
  for (const json& w : r["workers"]) {
    const double k = numberOr(w, "slowdown", 1);
    classes[std::round(k * 1000) / 1000].push_back(&w);
  }
  if (classes.size() > 10) {  // ten bands of equal worker counts, by slowdown
    std::vector<const json*> all;
    for (auto& [k, ws] : classes) all.insert(all.end(), ws.begin(), ws.end());
    classes.clear();
    for (size_t i = 0; i < all.size(); ++i) {
      classes[static_cast<double>(i * 10 / all.size())].push_back(all[i]);
    }
  }
  std::string s = "<table class=\"classes\"><thead><tr><th>workers</th><th>slowdown</th>"
                  "<th>mean speed index</th><th>pixels</th><th>mean busy share</th><th>lost</th>"
                  "</tr></thead><tbody>\n";
  for (const auto& [key, ws] : classes) {
    double lo = 1e300, hi = 0, index = 0, pixels = 0, busy = 0;
    size_t lost = 0;
    for (const json* w : ws) {
      const double k = numberOr(*w, "slowdown", 1);
      lo = std::min(lo, k);
      hi = std::max(hi, k);
      index += numberOr(*w, "speed_index_s", 0);
      pixels += numberOr(*w, "pixels", 0);
      busy += numberOr(*w, "busy_s", 0);
      lost += w->value("lost", false) ? 1 : 0;
    }
    const double m = static_cast<double>(ws.size());
    s += "<tr><td>" + formatCount(ws.size()) + "</td><td>" + formatNumber(lo) +
         (hi > lo ? "–" + formatNumber(hi) : "") + "×</td><td>" + formatSeconds(index / m) +
         "</td><td>" + formatCount(static_cast<uint64_t>(pixels)) + " <small>" +
         formatPercent(totalPixels > 0 ? pixels / totalPixels : 0) + "</small></td><td>" +
         formatPercent(elapsed > 0 ? busy / m / elapsed : 0) + "</td><td>" +
         (lost ? formatCount(lost) : "") + "</td></tr>\n";
  }
  return s + "</tbody></table>\n";
}

std::string workersSection(const json& r, const std::vector<std::string>& colours) {
  double totalPixels = 0;
  for (const json& w : r["workers"]) totalPixels += numberOr(w, "pixels", 0);
  std::string s = "<section><h2>Workers</h2>\n<p class=\"lead\">A worker's speed index is the "
                  "time of a fixed benchmark on it; the strategy shares the work out by these "
                  "(relative speed: how many of the serial machine it is worth).</p>\n";
  if (r["workers"].size() > kWorkersListed) {
    s += "<p class=\"note\">" + formatCount(r["workers"].size()) +
         " workers: summarised by speed class; the full table is folded below.</p>\n";
    s += speedClasses(r, totalPixels);
    s += "<details><summary>All " + formatCount(r["workers"].size()) + " workers</summary>\n" +
         workerTable(r, colours, totalPixels, "workers-table") + "</details>\n";
  } else {
    s += workerTable(r, colours, totalPixels, "workers-table");
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
                   " samples per pixel, DRT " + std::to_string(r.value("drt", 1)) +
                   (count(r, "rays") ? ", " + formatCount(count(r, "rays")) + " rays" : ""));
  const std::string driver = text(r, "driver");
  row("driver", escapeHtml(driver == "local"       ? "local: worker threads in one process"
                           : driver == "mpi"       ? "mpi: one rank per worker, rank 0 the master"
                           : driver == "simulated" ? "simulated: virtual time over a cost map"
                                                   : driver));
  if (const auto serial = number(r, "serial_s")) row("serial time", formatSeconds(*serial));
  row("serial machine's speed index", formatSeconds(numberOr(r, "master_speed_index_s", 0)));
  if (!text(context, "command_line").empty()) {
    row("command line", "<code class=\"command\">" + escapeHtml(text(context, "command_line")) +
                            "</code>");
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
  std::string body = "<header><h1>" + escapeHtml(title) + "</h1><p class=\"sub\">" +
                     escapeHtml(text(r.value("context", json::object()), "scene")) + " · " +
                     std::to_string(r.value("width", 0)) + "×" + std::to_string(r.value("height", 0)) +
                     " · " + escapeHtml(text(r.value("context", json::object()), "date")) +
                     "</p></header>\n<main>\n";
  body += glance(r);
  body += measures(r);
  body += mapsSection(r, picture, colours);
  body += timelineSection(r, colours);
  body += workersSection(r, colours);
  body += detailsSection(r);
  body += "</main>\n<footer>Made by prt. The run's report is embedded in this file as JSON "
          "(<code>script#prt-run</code>); <code>prt report</code> draws this page again from "
          "the saved report.</footer>\n";

  double totalPixels = 0;
  for (const json& w : r["workers"]) totalPixels += numberOr(w, "pixels", 0);
  json info = json::array();
  for (const json& w : r["workers"]) info.push_back(workerInfo(w, r, totalPixels));
  const json page = {{"colours", colours}, {"info", info}, {"picture_is_render", picture.isRender}};
  body += "<script type=\"application/json\" id=\"prt-run\">" + jsonForScript(r) + "</script>\n";
  body += "<script type=\"application/json\" id=\"prt-page\">" + jsonForScript(page) +
          "</script>\n";
  body += "<script>\n" + std::string(kPageScript) + "</script>\n";
  return htmlDocument(title, body);
}

}  // namespace prt
