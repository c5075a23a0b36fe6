#include "live/terminal_progress.h"

#include <sys/ioctl.h>
#include <unistd.h>

#include <chrono>
#include <cstdio>
#include <string>

#include "core/thread_start.h"
#include "live/progress_text.h"

namespace prt {
namespace {
constexpr double kShowAfterSeconds = 1.0;
constexpr double kRedrawSeconds = 0.2;

int terminalRows() {
  winsize size{};
  if (ioctl(STDERR_FILENO, TIOCGWINSZ, &size) == 0 && size.ws_row > 0) return size.ws_row;
  return 24;
}
}  // namespace

TerminalProgress::TerminalProgress(const ProgressBoard& board, bool enabled) : board_(board) {
  if (!enabled) return;
  terminal_ = isatty(STDERR_FILENO) != 0;
  thread_ = startThread([this] { run(); });
}

TerminalProgress::~TerminalProgress() { stop(); }

void TerminalProgress::stop() {
  {
    std::lock_guard lock(mutex_);
    if (stopping_) return;
    stopping_ = true;
  }
  wake_.notify_all();
  if (thread_.joinable()) thread_.join();
  clear();
}

void TerminalProgress::run() {
  using Clock = std::chrono::steady_clock;
  const auto start = Clock::now();
  const double period = terminal_ ? kRedrawSeconds : kPlainLineSeconds;
  auto next = start + std::chrono::duration_cast<Clock::duration>(std::chrono::duration<double>(
                          terminal_ ? kShowAfterSeconds : kPlainLineSeconds));
  std::unique_lock lock(mutex_);
  while (!stopping_) {
    if (wake_.wait_until(lock, next, [this] { return stopping_; })) break;
    lock.unlock();
    draw(terminal_);
    lock.lock();
    next += std::chrono::duration_cast<Clock::duration>(std::chrono::duration<double>(period));
  }
}

void TerminalProgress::draw(bool terminal) {
  const ProgressSnapshot s = board_.snapshot();
  if (s.version == 0 || s.phase == ProgressSnapshot::Phase::Finished ||
      s.phase == ProgressSnapshot::Phase::Failed) {
    return;
  }
  if (!terminal) {
    std::string line = "prt: " + progressSummary(s);
    if (const std::string workers = workerSummary(s); !workers.empty()) line += "; " + workers;
    std::fprintf(stderr, "%s\n", line.c_str());
    std::fflush(stderr);
    return;
  }
  const std::vector<std::string> lines = progressLines(s, std::min(16, terminalRows() - 3));
  std::string out;
  if (drawnLines_ > 1) out += "\x1b[" + std::to_string(drawnLines_ - 1) + "A";
  out += "\r";
  for (size_t i = 0; i < lines.size(); ++i) {
    out += "\x1b[2K" + lines[i];
    if (i + 1 < lines.size()) out += "\n";
  }
  // Fewer lines than last time (workers summarised): clear the rest below.
  out += "\x1b[J";
  std::fputs(out.c_str(), stderr);
  std::fflush(stderr);
  drawnLines_ = static_cast<int>(lines.size());
}

void TerminalProgress::clear() {
  if (!terminal_ || drawnLines_ == 0) return;
  std::string out;
  if (drawnLines_ > 1) out += "\x1b[" + std::to_string(drawnLines_ - 1) + "A";
  out += "\r\x1b[J";
  std::fputs(out.c_str(), stderr);
  std::fflush(stderr);
  drawnLines_ = 0;
}

}  // namespace prt
