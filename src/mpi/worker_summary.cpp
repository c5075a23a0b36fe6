#include "mpi/worker_summary.h"

#include <algorithm>
#include <bit>
#include <cstring>
#include <limits>
#include <stdexcept>
#include <string>
#include <type_traits>

namespace prt {
namespace {

// The same byte order as the protocol messages (cluster/messages.cpp).
static_assert(std::endian::native == std::endian::little, "encoding assumes little-endian");

constexpr uint8_t kVersion = 1;

class Writer {
 public:
  template <typename T>
  void pod(const T& v) {
    static_assert(std::is_trivially_copyable_v<T>);
    const auto* p = reinterpret_cast<const uint8_t*>(&v);
    out.insert(out.end(), p, p + sizeof(T));
  }
  void text(const std::string& s) {
    if (s.size() > std::numeric_limits<uint16_t>::max()) {
      throw std::runtime_error("worker summary: event label too long");
    }
    pod(static_cast<uint16_t>(s.size()));
    out.insert(out.end(), s.begin(), s.end());
  }
  Bytes out;
};

class Reader {
 public:
  Reader(const uint8_t* d, size_t n) : data_(d), size_(n) {}
  template <typename T>
  T pod() {
    need(sizeof(T));
    T v;
    std::memcpy(&v, data_ + pos_, sizeof(T));
    pos_ += sizeof(T);
    return v;
  }
  std::string text() {
    const auto n = pod<uint16_t>();
    need(n);
    std::string s(reinterpret_cast<const char*>(data_ + pos_), n);
    pos_ += n;
    return s;
  }
  void need(uint64_t n) const {
    if (n > size_ - pos_) throw std::runtime_error("malformed worker summary: truncated");
  }
  void finish() const {
    if (pos_ != size_) throw std::runtime_error("malformed worker summary: trailing bytes");
  }

 private:
  const uint8_t* data_;
  size_t size_;
  size_t pos_ = 0;
};

constexpr size_t kMinEventBytes = 1 + 4 + 8 + 8 + 8 + 8 + 4 + 2;

}  // namespace

Bytes encodeSummary(const WorkerSummary& summary) {
  Writer w;
  w.pod(kVersion);
  w.pod(summary.rays);
  w.pod(summary.tasksReceived);
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
  Reader r(data, size);
  if (r.pod<uint8_t>() != kVersion) throw std::runtime_error("worker summary: unknown version");
  WorkerSummary s;
  s.rays = r.pod<uint64_t>();
  s.tasksReceived = r.pod<uint64_t>();
  const auto count = r.pod<uint64_t>();
  if (count > size / kMinEventBytes) throw std::runtime_error("malformed worker summary: count");
  s.events.reserve(count);
  for (uint64_t i = 0; i < count; ++i) {
    Event e;
    const auto kind = r.pod<uint8_t>();
    if (kind > static_cast<uint8_t>(EventKind::WorkerLost)) {
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
  double sceneSent = -1, speedIndexReceived = -1, speedIndexSent = -1;
  for (const Event& e : masterEvents) {
    if (e.kind == EventKind::MessageSent && e.peer == worker && e.label == "Scene" &&
        sceneSent < 0) {
      sceneSent = e.start;
    } else if (e.kind == EventKind::MessageReceived && e.peer == worker &&
               e.label == "SpeedIndex" && speedIndexReceived < 0) {
      speedIndexReceived = e.start;
    }
  }
  for (const Event& e : workerEvents) {
    if (e.kind == EventKind::MessageSent && e.peer == kMaster && e.label == "SpeedIndex") {
      speedIndexSent = e.start;
      break;
    }
  }
  if (sceneSent < 0) return 0;
  if (speedIndexReceived < 0 || speedIndexSent < 0) return sceneSent;
  const double oneWay = (speedIndexReceived - sceneSent - speedIndexSent) / 2;
  return sceneSent + std::max(0.0, oneWay);
}

}  // namespace prt
