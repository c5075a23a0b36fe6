#include "core/input_file.h"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>

#include "core/input_error.h"
#include "core/memory_budget.h"
#include "core/text.h"

namespace prt {
namespace {

class Descriptor {
 public:
  explicit Descriptor(int fd) : fd_(fd) {}
  ~Descriptor() {
    if (fd_ >= 0) ::close(fd_);
  }
  Descriptor(const Descriptor&) = delete;
  Descriptor& operator=(const Descriptor&) = delete;
  int get() const { return fd_; }

 private:
  int fd_;
};

std::string tooLarge(const std::string& path, const std::string& what, uint64_t size,
                     uint64_t maxBytes) {
  return what + " " + quote(path, '\'') + " is " + formatMemorySize(size) + ", more than the " +
         formatMemorySize(maxBytes) + " a " + what + " may be" +
         (maxBytes == memoryBudgetBytes() ? " (the memory budget; --max-memory sets it)" : "");
}

}  // namespace

std::string specialFileKind(std::filesystem::file_type type) {
  using std::filesystem::file_type;
  switch (type) {
    case file_type::fifo:
      return "a FIFO (named pipe)";
    case file_type::character:
      return "a character device";
    case file_type::block:
      return "a block device";
    case file_type::socket:
      return "a socket";
    default:
      return {};
  }
}

uint64_t checkInputFile(const std::string& path, const std::string& what, uint64_t maxBytes) {
  namespace fs = std::filesystem;
  if (path.empty()) throw InputError("no " + what + " name given");
  std::error_code error;
  const fs::file_status status = fs::status(path, error);
  if (status.type() == fs::file_type::not_found) {
    throw InputError(what + " " + quote(path, '\'') + " does not exist");
  }
  if (status.type() == fs::file_type::directory) {
    throw InputError(what + " " + quote(path, '\'') + " is a directory");
  }
  if (const std::string kind = specialFileKind(status.type()); !kind.empty()) {
    throw InputError(what + " " + quote(path, '\'') + " is " + kind + ", not a regular file");
  }
  const uintmax_t size = fs::file_size(path, error);
  if (error) {
    throw InputError("cannot read " + what + " " + quote(path, '\'') + ": " + error.message());
  }
  if (size > maxBytes) throw InputError(tooLarge(path, what, size, maxBytes));
  return size;
}

uint64_t checkInputFile(const std::string& path, const std::string& what) {
  return checkInputFile(path, what, memoryBudgetBytes());
}

std::string readInputFile(const std::string& path, const std::string& what, uint64_t maxBytes) {
  checkInputFile(path, what, maxBytes);
  // O_NONBLOCK: should the file have been swapped for a FIFO since the check, opening does
  // not wait for a writer; fstat below then refuses it.
  const Descriptor fd(::open(path.c_str(), O_RDONLY | O_CLOEXEC | O_NONBLOCK | O_NOCTTY));
  if (fd.get() < 0) {
    throw InputError("cannot open " + what + " " + quote(path, '\'') + ": " + std::strerror(errno));
  }
  struct stat info{};
  if (::fstat(fd.get(), &info) != 0 || !S_ISREG(info.st_mode)) {
    throw InputError(what + " " + quote(path, '\'') + " is not a regular file");
  }
  if (static_cast<uint64_t>(info.st_size) > maxBytes) {
    throw InputError(tooLarge(path, what, static_cast<uint64_t>(info.st_size), maxBytes));
  }
  std::string bytes;
  bytes.reserve(static_cast<size_t>(info.st_size));
  char buffer[1 << 16];
  for (;;) {
    const ssize_t count = ::read(fd.get(), buffer, sizeof buffer);
    if (count == 0) break;
    if (count < 0) {
      if (errno == EINTR) continue;
      throw InputError("cannot read " + what + " " + quote(path, '\'') + ": " +
                       std::strerror(errno));
    }
    bytes.append(buffer, static_cast<size_t>(count));
    if (bytes.size() > maxBytes) throw InputError(tooLarge(path, what, bytes.size(), maxBytes));
  }
  return bytes;
}

std::string readInputFile(const std::string& path, const std::string& what) {
  return readInputFile(path, what, memoryBudgetBytes());
}

}  // namespace prt
