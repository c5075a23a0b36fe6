#include "cluster/messages.h"

#include <bit>
#include <cstring>
#include <stdexcept>
#include <type_traits>

namespace prt {
namespace {

// Little-endian on every platform PRT runs on (x86-64, arm64); a static_assert would need
// std::endian, which we check instead.
static_assert(std::endian::native == std::endian::little, "encoding assumes little-endian");

class Writer {
 public:
  template <typename T>
  void pod(const T& v) {
    static_assert(std::is_trivially_copyable_v<T>);
    const auto* p = reinterpret_cast<const uint8_t*>(&v);
    out.insert(out.end(), p, p + sizeof(T));
  }
  void tasks(const TaskSet& s) {
    pod(static_cast<uint64_t>(s.runs().size()));
    for (const TaskRun& r : s.runs()) {
      pod(r.first);
      pod(r.count);
      pod(r.stride);
    }
  }
  Bytes out;
};

class Reader {
 public:
  Reader(const uint8_t* d, size_t n) : data(d), size(n) {}
  template <typename T>
  T pod() {
    need(sizeof(T));
    T v;
    std::memcpy(&v, data + pos, sizeof(T));
    pos += sizeof(T);
    return v;
  }
  TaskSet tasks() {
    const auto runs = pod<uint64_t>();
    need(runs * 24);
    TaskSet s;
    for (uint64_t i = 0; i < runs; ++i) {
      TaskRun r;
      r.first = pod<uint64_t>();
      r.count = pod<uint64_t>();
      r.stride = pod<uint64_t>();
      s.append(r);
    }
    return s;
  }
  void need(uint64_t n) const {
    if (n > size - pos) throw std::runtime_error("malformed message: truncated");
  }
  void finish() const {
    if (pos != size) throw std::runtime_error("malformed message: trailing bytes");
  }
  const uint8_t* data;
  size_t size;
  size_t pos = 0;
};

}  // namespace

Bytes encode(const Message& message) {
  Writer w;
  w.pod(static_cast<uint8_t>(message.index()));
  std::visit(
      [&](const auto& m) {
        using M = std::decay_t<decltype(m)>;
        if constexpr (std::is_same_v<M, SceneMsg>) {
          w.pod(static_cast<uint64_t>(m.sceneText.size()));
          w.out.insert(w.out.end(), m.sceneText.begin(), m.sceneText.end());
          w.pod(static_cast<int32_t>(m.samplesPerPixel));
          w.pod(static_cast<int32_t>(m.drtRate));
        } else if constexpr (std::is_same_v<M, SpeedIndexMsg>) {
          w.pod(m.seconds);
        } else if constexpr (std::is_same_v<M, TasksMsg>) {
          w.tasks(m.tasks);
        } else if constexpr (std::is_same_v<M, ResultsMsg>) {
          w.tasks(m.tasks);
          w.pod(static_cast<uint64_t>(m.rgb.size()));
          const auto* p = reinterpret_cast<const uint8_t*>(m.rgb.data());
          w.out.insert(w.out.end(), p, p + m.rgb.size() * sizeof(float));
        } else if constexpr (std::is_same_v<M, QueueLengthMsg>) {
          w.pod(m.length);
        } else if constexpr (std::is_same_v<M, TransferOrderMsg>) {
          w.pod(static_cast<int32_t>(m.to));
          w.pod(m.count);
        } else if constexpr (std::is_same_v<M, TransferNoticeMsg>) {
          w.pod(static_cast<int32_t>(m.to));
          w.tasks(m.tasks);
        }
      },
      message);
  return std::move(w.out);
}

Message decode(const uint8_t* data, size_t size) {
  Reader r(data, size);
  const auto tag = r.pod<uint8_t>();
  Message m;
  switch (tag) {
    case 0: {
      SceneMsg s;
      const auto n = r.pod<uint64_t>();
      r.need(n);
      s.sceneText.assign(reinterpret_cast<const char*>(data + r.pos), n);
      r.pos += n;
      s.samplesPerPixel = r.pod<int32_t>();
      s.drtRate = r.pod<int32_t>();
      m = std::move(s);
      break;
    }
    case 1: m = SpeedIndexMsg{r.pod<double>()}; break;
    case 2: m = TasksMsg{r.tasks()}; break;
    case 3: {
      ResultsMsg res;
      res.tasks = r.tasks();
      const auto n = r.pod<uint64_t>();
      r.need(n * sizeof(float));
      res.rgb.resize(n);
      std::memcpy(res.rgb.data(), data + r.pos, n * sizeof(float));
      r.pos += n * sizeof(float);
      if (res.rgb.size() != 3 * res.tasks.size()) {
        throw std::runtime_error("malformed message: results size mismatch");
      }
      m = std::move(res);
      break;
    }
    case 4: m = RequestMsg{}; break;
    case 5: m = QueryQueueMsg{}; break;
    case 6: m = QueueLengthMsg{r.pod<uint64_t>()}; break;
    case 7: {
      TransferOrderMsg t;
      t.to = r.pod<int32_t>();
      t.count = r.pod<uint64_t>();
      m = t;
      break;
    }
    case 8: {
      TransferNoticeMsg t;
      t.to = r.pod<int32_t>();
      t.tasks = r.tasks();
      m = std::move(t);
      break;
    }
    case 9: m = StopMsg{}; break;
    default: throw std::runtime_error("malformed message: unknown type " + std::to_string(tag));
  }
  r.finish();
  return m;
}

const char* messageName(const Message& message) {
  static constexpr const char* kNames[] = {"Scene",       "SpeedIndex",    "Tasks",
                                           "Results",     "Request",       "QueryQueue",
                                           "QueueLength", "TransferOrder", "TransferNotice",
                                           "Stop"};
  return kNames[message.index()];
}

}  // namespace prt
