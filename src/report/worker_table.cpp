#include "report/worker_table.h"

#include <algorithm>
#include <map>
#include <set>

#include "report/page_fields.h"

namespace prt::page {
namespace {

const std::set<std::string> kKnownWorkerKeys = {
    "worker", "speed_index_s", "slowdown",          "tasks",      "pixels",         "busy_s",
    "idle_s", "messages_sent", "messages_received", "bytes_sent", "bytes_received", "lost"};

// Whether the workers ran a speed index: the report's MASU comes from it when they did.
bool speedIndexMeasured(const json& r) { return text(r, "masu_basis") != "measured_throughput"; }

std::string speedIndexText(const json& r, double seconds) {
  return speedIndexMeasured(r) && seconds > 0 ? formatSeconds(seconds) : "not measured";
}

std::string workerRow(const json& w, const json& r, double totalPixels, double elapsed,
                      const std::vector<std::string>& extraKeys, const std::string& colour) {
  const int id = w.value("worker", 0);
  const double masterIndex = numberOr(r, "master_speed_index_s", 0);
  const double index = numberOr(w, "speed_index_s", 0);
  const double busyShare = elapsed > 0 ? numberOr(w, "busy_s", 0) / elapsed : 0;
  std::string s = "<tr class=\"worker" + std::string(w.value("lost", false) ? " lost-row" : "") +
                  "\" data-first=\"" + std::to_string(id) + "\" data-last=\"" + std::to_string(id) +
                  "\">";
  auto cell = [&](const std::string& shown, const json& raw, const char* key) {
    s += "<td data-key=\"" + std::string(key) + "\" data-value=\"" + escapeHtml(attributeJson(raw)) +
         "\">" + shown + "</td>";
  };
  cell(chip(colour) + std::to_string(id), w.value("worker", json()), "worker");
  const bool indexed = speedIndexMeasured(r) && masterIndex > 0 && index > 0;
  cell(escapeHtml(speedIndexText(r, index)), w.value("speed_index_s", json()), "speed_index_s");
  cell(indexed ? formatNumber(masterIndex / index) : "n/a",
       indexed ? json(masterIndex / index) : json(), "relative_speed");
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
  cell(w.value("lost", false) ? "<b class=\"fault-text\">lost</b>" : "", w.value("lost", json()),
       "lost");
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
      if (hiddenWhileZero(key, value)) continue;  // a column only when some worker has one
      if (!kKnownWorkerKeys.count(key) &&
          std::find(extraKeys.begin(), extraKeys.end(), key) == extraKeys.end()) {
        extraKeys.push_back(key);
      }
    }
  }
  std::string s = "<table class=\"workers\" id=\"" + id +
                  "\"><thead><tr><th>worker</th>"
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
  std::string s =
      "<table class=\"classes\"><thead><tr><th>workers</th><th>slowdown</th>"
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
         (hi > lo ? "–" + formatNumber(hi) : "") + "×</td><td>" + speedIndexText(r, index / m) +
         "</td><td>" + formatCount(static_cast<uint64_t>(pixels)) + " <small>" +
         formatPercent(totalPixels > 0 ? pixels / totalPixels : 0) + "</small></td><td>" +
         formatPercent(elapsed > 0 ? busy / m / elapsed : 0) + "</td><td>" +
         (lost ? formatCount(lost) : "") + "</td></tr>\n";
  }
  return s + "</tbody></table>\n";
}

}  // namespace

std::string workersSection(const json& r, const std::vector<std::string>& colours) {
  double totalPixels = 0;
  for (const json& w : r["workers"]) totalPixels += numberOr(w, "pixels", 0);
  std::string s =
      "<section><h2>Workers</h2>\n<p class=\"lead\">A worker's speed index is the "
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

std::string workerInfo(const json& w, const json& r, double totalPixels) {
  const int id = w.value("worker", 0);
  const double elapsed = numberOr(r, "elapsed_s", 0);
  std::string s =
      "worker " + std::to_string(id) + ": " + formatCount(count(w, "pixels")) + " pixels (" +
      formatPercent(totalPixels > 0 ? numberOr(w, "pixels", 0) / totalPixels : 0) +
      "), rendering " + formatPercent(elapsed > 0 ? numberOr(w, "busy_s", 0) / elapsed : 0) +
      " of the run, speed index " + speedIndexText(r, numberOr(w, "speed_index_s", 0)) +
      ", slowdown " +
      formatNumber(numberOr(w, "slowdown", 1)) + "×";
  if (w.value("lost", false)) s += ", lost";
  return s;
}

}  // namespace prt::page
