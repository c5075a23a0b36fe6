#pragma once
// Mailbox: the in-process stand-in for a network endpoint. Messages travel as encoded bytes,
// exactly as over MPI, so both drivers count the same traffic. Thread-safe.

#include <chrono>
#include <condition_variable>
#include <deque>
#include <mutex>
#include <optional>

#include "cluster/messages.h"

namespace prt {

struct Mail {
  int from = kMaster;
  Bytes bytes;
  bool lost = false;  // not a message: the connection to `from` dropped
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
  std::optional<Mail> tryPop() {
    std::lock_guard lock(mutex_);
    return popLocked();
  }
  // Waits up to `timeout` for mail.
  std::optional<Mail> pop(std::chrono::duration<double> timeout) {
    std::unique_lock lock(mutex_);
    ready_.wait_for(lock, timeout, [&] { return !queue_.empty(); });
    return popLocked();
  }

 private:
  std::optional<Mail> popLocked() {
    if (queue_.empty()) return std::nullopt;
    Mail m = std::move(queue_.front());
    queue_.pop_front();
    return m;
  }
  std::mutex mutex_;
  std::condition_variable ready_;
  std::deque<Mail> queue_;
};

}  // namespace prt
