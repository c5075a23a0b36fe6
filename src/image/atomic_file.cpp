#include "image/atomic_file.h"

#include <unistd.h>

#include <atomic>
#include <cerrno>
#include <cstdint>
#include <filesystem>
#include <system_error>

#include "core/input_error.h"

namespace prt {
namespace {

// errno text without strerror's static buffer (std::generic_category is thread-safe).
std::string errnoText(int err) {
  return std::generic_category().message(err);
}

[[noreturn]] void throwCannotWrite(const std::string& path, int err) {
  throw InputError("cannot write '" + path + "': " + errnoText(err));
}

// Creates the temporary file exclusively ("x"), so a stale file of the same name left by a
// crashed process with a recycled pid is never reused: we just move on to the next name.
std::FILE* openTemporary(const std::string& path, std::string& tempPath) {
  static std::atomic<uint64_t> counter{0};
  const std::string prefix = path + ".tmp-" + std::to_string(::getpid()) + "-";
  for (int attempt = 0; attempt < 100; ++attempt) {
    tempPath = prefix + std::to_string(counter.fetch_add(1, std::memory_order_relaxed));
    if (std::FILE* f = std::fopen(tempPath.c_str(), "wbx")) return f;
    if (errno != EEXIST) throwCannotWrite(path, errno);
  }
  throwCannotWrite(path, EEXIST);
}

}  // namespace

void writeFileAtomically(const std::string& path,
                         const std::function<void(std::FILE*)>& writeContents) {
  std::string tempPath;
  std::FILE* file = openTemporary(path, tempPath);

  // Closes (if still open) and deletes the temporary file; used on every failure path.
  auto discard = [&] {
    if (file != nullptr) std::fclose(file);
    file = nullptr;
    std::remove(tempPath.c_str());
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
}

void checkWritable(const std::string& path) {
  if (path.empty()) throw InputError("cannot write '': no file name given");
  std::error_code error;
  if (std::filesystem::is_directory(path, error)) throwCannotWrite(path, EISDIR);
  std::string tempPath;
  std::FILE* file = openTemporary(path, tempPath);
  std::fclose(file);
  std::remove(tempPath.c_str());
}

void writeFileAtomically(const std::string& path, std::string_view contents) {
  writeFileAtomically(path,
                      [&](std::FILE* f) { std::fwrite(contents.data(), 1, contents.size(), f); });
}

}  // namespace prt
