#pragma once
// Running helper programs (POV-Ray, gnuplot, ffmpeg) as child processes: fork/exec with an
// argument vector, no shell, so no quoting; stdin from /dev/null (or a pipe the caller
// feeds), stdout and stderr to a log file.
// Thread-safe: nothing is shared between calls. Blocks until the child exits.

#include <filesystem>
#include <functional>
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
int runProgram(const std::string& program, const std::vector<std::string>& args,
               const std::filesystem::path& directory, const std::filesystem::path& logFile,
               const std::function<void(int)>& feedStdin = {});

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
