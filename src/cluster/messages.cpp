#include "cluster/messages.h"

#include <cmath>
#include <iterator>
#include <stdexcept>

#include "core/byte_codec.h"

namespace prt {

std::string kernelsOf(const std::string& build) {
  const std::string key = "(trace kernels: ";
  const size_t at = build.find(key);
  if (at == std::string::npos) return "";
  const size_t begin = at + key.size(), end = build.find(')', begin);
  return end == std::string::npos ? "" : build.substr(begin, end - begin);
}
namespace {

// Task sets travel as their runs: a count, then (first, count, stride) for each.
void writeTasks(ByteWriter& w, const TaskSet& s) {
  w.pod(static_cast<uint64_t>(s.runs().size()));
  for (const TaskRun& r : s.runs()) {
    w.pod(r.first);
    w.pod(r.count);
    w.pod(r.stride);
  }
}

constexpr uint64_t kMaxTaskIndex = uint64_t{1} << 40;

TaskSet readTasks(ByteReader& r) {
  const auto runs = r.pod<uint64_t>();
  r.needItems(runs, 24);
  TaskSet s;
  uint64_t total = 0;
  for (uint64_t i = 0; i < runs; ++i) {
    TaskRun run;
    run.first = r.pod<uint64_t>();
    run.count = r.pod<uint64_t>();
    run.stride = r.pod<uint64_t>();
    // No image has 2^40 pixels: larger indices or counts are corruption, and would overflow
    // the task set's arithmetic (its last index, its size).
    const bool beyond = !run.endsBefore(kMaxTaskIndex + 1) || run.count > kMaxTaskIndex - total;
    if (beyond) r.fail("task run beyond 2^40 pixels");
    total += run.count;
    s.append(run);
  }
  return s;
}

// Colours travel as a count of floats and the floats; 3 per task of `tasks`.
void writeColours(ByteWriter& w, const std::vector<float>& rgb) {
  w.pod(static_cast<uint64_t>(rgb.size()));
  w.raw(rgb.data(), rgb.size() * sizeof(float));
}

std::vector<float> readColours(ByteReader& r, const TaskSet& tasks) {
  const auto n = r.pod<uint64_t>();
  r.needItems(n, sizeof(float));
  if (n != 3 * tasks.size()) throw std::runtime_error("malformed message: results size mismatch");
  std::vector<float> rgb(n);
  r.raw(rgb.data(), n * sizeof(float));
  return rgb;
}

}  // namespace

Bytes encode(const Message& message) {
  ByteWriter w;
  // Room for the small messages at once (and no GCC 12 -Wstringop-overflow false alarm on
  // the first insert into an empty vector).
  w.out.reserve(64);
  w.pod(static_cast<uint8_t>(message.index()));
  std::visit(
      [&](const auto& m) {
        using M = std::decay_t<decltype(m)>;
        if constexpr (std::is_same_v<M, SceneMsg>) {
          w.pod(static_cast<uint64_t>(m.sceneText.size()));
          w.raw(m.sceneText.data(), m.sceneText.size());
          w.pod(static_cast<int32_t>(m.samplesPerPixel));
          w.pod(static_cast<int32_t>(m.drtRate));
          w.pod(static_cast<uint64_t>(m.assets.size()));
          w.raw(m.assets.data(), m.assets.size());
          w.pod(m.frames.first);
          w.pod(m.frames.last);
          w.pod(m.frames.step);
          w.pod(m.frames.fps);
          w.pod(static_cast<uint8_t>(m.frames.animated));
        } else if constexpr (std::is_same_v<M, SpeedIndexMsg>) {
          w.pod(m.seconds);
          w.text(m.identity.build);
          w.text(m.identity.host);
        } else if constexpr (std::is_same_v<M, TasksMsg>) {
          writeTasks(w, m.tasks);
        } else if constexpr (std::is_same_v<M, ResultsMsg>) {
          writeTasks(w, m.tasks);
          writeColours(w, m.rgb);
          w.pod(m.computeSeconds);
        } else if constexpr (std::is_same_v<M, QueueLengthMsg>) {
          w.pod(m.length);
        } else if constexpr (std::is_same_v<M, TransferOrderMsg>) {
          w.pod(static_cast<int32_t>(m.to));
          w.pod(m.count);
        } else if constexpr (std::is_same_v<M, TransferNoticeMsg>) {
          w.pod(static_cast<int32_t>(m.to));
          writeTasks(w, m.tasks);
        } else if constexpr (std::is_same_v<M, CheckMsg>) {
          writeTasks(w, m.tasks);
        } else if constexpr (std::is_same_v<M, CheckResultsMsg>) {
          writeTasks(w, m.tasks);
          writeColours(w, m.rgb);
        }
      },
      message);
  return std::move(w.out);
}

Message decode(const uint8_t* data, size_t size) {
  ByteReader r(data, size, "message");
  const auto tag = r.pod<uint8_t>();
  Message m;
  switch (tag) {
    case 0: {
      SceneMsg s;
      const auto n = r.pod<uint64_t>();
      r.need(n);
      s.sceneText.resize(n);
      r.raw(s.sceneText.data(), n);
      s.samplesPerPixel = r.pod<int32_t>();
      s.drtRate = r.pod<int32_t>();
      const auto meshBytes = r.pod<uint64_t>();
      r.need(meshBytes);
      s.assets.resize(meshBytes);
      r.raw(s.assets.data(), meshBytes);
      s.frames.first = r.pod<int64_t>();
      s.frames.last = r.pod<int64_t>();
      s.frames.step = r.pod<int64_t>();
      s.frames.fps = r.pod<double>();
      s.frames.animated = r.pod<uint8_t>() != 0;
      // A sequence no command line could ask for is a damaged message.
      if (!(s.frames.step >= 1 && s.frames.first <= s.frames.last &&
            s.frames.first >= -FrameSequence::kMaxFrameNumber &&
            s.frames.last <= FrameSequence::kMaxFrameNumber &&
            s.frames.count() <= static_cast<uint64_t>(FrameSequence::kMaxFrames) &&
            std::isfinite(s.frames.fps) && s.frames.fps > 0)) {
        throw std::runtime_error("malformed message: a scene with an impossible frame sequence");
      }
      m = std::move(s);
      break;
    }
    case 1: {
      SpeedIndexMsg s;
      s.seconds = r.pod<double>();
      s.identity.build = r.text();
      s.identity.host = r.text();
      m = std::move(s);
      break;
    }
    case 2:
      m = TasksMsg{readTasks(r)};
      break;
    case 3: {
      ResultsMsg res;
      res.tasks = readTasks(r);
      res.rgb = readColours(r, res.tasks);
      res.computeSeconds = r.pod<double>();
      m = std::move(res);
      break;
    }
    case 4:
      m = RequestMsg{};
      break;
    case 5:
      m = QueryQueueMsg{};
      break;
    case 6:
      m = QueueLengthMsg{r.pod<uint64_t>()};
      break;
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
      t.tasks = readTasks(r);
      m = std::move(t);
      break;
    }
    case 9:
      m = StopMsg{};
      break;
    case 10:
      m = HeartbeatMsg{};
      break;
    case 11:
      m = CheckMsg{readTasks(r)};
      break;
    case 12: {
      CheckResultsMsg c;
      c.tasks = readTasks(r);
      c.rgb = readColours(r, c.tasks);
      m = std::move(c);
      break;
    }
    default:
      throw std::runtime_error("malformed message: unknown type " + std::to_string(tag));
  }
  r.finish();
  return m;
}

const char* messageName(const Message& message) {
  static constexpr const char* kNames[] = {
      "Scene",      "SpeedIndex",  "Tasks",         "Results",        "Request",
      "QueryQueue", "QueueLength", "TransferOrder", "TransferNotice", "Stop",
      "Heartbeat",  "Check",       "CheckResults"};
  static_assert(std::size(kNames) == std::variant_size_v<Message>);
  return kNames[message.index()];
}

}  // namespace prt
