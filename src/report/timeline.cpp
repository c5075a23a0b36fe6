#include "report/timeline.h"

#include <algorithm>
#include <cmath>
#include <string>

namespace prt {
namespace {

using nlohmann::json;

double rounded(double share) {
  return std::round(share * 1000) / 1000;
}

// Adds [start, end) seconds, weighted by `weight`, to the per-tick totals.
void addOverlap(std::vector<double>& bins, double tickSeconds, double start, double end,
                double weight = 1) {
  if (!(end > start) || tickSeconds <= 0) return;
  const auto n = static_cast<long>(bins.size());
  long first = static_cast<long>(std::floor(start / tickSeconds));
  long last = static_cast<long>(std::floor(end / tickSeconds));
  first = std::clamp(first, 0L, n - 1);
  last = std::clamp(last, 0L, n - 1);
  for (long b = first; b <= last; ++b) {
    const double lo = std::max(start, static_cast<double>(b) * tickSeconds);
    const double hi = std::min(end, static_cast<double>(b + 1) * tickSeconds);
    if (hi > lo) bins[static_cast<size_t>(b)] += weight * (hi - lo);
  }
}

json shares(const std::vector<double>& seconds, double capacity) {
  json out = json::array();
  for (double s : seconds) out.push_back(capacity > 0 ? rounded(std::min(1.0, s / capacity)) : 0);
  return out;
}

// Spans in ticks, merged when less than a tick apart.
class SpanList {
 public:
  void add(long from, long to) { spans_.push_back({from, std::max(to, from + 1)}); }
  json toJson() {
    std::sort(spans_.begin(), spans_.end());
    json out = json::array();
    long from = 0, to = -2;
    for (const auto& [a, b] : spans_) {
      if (a <= to) {
        to = std::max(to, b);
        continue;
      }
      if (to >= 0) out.push_back({from, to});
      from = a;
      to = b;
    }
    if (to >= 0) out.push_back({from, to});
    return out;
  }

 private:
  std::vector<std::pair<long, long>> spans_;
};

struct Row {
  int first = 0, last = 0;
  SpanList rendering, setup;
  std::vector<long> messages;
  std::vector<double> renderingSeconds, setupSeconds;  // aggregated rows
  double finished = 0;
  json marks = json::array();
  size_t dropped = 0;
};

std::string markLabel(const Event& e) {
  if (e.kind == EventKind::WorkerLost) return "worker " + std::to_string(e.worker) + " lost";
  if (e.kind == EventKind::WorkerJoined) return "worker " + std::to_string(e.worker) + " joined";
  std::string label = eventKindName(e.kind);
  std::replace(label.begin(), label.end(), '_', ' ');
  if (e.pixels > 0) label += ", " + std::to_string(e.pixels) + " pixels";
  if (!e.label.empty()) label += ": " + e.label;
  return label;
}

}  // namespace

json timelineJson(const std::vector<Event>& events, int workers, double elapsedSeconds,
                  const TimelineOptions& options) {
  const int ticks = std::max(1, options.ticks);
  const int n = std::max(0, workers);
  const bool aggregated = n > options.maxRows;
  const int perRow = aggregated ? (n + options.maxRows - 1) / options.maxRows : 1;
  const int rowCount = n == 0 ? 0 : (n + perRow - 1) / perRow;
  double end = elapsedSeconds;
  for (const Event& e : events) end = std::max(end, e.end);  // a late event stays in view
  const double tickSeconds = end > 0 ? end / ticks : 1;
  const int bins = std::max(1, options.shareBins);
  const double binSeconds = end > 0 ? end / bins : 1;
  auto tickOf = [&](double t) {
    return std::clamp(static_cast<long>(std::floor(t / tickSeconds)), 0L, static_cast<long>(ticks));
  };

  std::vector<Row> rows(static_cast<size_t>(rowCount));
  for (int r = 0; r < rowCount; ++r) {
    Row& row = rows[static_cast<size_t>(r)];
    row.first = r * perRow;
    row.last = std::min(n, (r + 1) * perRow) - 1;
    if (aggregated) {
      row.renderingSeconds.assign(static_cast<size_t>(bins), 0);
      row.setupSeconds.assign(static_cast<size_t>(bins), 0);
    }
  }
  Row master;
  std::vector<double> rendering(static_cast<size_t>(bins), 0);

  for (const Event& e : events) {
    const bool onWorker = e.worker >= 0 && e.worker < n;
    Row& row = onWorker ? rows[static_cast<size_t>(e.worker / perRow)] : master;
    switch (e.kind) {
      case EventKind::Compute:
        if (!onWorker) break;
        addOverlap(rendering, binSeconds, e.start, e.end);
        row.finished = std::max(row.finished, e.end);
        if (aggregated) {
          addOverlap(row.renderingSeconds, binSeconds, e.start, e.end);
        } else {
          row.rendering.add(tickOf(e.start), tickOf(e.end));
        }
        break;
      case EventKind::Setup:
        if (!onWorker) break;
        if (aggregated) {
          addOverlap(row.setupSeconds, binSeconds, e.start, e.end);
        } else {
          row.setup.add(tickOf(e.start), tickOf(e.end));
        }
        break;
      case EventKind::MessageSent:
      case EventKind::MessageReceived:
        if (onWorker && !aggregated) row.messages.push_back(tickOf(e.start));
        break;
      default: {
        if (row.marks.size() >= static_cast<size_t>(options.maxMarksPerRow)) {
          ++row.dropped;
          break;
        }
        json mark = {{"kind", eventKindName(e.kind)},
                     {"label", markLabel(e)},
                     {"t_s", e.start},
                     {"worker", e.worker}};
        if (e.end > e.start) mark["end_s"] = e.end;
        row.marks.push_back(std::move(mark));
        break;
      }
    }
  }

  json out = {{"elapsed_s", elapsedSeconds}, {"ticks", ticks}, {"tick_s", tickSeconds},
              {"share_bins", bins},          {"workers", n},   {"workers_per_row", perRow},
              {"aggregated", aggregated}};
  out["rendering_share"] = shares(rendering, binSeconds * n);
  json rowsJson = json::array();
  size_t dropped = master.dropped;
  for (Row& row : rows) {
    json r = {{"first", row.first}, {"last", row.last}, {"finished_s", row.finished}};
    if (aggregated) {
      const double capacity = binSeconds * (row.last - row.first + 1);
      r["rendering_share"] = shares(row.renderingSeconds, capacity);
      r["setup_share"] = shares(row.setupSeconds, capacity);
    } else {
      r["rendering"] = row.rendering.toJson();
      r["setup"] = row.setup.toJson();
      std::sort(row.messages.begin(), row.messages.end());
      row.messages.erase(std::unique(row.messages.begin(), row.messages.end()), row.messages.end());
      r["messages"] = row.messages;
    }
    r["marks"] = std::move(row.marks);
    dropped += row.dropped;
    rowsJson.push_back(std::move(r));
  }
  out["rows"] = std::move(rowsJson);
  out["master_marks"] = std::move(master.marks);
  out["marks_dropped"] = dropped;
  return out;
}

}  // namespace prt
