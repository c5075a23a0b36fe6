#include "drive/transport.h"

#include <chrono>
#include <condition_variable>
#include <exception>
#include <mutex>
#include <thread>

#include "core/thread_start.h"

namespace prt {

void sendOutbox(Transport& net, int from, const Outbox& out, EventLog& log) {
  for (const Envelope& e : out) {
    Bytes bytes = encode(e.message);
    const double now = net.now();
    log.add({EventKind::MessageSent, from, now, now, 0, bytes.size(), e.to,
             messageName(e.message)});
    net.send(e.to, Channel::Protocol, std::move(bytes));
  }
}

void whileHeartbeating(Transport& net, double beat, const std::function<int()>& workers,
                       const std::function<void()>& work) {
  std::exception_ptr error;
  std::mutex mutex;
  std::condition_variable finished;
  bool done = false;
  std::thread thread = startThread([&] {
    try {
      work();
    } catch (...) {
      error = std::current_exception();
    }
    std::lock_guard<std::mutex> lock(mutex);
    done = true;
    finished.notify_one();
  });
  {
    std::unique_lock<std::mutex> lock(mutex);
    while (!finished.wait_for(lock, std::chrono::duration<double>(beat), [&] { return done; })) {
      lock.unlock();
      const Bytes heartbeat = encode(HeartbeatMsg{});
      for (int w = 0; workers && w < workers(); ++w) net.send(w, Channel::Protocol, heartbeat);
      lock.lock();
    }
  }
  thread.join();
  if (error) std::rethrow_exception(error);
}


}  // namespace prt
