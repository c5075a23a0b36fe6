#include "loops/worker_summary.h"

#include <algorithm>
#include <stdexcept>
#include <string>

#include "core/byte_codec.h"

namespace prt {
namespace {

// 2: the thread count; 3: the slowdown; 4: frames built; 5: samples not finite
constexpr uint8_t kSummaryVersion = 5;

constexpr size_t kMinEventBytes = 1 + 4 + 8 + 8 + 8 + 8 + 4 + 2;

}  // namespace

Bytes encodeSummary(const WorkerSummary& summary) {
  ByteWriter w;
  w.pod(kSummaryVersion);
  w.pod(summary.rays);
  w.pod(summary.tasksReceived);
  w.pod(static_cast<int32_t>(summary.threads));
  w.pod(summary.slowdown);
  w.pod(summary.framesBuilt);
  w.pod(summary.nonFiniteSamples);
  w.pod(static_cast<uint64_t>(summary.events.size()));
  for (const Event& e : summary.events) {
    w.pod(static_cast<uint8_t>(e.kind));
    w.pod(static_cast<int32_t>(e.worker));
    w.pod(e.start);
    w.pod(e.end);
    w.pod(e.pixels);
    w.pod(e.bytes);
    w.pod(static_cast<int32_t>(e.peer));
    w.text(e.label);
  }
  return std::move(w.out);
}

WorkerSummary decodeSummary(const uint8_t* data, size_t size) {
  ByteReader r(data, size, "worker summary");
  if (r.pod<uint8_t>() != kSummaryVersion)
    throw std::runtime_error("worker summary: unknown version");
  WorkerSummary s;
  s.rays = r.pod<uint64_t>();
  s.tasksReceived = r.pod<uint64_t>();
  s.threads = r.pod<int32_t>();
  if (s.threads < 1) throw std::runtime_error("malformed worker summary: thread count");
  s.slowdown = r.pod<double>();
  if (!(s.slowdown >= 1)) throw std::runtime_error("malformed worker summary: slowdown");
  s.framesBuilt = r.pod<uint64_t>();
  s.nonFiniteSamples = r.pod<uint64_t>();
  const auto count = r.pod<uint64_t>();
  if (count > size / kMinEventBytes) throw std::runtime_error("malformed worker summary: count");
  s.events.reserve(count);
  for (uint64_t i = 0; i < count; ++i) {
    Event e;
    const auto kind = r.pod<uint8_t>();
    if (kind > static_cast<uint8_t>(EventKind::WorkerJoined)) {
      throw std::runtime_error("malformed worker summary: event kind");
    }
    e.kind = static_cast<EventKind>(kind);
    e.worker = r.pod<int32_t>();
    e.start = r.pod<double>();
    e.end = r.pod<double>();
    e.pixels = r.pod<uint64_t>();
    e.bytes = r.pod<uint64_t>();
    e.peer = r.pod<int32_t>();
    e.label = r.text();
    s.events.push_back(std::move(e));
  }
  r.finish();
  return s;
}

double workerClockOffset(const std::vector<Event>& masterEvents,
                         const std::vector<Event>& workerEvents, int worker) {
  double sceneSent = -1, speedIndexReceived = -1;
  for (const Event& e : masterEvents) {
    if (e.kind == EventKind::MessageSent && e.peer == worker && e.label == "Scene" &&
        sceneSent < 0) {
      sceneSent = e.start;
    } else if (e.kind == EventKind::MessageReceived && e.peer == worker &&
               e.label == "SpeedIndex" && speedIndexReceived < 0) {
      speedIndexReceived = e.start;
    }
  }
  // The worker's clock may start anywhere: its receipt of the scene is its time 0 here.
  double sceneReceived = -1, speedIndexSent = -1;
  for (const Event& e : workerEvents) {
    if (e.kind == EventKind::MessageReceived && e.peer == kMaster && e.label == "Scene" &&
        sceneReceived < 0) {
      sceneReceived = e.start;
    } else if (e.kind == EventKind::MessageSent && e.peer == kMaster &&
               e.label == "SpeedIndex" && speedIndexSent < 0) {
      speedIndexSent = e.start;
    }
  }
  const double origin = sceneReceived < 0 ? 0.0 : sceneReceived;
  if (sceneSent < 0) return -origin;
  if (speedIndexReceived < 0 || speedIndexSent < 0) return sceneSent - origin;
  const double oneWay = (speedIndexReceived - sceneSent - (speedIndexSent - origin)) / 2;
  return sceneSent + std::max(0.0, oneWay) - origin;
}

}  // namespace prt
