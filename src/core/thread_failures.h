#pragma once
// ThreadFailures: what the threads of a run threw, kept for the thread that started them.
//
// An exception that leaves a std::thread's function ends the whole process (std::terminate:
// SIGABRT, exit 134, no message). A thread body run through ThreadFailures::run instead stores
// the exception, the first of all of them being kept; the starting thread asks any() while it
// waits (to stop the run at once) and, once every thread is joined, rethrowFirst() hands the
// exception on to the one place that reports errors. A std::bad_alloc thus reaches main() as
// in a serial run and becomes "prt: error: out of memory ..." (see outOfMemoryMessage).
//
// Thread-safe: run() and any() may be called from any thread; rethrowFirst() after the joins.

#include <atomic>
#include <exception>
#include <mutex>
#include <string>

namespace prt {

class ThreadFailures {
 public:
  // Calls fn(); returns false, keeping the exception, if it threw.
  template <typename Fn>
  bool run(Fn&& fn) noexcept {
    try {
      fn();
      return true;
    } catch (...) {
      const std::lock_guard<std::mutex> lock(mutex_);
      if (!first_) first_ = std::current_exception();
      failed_.store(true);
      return false;
    }
  }

  bool any() const { return failed_.load(); }

  // Rethrows the first exception kept, if any.
  void rethrowFirst() const {
    const std::lock_guard<std::mutex> lock(mutex_);
    if (first_) std::rethrow_exception(first_);
  }

 private:
  mutable std::mutex mutex_;
  std::exception_ptr first_;
  std::atomic<bool> failed_{false};
};

// The message for a std::bad_alloc, in any thread: what ran out and what to do.
inline std::string outOfMemoryMessage() {
  return "out of memory: the run needs more memory than the system grants it (ulimit -v, "
         "cgroup limits or free RAM); use fewer --workers (each holds its own copy of the "
         "scene), a smaller image or a simpler scene";
}

}  // namespace prt
