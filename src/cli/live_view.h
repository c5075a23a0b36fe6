#pragma once
// LiveView: what a `prt render` shows while it runs, whatever renders it: the progress board,
// its lines on stderr (unless --quiet) and, with --serve, the live page. The render publishes
// to board(); finish() ends the lines and gives a watching page a moment to see the end.

#include <memory>
#include <optional>

#include "cli/render_options.h"
#include "farm/progress_board.h"
#include "live/live_server.h"
#include "live/terminal_progress.h"

namespace prt::cli {

class LiveView {
 public:
  // Binds --serve's address now (InputError when it cannot) and prints the page's address.
  LiveView(const RenderOptions& o, ProgressBoard::RunFacts facts);
  ~LiveView();
  ProgressBoard& board() { return board_; }
  // Ends the progress lines (before the summary is printed).
  void stopLines();
  // stopLines, and the page's last moment (once the outputs are written).
  void finish();

 private:
  ProgressBoard board_;
  std::unique_ptr<LiveServer> server_;
  std::optional<TerminalProgress> terminal_;
};

// Seconds on one steady clock, for the serial renders' progress.
double steadySeconds();

}  // namespace prt::cli
