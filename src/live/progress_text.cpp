#include "live/progress_text.h"

#include <cmath>
#include <cstdio>

namespace prt {

std::string formatDuration(double seconds) {
  char text[48];
  if (!std::isfinite(seconds) || seconds < 0) return "?";
  if (seconds < 10) {
    std::snprintf(text, sizeof text, "%.1f s", seconds);
  } else if (seconds < 60) {
    std::snprintf(text, sizeof text, "%.0f s", seconds);
  } else if (seconds < 3600) {
    const auto s = static_cast<long long>(std::lround(seconds));
    std::snprintf(text, sizeof text, "%lld min %02lld s", s / 60, s % 60);
  } else {
    const auto m = static_cast<long long>(std::lround(seconds / 60));
    std::snprintf(text, sizeof text, "%lld h %02lld min", m / 60, m % 60);
  }
  return text;
}

std::string groupDigits(uint64_t value) {
  std::string digits = std::to_string(value), out;
  for (size_t i = 0; i < digits.size(); ++i) {
    if (i > 0 && (digits.size() - i) % 3 == 0) out += ',';
    out += digits[i];
  }
  return out;
}

std::string progressSummary(const ProgressSnapshot& s) {
  const double fraction =
      s.pixelsTotal > 0 ? static_cast<double>(s.pixelsDone) / static_cast<double>(s.pixelsTotal)
                        : 0.0;
  char text[64];
  std::snprintf(text, sizeof text, "%.1f%%", 100 * fraction);
  std::string line = std::string(text) + " of " + groupDigits(s.pixelsTotal) + " px, " +
                     formatDuration(s.elapsedSeconds);
  if (s.phase == ProgressSnapshot::Phase::Finished) return line + ", done";
  if (s.phase == ProgressSnapshot::Phase::Failed) return line + ", stopped";
  line += s.etaSeconds ? ", ETA " + formatDuration(*s.etaSeconds) : ", ETA estimating";
  return line;
}

std::string workerSummary(const ProgressSnapshot& s) {
  if (s.workers.empty()) return "";
  int counts[5] = {0, 0, 0, 0, 0};
  for (const WorkerProgress& w : s.workers) ++counts[static_cast<int>(w.state)];
  std::string line = std::to_string(s.workers.size()) +
                     (s.workers.size() == 1 ? " worker:" : " workers:");
  bool first = true;
  for (const auto state : {WorkerProgress::State::Working, WorkerProgress::State::Idle,
                           WorkerProgress::State::Starting, WorkerProgress::State::Done,
                           WorkerProgress::State::Lost}) {
    const int n = counts[static_cast<int>(state)];
    if (n == 0) continue;
    line += std::string(first ? " " : ", ") + std::to_string(n) + " " + stateName(state);
    first = false;
  }
  return line;
}

std::vector<std::string> progressLines(const ProgressSnapshot& s, int maxWorkerRows,
                                       int barWidth) {
  std::vector<std::string> lines;
  if (!s.workers.empty() && static_cast<int>(s.workers.size()) <= maxWorkerRows) {
    char row[160];
    std::snprintf(row, sizeof row, "%6s  %-8s %12s %6s %10s %10s", "worker", "state", "pixels",
                  "share", "px/s", "heard");
    lines.emplace_back(row);
    for (size_t i = 0; i < s.workers.size(); ++i) {
      const WorkerProgress& w = s.workers[i];
      const double share = s.pixelsTotal > 0 ? 100.0 * static_cast<double>(w.pixels) /
                                                   static_cast<double>(s.pixelsTotal)
                                             : 0.0;
      const std::string heard =
          w.state == WorkerProgress::State::Lost ? "lost" : formatDuration(w.silentSeconds) + " ago";
      std::snprintf(row, sizeof row, "%6zu  %-8s %12s %5.1f%% %10s %10s", i, stateName(w.state),
                    groupDigits(w.pixels).c_str(), share,
                    groupDigits(static_cast<uint64_t>(std::lround(w.pixelsPerSecond))).c_str(),
                    heard.c_str());
      lines.emplace_back(row);
    }
  } else if (!s.workers.empty()) {
    lines.push_back(workerSummary(s));
  }
  const double fraction =
      s.pixelsTotal > 0 ? static_cast<double>(s.pixelsDone) / static_cast<double>(s.pixelsTotal)
                        : 0.0;
  const int filled = static_cast<int>(fraction * barWidth);
  std::string bar(static_cast<size_t>(filled), '#');
  bar.resize(static_cast<size_t>(barWidth), '-');
  lines.push_back("[" + bar + "] " + progressSummary(s));
  return lines;
}

}  // namespace prt
