#pragma once
// The master-worker protocol as typed messages, with an explicit binary encoding so every
// transport (threads, MPI) moves and counts the same bytes. The flow, as in the paper:
//   master -> worker  SceneMsg            the scene text and render settings
//   worker -> master  SpeedIndexMsg       the worker's Towers of Hanoi time, and who it is
//   master -> worker  TasksMsg            pixels to render (also worker -> worker, diffusion)
//   worker -> master  ResultsMsg          a batch of rendered pixels with their positions
//   worker -> master  RequestMsg          "request for more": the worker's queue is empty
//   master -> worker  QueryQueueMsg       diffusion: how long is your queue?
//   worker -> master  QueueLengthMsg      the answer
//   master -> worker  TransferOrderMsg    diffusion: send up to `count` tasks to worker `to`
//   worker -> master  TransferNoticeMsg   which tasks it sent, so the master can recover them
//   master -> worker  StopMsg             the image is complete
//   either way        HeartbeatMsg        "still here": renews the sender's lease while it
//                                         renders or waits (see drive/worker_loop.h)
//   master -> worker  CheckMsg            spot checks: render these pixels another worker
//                                         delivered, before the next batch (cluster/spot_checks.h)
//   worker -> master  CheckResultsMsg     their colours, compared bit for bit by the master
// Endpoints are worker indices 0..c-1 and kMaster.

#include <cstdint>
#include <string>
#include <variant>
#include <vector>

#include "core/frame_sequence.h"
#include "core/task_set.h"

namespace prt {

inline constexpr int kMaster = -1;

struct SceneMsg {
  std::string sceneText;  // the scene in .scene syntax, written by writeScene()
  int samplesPerPixel = 1;
  int drtRate = 1;
  std::vector<uint8_t> assets = {};  // its meshes, imported models and textures (scene/asset_pack.h)
  FrameSequence frames = {};  // the frames to render: task i*P + p is pixel p of the i-th frame
  bool operator==(const SceneMsg&) const = default;
};
// What a worker says of itself: its build (`prt --version`) and its machine's name, for the
// master's version rule and its blocklist; empty in the simulator.
struct WorkerIdentity {
  std::string build;
  std::string host;
  bool operator==(const WorkerIdentity&) const = default;
};
// The build of the trace kernels a build description names: "x86-64-v4" of
// "prt 0.1.0 (trace kernels: x86-64-v4)"; "" when it names none.
std::string kernelsOf(const std::string& build);
struct SpeedIndexMsg {
  double seconds = 0;
  WorkerIdentity identity = {};
  bool operator==(const SpeedIndexMsg&) const = default;
};
struct TasksMsg {
  TaskSet tasks;
  bool operator==(const TasksMsg&) const = default;
};
struct ResultsMsg {
  TaskSet tasks;
  std::vector<float> rgb;  // 3 floats per task, in task order, linear RGB; empty only in the
                           // simulator, which renders no colours (never on a real transport)
  double computeSeconds = 0;  // the worker's measured time rendering them (0: unmeasured)
  bool operator==(const ResultsMsg&) const = default;
};
struct RequestMsg {
  bool operator==(const RequestMsg&) const = default;
};
struct QueryQueueMsg {
  bool operator==(const QueryQueueMsg&) const = default;
};
struct QueueLengthMsg {
  uint64_t length = 0;
  bool operator==(const QueueLengthMsg&) const = default;
};
struct TransferOrderMsg {
  int to = 0;
  uint64_t count = 0;
  bool operator==(const TransferOrderMsg&) const = default;
};
struct TransferNoticeMsg {
  int to = 0;
  TaskSet tasks;
  bool operator==(const TransferNoticeMsg&) const = default;
};
struct StopMsg {
  bool operator==(const StopMsg&) const = default;
};
struct HeartbeatMsg {
  bool operator==(const HeartbeatMsg&) const = default;
};
struct CheckMsg {
  TaskSet tasks;
  bool operator==(const CheckMsg&) const = default;
};
struct CheckResultsMsg {
  TaskSet tasks;
  std::vector<float> rgb;  // 3 floats per task, in task order
  bool operator==(const CheckResultsMsg&) const = default;
};

using Message = std::variant<SceneMsg, SpeedIndexMsg, TasksMsg, ResultsMsg, RequestMsg,
                             QueryQueueMsg, QueueLengthMsg, TransferOrderMsg, TransferNoticeMsg,
                             StopMsg, HeartbeatMsg, CheckMsg, CheckResultsMsg>;

// A message and where it goes.
struct Envelope {
  int to = kMaster;
  Message message;
};
using Outbox = std::vector<Envelope>;

using Bytes = std::vector<uint8_t>;
Bytes encode(const Message& message);
// Throws std::runtime_error on a malformed buffer (a transport fault, not user input).
Message decode(const uint8_t* data, size_t size);
inline Message decode(const Bytes& bytes) { return decode(bytes.data(), bytes.size()); }

const char* messageName(const Message& message);  // "Tasks", "Results", ... for traces and logs

}  // namespace prt
