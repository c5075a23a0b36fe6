#pragma once
// TerminalProgress: a render's progress on stderr, from a ProgressBoard, drawn by a thread
// of its own. On a terminal: a row per worker (a summary line past a screenful) and a bar
// with the ETA, redrawn in place five times a second from the first second on, cleared at the
// end. Elsewhere (a pipe, a log file, mpirun's forwarding): one plain line every
// `kPlainLineSeconds`, so short runs print nothing and long ones leave a readable log.
// Disabled (quiet): nothing at all.

#include <condition_variable>
#include <mutex>
#include <thread>

#include "farm/progress_board.h"

namespace prt {

class TerminalProgress {
 public:
  static constexpr double kPlainLineSeconds = 10;

  TerminalProgress(const ProgressBoard& board, bool enabled);
  ~TerminalProgress();  // stop()
  // Ends the thread and clears what it drew. Safe to call more than once.
  void stop();

 private:
  void run();
  void draw(bool terminal);
  void clear();

  const ProgressBoard& board_;
  bool terminal_ = false;
  int drawnLines_ = 0;
  std::mutex mutex_;
  std::condition_variable wake_;
  bool stopping_ = false;
  std::thread thread_;
};

}  // namespace prt
