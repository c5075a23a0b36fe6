#pragma once
// WorkerSummary: what a worker tells the master after StopMsg so the report can be built on
// the master the same way whatever the transport — the worker's event log, its ray count and
// the number of task messages it received. Sent once, on the transport's summary channel,
// outside the master-worker protocol (the protocol state machines never see it).
//
// Clocks: ranks may run on different machines whose clocks are not synchronised, so a worker
// times its events on its own steady clock and the master places them on its own timeline
// with workerClockOffset(), taking the worker's receipt of the scene as its reference. The scene send and the
// speed-index reply form one round trip: the master sends the scene at M0 and receives the
// speed index at M1 (master clock); the worker sends the speed index S seconds after receiving
// the scene (worker clock). Assuming the two legs take equally long, the scene arrived at
// M0 + (M1 - M0 - S) / 2, which keeps every aligned event causal: a worker's receipt is never
// before the master's send, nor its reply after the master's receipt. Pure functions; no MPI.

#include <cstdint>
#include <vector>

#include "cluster/messages.h"
#include "metrics/events.h"

namespace prt {

struct WorkerSummary {
  uint64_t rays = 0;           // rays traced by the worker
  uint64_t tasksReceived = 0;  // task messages received (assignments and transfers)
  int threads = 1;             // threads the worker rendered with
  double slowdown = 1;         // the --slowdown it was emulating (its own, for a joiner)
  std::vector<Event> events;   // seconds since the worker received the scene
  uint64_t framesBuilt = 0;    // frames of the sequence it prepared (a frame met again after
                               // another is prepared again)
  uint64_t nonFiniteSamples = 0;  // samples of its tasks not finite, left out of their pixels
  bool operator==(const WorkerSummary&) const = default;
};

Bytes encodeSummary(const WorkerSummary& summary);
// Throws std::runtime_error on a malformed buffer (a transport fault, not user input).
WorkerSummary decodeSummary(const uint8_t* data, size_t size);
inline WorkerSummary decodeSummary(const Bytes& bytes) {
  return decodeSummary(bytes.data(), bytes.size());
}

// Seconds to add to `worker`'s event times to put them on the master's clock, from the scene
// and speed-index messages in both logs (see above). Without a reply, the scene is taken to
// arrive as it was sent.
double workerClockOffset(const std::vector<Event>& masterEvents,
                         const std::vector<Event>& workerEvents, int worker);

}  // namespace prt
