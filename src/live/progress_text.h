#pragma once
// How progress reads as text: durations, the worker table of the terminal and the one-line
// summaries, from a ProgressSnapshot. Pure functions, unit-tested.

#include <string>
#include <vector>

#include "farm/progress_board.h"

namespace prt {

// "0.4 s", "12 s", "3 min 05 s", "2 h 04 min".
std::string formatDuration(double seconds);
// "12,345".
std::string groupDigits(uint64_t value);

// "45.2% of 76,800 px, 12 s, ETA 15 s" (ETA "estimating" until there is one).
std::string progressSummary(const ProgressSnapshot& s);
// "4 workers: 3 working, 1 lost" (empty for a serial render).
std::string workerSummary(const ProgressSnapshot& s);

// The terminal's lines: a header and one row per worker when at most `maxWorkerRows` of
// them, else the worker summary; then a bar of `barWidth` and the progress summary.
std::vector<std::string> progressLines(const ProgressSnapshot& s, int maxWorkerRows,
                                       int barWidth = 30);

}  // namespace prt
