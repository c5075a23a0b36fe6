#pragma once
// The one event stream every driver emits (threads, MPI, the simulator). Metrics, the report,
// the Chrome trace and the ownership map are all computed from it; strategies, master and
// worker keep no timers of their own. Times are seconds since the run started.

#include <cstdint>
#include <string>
#include <vector>

namespace prt {

enum class EventKind {
  Setup,        // a worker loading the scene and measuring its speed index [start, end]
  Compute,      // a worker rendering a batch of `pixels` pixels [start, end]
  MessageSent,  // `bytes` sent to `peer` at `start`
  MessageReceived,  // `bytes` received from `peer` at `start`
  WorkerLost,   // the master declared `worker` lost at `start`
  WorkerJoined,  // `worker` joined the running render at `start` (on the master's clock)
};

struct Event {
  EventKind kind = EventKind::Compute;
  int worker = 0;     // the endpoint the event happened on: worker index, or -1 for the master
  double start = 0;   // seconds since the run began
  double end = 0;     // = start for instantaneous events
  uint64_t pixels = 0;  // Compute: pixels rendered
  uint64_t bytes = 0;   // messages: encoded size
  int peer = 0;         // messages: the other endpoint
  std::string label;    // messages: the message type ("Tasks", "Results", ...); Compute:
                        // kCheckLabel for a batch of spot checks (not the worker's pixels)
};

inline constexpr const char* kCheckLabel = "check";

// The kind's name in reports and pages ("compute", "worker_lost"). No default case: a new
// kind fails to compile (-Wswitch) until it is named here.
inline const char* eventKindName(EventKind kind) {
  switch (kind) {
    case EventKind::Setup: return "setup";
    case EventKind::Compute: return "compute";
    case EventKind::MessageSent: return "message_sent";
    case EventKind::MessageReceived: return "message_received";
    case EventKind::WorkerLost: return "worker_lost";
    case EventKind::WorkerJoined: return "worker_joined";
  }
  return "unknown";
}

// Collects events from one thread; drivers keep one log per thread and merge at the end.
struct EventLog {
  std::vector<Event> events;
  void add(Event e) { events.push_back(std::move(e)); }
  void merge(const EventLog& other) {
    events.insert(events.end(), other.events.begin(), other.events.end());
  }
};

}  // namespace prt
