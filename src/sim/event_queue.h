#pragma once
// EventQueue: the simulator's agenda, a min-heap of events ordered by (virtual time, sequence
// number). The sequence number breaks ties in the order events were scheduled, so a
// simulation is deterministic: the same inputs give the same event order, bit for bit.
// Not thread-safe.

#include <algorithm>
#include <cstdint>
#include <utility>
#include <vector>

#include "cluster/messages.h"

namespace prt {

enum class SimEventKind {
  Reach,       // a message reaches the receiver's port (its incoming link is reserved then)
  Deliver,     // a message is in the receiver's mailbox
  MasterDone,  // the master finished handling a message; its replies leave now
  WorkerDone,  // a worker finished its setup or its batch
  Join,        // worker `endpoint` joins the running render
  Fail,        // worker `endpoint`'s machine fails now, silently (--mtbf, --fail-share)
  Lost,        // the master hears that worker `endpoint`'s connection dropped
  Deadline,    // the master's next deadline (a lease, a checkpoint): MasterReactor::onDeadline
};

struct SimEvent {
  double time = 0;  // virtual seconds since the run began
  uint64_t seq = 0;
  SimEventKind kind = SimEventKind::Deliver;
  int endpoint = kMaster;  // where it happens
  int from = kMaster;      // messages: the sender
  uint64_t bytes = 0;      // messages: encoded size
  Message message;         // messages: the payload
};

class EventQueue {
 public:
  void push(SimEvent event) {
    event.seq = nextSeq_++;
    heap_.push_back(std::move(event));
    std::push_heap(heap_.begin(), heap_.end(), later);
  }
  // The earliest event; the queue must not be empty.
  SimEvent pop() {
    std::pop_heap(heap_.begin(), heap_.end(), later);
    SimEvent e = std::move(heap_.back());
    heap_.pop_back();
    return e;
  }
  bool empty() const { return heap_.empty(); }
  uint64_t scheduled() const { return nextSeq_; }  // events scheduled so far

 private:
  static bool later(const SimEvent& a, const SimEvent& b) {
    return a.time != b.time ? a.time > b.time : a.seq > b.seq;
  }
  std::vector<SimEvent> heap_;
  uint64_t nextSeq_ = 0;
};

}  // namespace prt
