#pragma once
// Mailbox: the in-process stand-in for a network endpoint. Messages travel as encoded bytes,
// exactly as over MPI, so both drivers count the same traffic. Thread-safe.

#include <chrono>
#include <condition_variable>
#include <deque>
#include <mutex>
#include <optional>

#include "cluster/messages.h"
#include "drive/transport.h"

namespace prt {

struct Mail {
  int from = kMaster;
  Channel channel = Channel::Protocol;
  Bytes bytes;
  bool lost = false;    // not a message: the connection to `from` dropped
  bool joined = false;  // not a message: `from` connected (a worker joining the run)
  int relayTo = kMaster;  // for the master's mailbox: bound for worker relayTo, which has no
                          // mailbox here (it joined over a network): the master relays it
};

class Mailbox {
 public:
  void push(Mail mail) {
    {
      std::lock_guard lock(mutex_);
      queue_.push_back(std::move(mail));
    }
    ready_.notify_one();
  }
  // Waits until `deadline` at most for mail.
  std::optional<Mail> popUntil(std::chrono::steady_clock::time_point deadline) {
    std::unique_lock lock(mutex_);
    // A deadline already past is a poll: no wait at all (a timed wait on an expired deadline
    // still sleeps for the kernel's timer slack, some 50 us, on every batch).
    if (queue_.empty() && std::chrono::steady_clock::now() < deadline) {
      ready_.wait_until(lock, deadline, [&] { return !queue_.empty(); });
    }
    if (queue_.empty()) return std::nullopt;
    Mail m = std::move(queue_.front());
    queue_.pop_front();
    return m;
  }

 private:
  std::mutex mutex_;
  std::condition_variable ready_;
  std::deque<Mail> queue_;
};

}  // namespace prt
