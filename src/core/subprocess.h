#pragma once
// Running helper programs (POV-Ray, gnuplot, ffmpeg) as child processes: fork/exec with an
// argument vector, no shell, so no quoting; stdin from /dev/null (or a pipe the caller
// feeds), stdout and stderr to a log file.
// Each child runs in a process group of its own, which is ended whole (SIGKILL) when this
// process stops early: by a stop signal (see killRunningPrograms), or when the child is
// ended for want of progress. Nothing it started outlives it.
// Thread-safe: calls share only the table of running groups. Blocks until the child exits.

#include <filesystem>
#include <atomic>
#include <cstdint>
#include <functional>
#include <stdexcept>
#include <string>
#include <vector>

namespace prt {

// The executable `program` names: itself if it contains a '/', else the first match on PATH;
// empty if there is none.
std::string findProgram(const std::string& program);

// Runs the executable at `program` (a path, as findProgram returns) with `args` in
// `directory`, its stdout and stderr to `logFile`. Returns the wait status (see
// describeExit). Throws std::runtime_error "cannot run '<program>': <reason>" when it cannot
// be started.
// With `feedStdin`, the child's stdin is a pipe: feedStdin(fd) writes to it and the pipe
// is closed after; a child that stops reading makes the
// writes fail with EPIPE, never a SIGPIPE to this process. Exceptions from feedStdin pass
// on once the child has been waited for.
//
// With `watch`, the child is watched while it runs (every 50 ms): a stop signal that
// watch.stopSignal reports, or no progress for watch.stallSeconds, ends its process group
// (SIGKILL) and throws ProgramEnded once it is reaped and the feeding has returned.
struct ProgramWatch {
  // Seconds the child may go without progress; 0: no deadline. Progress is a change of
  // `progress` or of the size of any of `progressFiles`.
  double stallSeconds = 0;
  const std::atomic<uint64_t>* progress = nullptr;  // e.g. bytes the child took from stdin
  std::vector<std::filesystem::path> progressFiles;  // e.g. its output and its log
  std::function<int()> stopSignal;                   // a pending stop signal (0: none)
};

// A watched child ended early: by a stop signal (signal() > 0), or for making no progress
// within its deadline (signal() == 0).
class ProgramEnded : public std::runtime_error {
 public:
  ProgramEnded(const std::string& message, int signal)
      : std::runtime_error(message), signal_(signal) {}
  int signal() const { return signal_; }

 private:
  int signal_;
};

int runProgram(const std::string& program, const std::vector<std::string>& args,
               const std::filesystem::path& directory, const std::filesystem::path& logFile,
               const std::function<void(int)>& feedStdin = {},
               const ProgramWatch& watch = {});

// Ends (SIGKILL) the process group of every child runProgram is running. Async-signal-safe:
// for the handlers that end this process on a signal, so that no child outlives it.
void killRunningPrograms();

// "" for a clean exit (code 0), else "exited with code N" or "was killed by signal N".
std::string describeExit(int waitStatus);

// The whole file as bytes; empty if it cannot be read.
std::string readWholeFile(const std::filesystem::path& path);

// The last `count` lines of `text` (where a tool says what went wrong).
std::string lastLines(const std::string& text, int count);

// A fresh private directory under $TMPDIR (or /tmp), named `prefix` + random letters, removed
// with everything in it when the object goes out of scope. Throws std::runtime_error if it
// cannot be created.
class TempDirectory {
 public:
  explicit TempDirectory(const std::string& prefix);
  ~TempDirectory();
  TempDirectory(const TempDirectory&) = delete;
  TempDirectory& operator=(const TempDirectory&) = delete;

  const std::filesystem::path& path() const { return path_; }

 private:
  std::filesystem::path path_;
};

}  // namespace prt
