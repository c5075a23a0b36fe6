#pragma once
// EffectThread: one long-lived thread that runs a worker's heavy effects (loading the scene,
// the speed index, rendering a batch) while the worker loop's own thread stays free to send
// heartbeats. One job at a time; the same thread runs every job, so per-thread state (the
// throttle's CPU clock) carries from one to the next. An exception in a job is rethrown by
// take(). The owner calls start/waitFor/take from one thread.

#include <condition_variable>
#include <exception>
#include <functional>
#include <mutex>
#include <thread>

namespace prt {

class EffectThread {
 public:
  EffectThread();
  ~EffectThread();
  EffectThread(const EffectThread&) = delete;
  EffectThread& operator=(const EffectThread&) = delete;

  // Starts `job`; none may be running.
  void start(std::function<void()> job);
  bool running() const { return running_; }
  // Waits until the job is done or `seconds` have passed; true when done.
  bool waitFor(double seconds);
  // After waitFor returned true: rethrows the job's exception, if any, and frees the thread.
  void take();

 private:
  void loop();

  std::mutex mutex_;
  std::condition_variable wake_;
  std::condition_variable done_;
  std::function<void()> job_;
  std::exception_ptr error_;
  bool finished_ = false;
  bool running_ = false;
  bool quit_ = false;
  std::thread thread_;
};

}  // namespace prt
