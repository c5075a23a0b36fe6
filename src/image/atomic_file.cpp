#include "image/atomic_file.h"

#include <signal.h>
#include <unistd.h>

#include <atomic>
#include <cerrno>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <system_error>

#include "core/input_error.h"
#include "core/subprocess.h"

namespace prt {
namespace {

// errno text without strerror's static buffer (std::generic_category is thread-safe).
std::string errnoText(int err) {
  return std::generic_category().message(err);
}

[[noreturn]] void throwCannotWrite(const std::string& path, int err) {
  throw InputError("cannot write '" + path + "': " + errnoText(err));
}

// The file a write to `path` replaces: `path`, or where it leads when it is a symbolic link
// (followed link by link, each relative to the folder of the link that names it), so that the
// link stays and the file it names gets the contents, as `cp` and a shell's `>` do; a rename
// onto the link would replace the link itself. Throws for a chain of links that loops.
std::string followLinks(const std::string& path) {
  std::filesystem::path at(path);
  for (int hops = 0; hops < 40; ++hops) {
    std::error_code error;
    if (!std::filesystem::is_symlink(std::filesystem::symlink_status(at, error))) return at.string();
    const std::filesystem::path next = std::filesystem::read_symlink(at, error);
    if (error) throwCannotWrite(path, error.value());
    at = next.is_absolute() ? next : (at.parent_path() / next).lexically_normal();
  }
  throwCannotWrite(path, ELOOP);
}

// The temporary files this process has open, for the signal handler to remove: a fixed table
// of lock-free slots, as a handler may not allocate or lock. A slot is claimed (Writing), its
// path copied in, then published (Ready); only Ready slots are read by the handler.
enum SlotState : int { kFree, kWriting, kReady };
constexpr int kSlots = 64;
constexpr size_t kPathBytes = 4096;
std::atomic<int> slotState[kSlots];
char slotPath[kSlots][kPathBytes];
static_assert(std::atomic<int>::is_always_lock_free);

// Returns the slot holding `path`, or -1 if the table is full or the path too long (the file
// is then merely not removed on a signal).
int registerTemporary(const std::string& path) {
  if (path.size() >= kPathBytes) return -1;
  for (int i = 0; i < kSlots; ++i) {
    int expected = kFree;
    if (slotState[i].compare_exchange_strong(expected, kWriting)) {
      std::memcpy(slotPath[i], path.c_str(), path.size() + 1);
      slotState[i].store(kReady);
      return i;
    }
  }
  return -1;
}

void unregisterTemporary(int slot) {
  if (slot >= 0) slotState[slot].store(kFree);
}

extern "C" void removeTemporariesAndExit(int signal) {
  killRunningPrograms();  // a program writing one of them (ffmpeg) must not outlive us
  for (int i = 0; i < kSlots; ++i) {
    if (slotState[i].load() == kReady) ::unlink(slotPath[i]);
  }
  ::_exit(128 + signal);
}

// Creates the temporary file exclusively ("x"), so a stale file of the same name left by a
// crashed process with a recycled pid is never reused: we just move on to the next name.
// `slot` is its entry in the table of files to remove on a signal.
std::FILE* openTemporary(const std::string& path, std::string& tempPath, int& slot,
                         const std::string& extension = "") {
  static std::atomic<uint64_t> counter{0};
  removeStaleTemporaries(path);
  const std::string prefix = path + ".tmp-" + std::to_string(::getpid()) + "-";
  for (int attempt = 0; attempt < 100; ++attempt) {
    tempPath = prefix + std::to_string(counter.fetch_add(1, std::memory_order_relaxed)) + extension;
    // Registered before it exists, so that no signal can leave it behind.
    slot = registerTemporary(tempPath);
    if (std::FILE* f = std::fopen(tempPath.c_str(), "wbx")) return f;
    const int err = errno;
    unregisterTemporary(slot);
    if (err != EEXIST) throwCannotWrite(path, err);
  }
  throwCannotWrite(path, EEXIST);
}

}  // namespace

// Removes `name.tmp-PID-N` files beside `path` whose process PID is gone: a run killed by
// SIGKILL (or a crash) could not remove its own. A live process's files, ours included, are
// left alone; pids are those of this machine.
void removeStaleTemporaries(const std::string& path) {
  namespace fs = std::filesystem;
  const fs::path target(path);
  const std::string prefix = target.filename().string() + ".tmp-";
  const fs::path folder = target.has_parent_path() ? target.parent_path() : fs::path(".");
  std::error_code error;
  fs::directory_iterator entries(folder, error);
  if (error) return;  // a missing folder is reported by the write itself
  for (const fs::directory_entry& entry : entries) {
    const std::string name = entry.path().filename().string();
    if (!name.starts_with(prefix)) continue;
    std::string rest = name.substr(prefix.size());
    // A TemporaryFile keeps its extension: ".tmp-PID-N.mp4".
    if (const size_t dot = rest.find('.'); dot != std::string::npos) rest.resize(dot);
    const size_t dash = rest.find('-');
    if (dash == 0 || dash == std::string::npos || dash > 9 ||
        rest.find_first_not_of("0123456789-") != std::string::npos) {
      continue;
    }
    const auto pid = static_cast<pid_t>(std::stol(rest.substr(0, dash)));
    if (pid <= 0 || ::kill(pid, 0) == 0 || errno != ESRCH) continue;
    std::error_code ignored;
    fs::remove(entry.path(), ignored);
  }
}

TemporaryFile::TemporaryFile(const std::string& path, const std::string& extension)
    : target_(followLinks(path)) {
  std::FILE* file = openTemporary(target_, tempPath_, slot_, extension);
  std::fclose(file);
}

TemporaryFile::~TemporaryFile() {
  if (!committed_) std::remove(tempPath_.c_str());
  unregisterTemporary(slot_);
}

void TemporaryFile::commit() {
  if (std::rename(tempPath_.c_str(), target_.c_str()) != 0) throwCannotWrite(target_, errno);
  committed_ = true;
}

void writeFileAtomically(const std::string& given,
                         const std::function<void(std::FILE*)>& writeContents) {
  const std::string path = followLinks(given);
  std::string tempPath;
  int slot = -1;
  std::FILE* file = openTemporary(path, tempPath, slot);

  // Closes (if still open) and deletes the temporary file; used on every failure path.
  auto discard = [&] {
    if (file != nullptr) std::fclose(file);
    file = nullptr;
    std::remove(tempPath.c_str());
    unregisterTemporary(slot);
  };

  try {
    errno = 0;  // so a stream error below reports the errno of the failed write
    writeContents(file);
  } catch (...) {
    discard();
    throw;
  }

  // Each step can be the first to report a failed write (buffered data reaches the disk
  // late), so each is checked. fsync before rename: otherwise a crash soon after the rename
  // can leave an empty file at `path` on some file systems.
  int err = 0;
  if (std::ferror(file)) {
    err = errno != 0 ? errno : EIO;
  } else if (std::fflush(file) != 0 || ::fsync(::fileno(file)) != 0) {
    err = errno;
  }
  if (err != 0) {
    discard();
    throwCannotWrite(path, err);
  }
  const int closeResult = std::fclose(file);
  file = nullptr;
  if (closeResult != 0) {
    err = errno;
    discard();
    throwCannotWrite(path, err);
  }
  if (std::rename(tempPath.c_str(), path.c_str()) != 0) {
    err = errno;
    discard();
    throwCannotWrite(path, err);
  }
  unregisterTemporary(slot);
}

void checkWritable(const std::string& given) {
  if (given.empty()) throw InputError("cannot write '': no file name given");
  const std::string path = followLinks(given);
  std::error_code error;
  if (std::filesystem::is_directory(path, error)) throwCannotWrite(path, EISDIR);
  std::string tempPath;
  int slot = -1;
  std::FILE* file = openTemporary(path, tempPath, slot);
  std::fclose(file);
  std::remove(tempPath.c_str());
  unregisterTemporary(slot);
}

void removeTemporaryFilesOnSignals() {
  struct sigaction action {};
  action.sa_handler = removeTemporariesAndExit;
  sigemptyset(&action.sa_mask);
  for (const int signal : {SIGTERM, SIGINT, SIGHUP}) {
    // Block the others while one is handled: two handlers at once would be harmless, but the
    // exit code should name the first signal.
    sigaddset(&action.sa_mask, signal);
  }
  for (const int signal : {SIGTERM, SIGINT, SIGHUP}) sigaction(signal, &action, nullptr);
}

void writeFileAtomically(const std::string& path, std::string_view contents) {
  writeFileAtomically(path,
                      [&](std::FILE* f) { std::fwrite(contents.data(), 1, contents.size(), f); });
}

}  // namespace prt
