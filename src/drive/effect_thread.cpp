#include "drive/effect_thread.h"

#include <chrono>

#include "core/thread_start.h"
#include "core/check.h"

namespace prt {

EffectThread::EffectThread() : thread_(startThread([this] { loop(); })) {}

EffectThread::~EffectThread() {
  {
    std::lock_guard lock(mutex_);
    quit_ = true;
  }
  wake_.notify_one();
  thread_.join();
}

void EffectThread::start(std::function<void()> job) {
  PRT_CHECK(!running_);
  {
    std::lock_guard lock(mutex_);
    job_ = std::move(job);
    finished_ = false;
    error_ = nullptr;
  }
  running_ = true;
  wake_.notify_one();
}

bool EffectThread::waitFor(double seconds) {
  PRT_CHECK(running_);
  std::unique_lock lock(mutex_);
  return done_.wait_for(lock, std::chrono::duration<double>(seconds), [&] { return finished_; });
}

void EffectThread::take() {
  std::exception_ptr error;
  {
    std::lock_guard lock(mutex_);
    PRT_CHECK(running_ && finished_);
    error = error_;
    error_ = nullptr;
  }
  running_ = false;
  if (error) std::rethrow_exception(error);
}

void EffectThread::loop() {
  std::unique_lock lock(mutex_);
  for (;;) {
    wake_.wait(lock, [&] { return quit_ || static_cast<bool>(job_); });
    if (quit_) return;
    std::function<void()> job = std::move(job_);
    job_ = nullptr;
    lock.unlock();
    std::exception_ptr error;
    try {
      job();
    } catch (...) {
      error = std::current_exception();
    }
    lock.lock();
    error_ = error;
    finished_ = true;
    done_.notify_one();
  }
}

}  // namespace prt
