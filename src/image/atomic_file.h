#pragma once
// Atomic file replacement: a reader of `path` sees either its previous contents (or no file)
// or the complete new contents, never a half-written file, even if the write fails or the
// process dies part-way.
//
// How: the contents go to a temporary file in the same directory (so the final rename stays
// on one file system), named `path + ".tmp-<pid>-<counter>"`; it is flushed, synced and
// closed with every step checked, then renamed onto `path`. On any failure the temporary
// file is removed and an exception propagates.
//
// A `path` that is a symbolic link is followed: the file it names is replaced (in that file's
// folder) and the link stays, as `cp` and a shell's `>` do.
//
// Thread-safe: concurrent calls use distinct temporary names. Two concurrent writers to the
// same `path` both succeed and one of the complete files wins.
//
// Nothing is left behind: with removeTemporaryFilesOnSignals() installed, SIGTERM, SIGINT and
// SIGHUP remove the temporary files being written and end the process with exit code
// 128 + signal; and each write first removes the temporary files beside `path` of processes
// that are gone (killed by SIGKILL, or crashed). Only pids of this machine are known: a folder
// shared by machines that write the same file at once is not supported.

#include <cstdio>
#include <functional>
#include <string>
#include <string_view>

namespace prt {

// Calls writeContents with the open temporary file (binary mode); it writes the whole file
// and may throw to abort. Stream errors it leaves set on the FILE are detected afterwards.
// Throws InputError "cannot write '<path>': <reason>" for I/O failures (missing directory,
// permission denied, disk full, target is a directory); rethrows whatever writeContents
// throws, unchanged.
void writeFileAtomically(const std::string& path,
                         const std::function<void(std::FILE*)>& writeContents);

// Throws the InputError writeFileAtomically would throw for `path` if it cannot be written:
// creates, and removes at once, a temporary file beside it, and refuses a directory. For
// checking every output of a run before the run starts. Leaves `path` itself untouched.
void checkWritable(const std::string& path);

// A temporary file beside `path` for another program to fill (ffmpeg writing a video), named
// `path + ".tmp-<pid>-<counter>" + extension` so that the program can tell the format from
// its name. It is created empty, removed by the signal handlers and by the destructor, and
// as a stale file by later writes beside `path` if this process dies; commit() renames it
// onto `path` (throwing InputError "cannot write ..." on failure). Not copyable.
class TemporaryFile {
 public:
  TemporaryFile(const std::string& path, const std::string& extension);
  ~TemporaryFile();
  TemporaryFile(const TemporaryFile&) = delete;
  TemporaryFile& operator=(const TemporaryFile&) = delete;

  const std::string& path() const { return tempPath_; }
  void commit();

 private:
  std::string target_;
  std::string tempPath_;
  int slot_ = -1;
  bool committed_ = false;
};

// Removes `name.tmp-PID-N` files beside `path` whose process is gone (a run killed by SIGKILL
// could not remove its own); every write beside `path` does it, and so does a run that ends
// without writing (a resumed render finished before its first checkpoint).
void removeStaleTemporaries(const std::string& path);

// Installs handlers for SIGTERM, SIGINT and SIGHUP that end the programs this process runs
// (core/subprocess.h), remove this process's temporary files and _exit(128 + signal). For a program's main(), once, before any thread starts.
void removeTemporaryFilesOnSignals();

// The same, with the whole contents in hand (text or bytes).
void writeFileAtomically(const std::string& path, std::string_view contents);

}  // namespace prt
