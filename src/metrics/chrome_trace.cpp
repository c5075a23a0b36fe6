#include "metrics/chrome_trace.h"

#include <algorithm>
#include <nlohmann/json.hpp>

namespace prt {
namespace {

// Track ids: the master is 0, worker w is w + 1.
int trackOf(int endpoint) { return endpoint + 1; }
double micros(double seconds) { return seconds * 1e6; }

}  // namespace

std::string chromeTraceJson(const std::vector<Event>& events, int workerCount,
                            double elapsedSeconds) {
  using nlohmann::json;
  json trace = json::array();
  auto name = [&](int endpoint, const std::string& label) {
    trace.push_back({{"ph", "M"}, {"pid", 1}, {"tid", trackOf(endpoint)}, {"name", "thread_name"},
                     {"args", {{"name", label}}}});
    trace.push_back({{"ph", "M"}, {"pid", 1}, {"tid", trackOf(endpoint)},
                     {"name", "thread_sort_index"}, {"args", {{"sort_index", trackOf(endpoint)}}}});
  };
  name(-1, "master");
  for (int w = 0; w < workerCount; ++w) name(w, "worker " + std::to_string(w));

  // Busy spans per worker, to derive the waiting spans between them.
  std::vector<std::vector<std::pair<double, double>>> busy(static_cast<size_t>(workerCount));
  for (const Event& e : events) {
    const int tid = trackOf(e.worker);
    switch (e.kind) {
      case EventKind::Setup:
      case EventKind::Compute: {
        const bool compute = e.kind == EventKind::Compute;
        json span = {{"ph", "X"}, {"pid", 1}, {"tid", tid}, {"ts", micros(e.start)},
                     {"dur", micros(e.end - e.start)}, {"name", compute ? "rendering" : "setup"},
                     {"cat", compute ? "render" : "setup"}};
        if (compute) span["args"] = {{"pixels", e.pixels}};
        trace.push_back(span);
        if (e.worker >= 0 && e.worker < workerCount) {
          busy[static_cast<size_t>(e.worker)].push_back({e.start, e.end});
        }
        break;
      }
      case EventKind::MessageSent:
        trace.push_back({{"ph", "i"}, {"s", "t"}, {"pid", 1}, {"tid", tid}, {"ts", micros(e.start)},
                         {"name", "send " + e.label}, {"cat", "communicate"},
                         {"args", {{"to", e.peer}, {"bytes", e.bytes}}}});
        break;
      case EventKind::MessageReceived:
        trace.push_back({{"ph", "i"}, {"s", "t"}, {"pid", 1}, {"tid", tid}, {"ts", micros(e.start)},
                         {"name", "receive " + e.label}, {"cat", "communicate"},
                         {"args", {{"from", e.peer}, {"bytes", e.bytes}}}});
        break;
      case EventKind::WorkerLost:
        trace.push_back({{"ph", "i"}, {"s", "g"}, {"pid", 1}, {"tid", trackOf(-1)},
                         {"ts", micros(e.start)}, {"name", "worker " + std::to_string(e.worker) + " lost"},
                         {"cat", "fault"}});
        break;
      case EventKind::WorkerJoined:
        trace.push_back({{"ph", "i"}, {"s", "g"}, {"pid", 1}, {"tid", trackOf(-1)},
                         {"ts", micros(e.start)},
                         {"name", "worker " + std::to_string(e.worker) + " joined"},
                         {"cat", "arrival"}});
        break;
    }
  }
  for (int w = 0; w < workerCount; ++w) {
    auto& spans = busy[static_cast<size_t>(w)];
    std::sort(spans.begin(), spans.end());
    double cursor = 0;
    for (const auto& [s, e] : spans) {
      if (s > cursor + 1e-6) {
        trace.push_back({{"ph", "X"}, {"pid", 1}, {"tid", trackOf(w)}, {"ts", micros(cursor)},
                         {"dur", micros(s - cursor)}, {"name", "waiting"}, {"cat", "idle"}});
      }
      cursor = std::max(cursor, e);
    }
    if (elapsedSeconds > cursor + 1e-6) {
      trace.push_back({{"ph", "X"}, {"pid", 1}, {"tid", trackOf(w)}, {"ts", micros(cursor)},
                       {"dur", micros(elapsedSeconds - cursor)}, {"name", "waiting"},
                       {"cat", "idle"}});
    }
  }
  json doc = {{"traceEvents", trace}, {"displayTimeUnit", "ms"}};
  return doc.dump() + "\n";
}

}  // namespace prt
