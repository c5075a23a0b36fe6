#pragma once
// ProgressBar: a one-line bar on stderr — done, rate, ETA — for renders longer than about a
// second. Silent when disabled or when stderr is not a terminal. Thread-safe: update() may be
// called from any thread.

#include <chrono>
#include <cstdint>
#include <mutex>
#include <string>

namespace prt::cli {

class ProgressBar {
 public:
  ProgressBar(std::string unit, bool enabled);
  ~ProgressBar();
  void update(uint64_t done, uint64_t total);
  void finish();  // clears the line

 private:
  std::string unit_;
  bool enabled_;
  bool drawn_ = false;
  std::mutex mutex_;
  std::chrono::steady_clock::time_point start_, lastDraw_;
};

}  // namespace prt::cli
