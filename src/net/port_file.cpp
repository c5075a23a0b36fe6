#include "net/port_file.h"

#include <fcntl.h>
#include <sys/file.h>
#include <sys/stat.h>
#include <unistd.h>

#include <atomic>
#include <cerrno>
#include <string>
#include <system_error>
#include <utility>

#include "core/input_error.h"
#include "net/invitation.h"

namespace prt {
namespace {

std::string portFileErrno(int err) {
  return std::generic_category().message(err);
}

[[noreturn]] void refusePortFile(const std::string& path, const std::string& why) {
  throw InputError("--accept-workers: the port file '" + path + "' " + why);
}

[[noreturn]] void cannotWritePortFile(const std::string& path, int err) {
  throw InputError("cannot write the port file '" + path + "': " + portFileErrno(err));
}

// Whether the lock cannot be had on this file system (as opposed to being held by another).
bool noLocksHere(int err) {
  return err == ENOLCK || err == EOPNOTSUPP || err == EINVAL;
}

bool writeAll(int fd, const std::string& text) {
  size_t done = 0;
  while (done < text.size()) {
    const ssize_t n = ::write(fd, text.data() + done, text.size() - done);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) return false;
    done += static_cast<size_t>(n);
  }
  return true;
}

// The file already at `path`, when `link` found one: returns normally when it is a port file
// no running render holds (stale: it may be replaced), throws otherwise. ENOENT (it went
// meanwhile) is returned as false: try again.
bool staleAt(const std::string& path) {
  const int fd = ::open(path.c_str(), O_RDONLY | O_NOFOLLOW | O_NONBLOCK | O_CLOEXEC);
  if (fd < 0) {
    const int err = errno;
    if (err == ENOENT) return false;
    if (err == ELOOP) {
      refusePortFile(path,
                     "is a symbolic link: refused (the port file is written where it is "
                     "named, never through a link)");
    }
    cannotWritePortFile(path, err);
  }
  struct Closer {
    int fd;
    ~Closer() { ::close(fd); }
  } closer{fd};
  struct stat st {};
  if (::fstat(fd, &st) != 0 || !S_ISREG(st.st_mode)) {
    refusePortFile(path, "exists and is not a file: refused rather than replaced");
  }
  if (::flock(fd, LOCK_EX | LOCK_NB) != 0 && !noLocksHere(errno)) {
    refusePortFile(path,
                   "belongs to a render that is running (it holds the file): give this "
                   "render another path, or end that one first");
  }
  std::string text;
  char buffer[4096];
  for (ssize_t n; text.size() < (1u << 16) && (n = ::read(fd, buffer, sizeof buffer)) != 0;) {
    if (n < 0) {
      if (errno == EINTR) continue;
      cannotWritePortFile(path, errno);
    }
    text.append(buffer, static_cast<size_t>(n));
  }
  if (!parsePortFile(text).secret) {
    refusePortFile(path, "exists and is not a port file: refused rather than replaced");
  }
  // Still the file checked (not replaced meanwhile by another render)?
  struct stat now {};
  if (::lstat(path.c_str(), &now) != 0) return false;
  if (now.st_dev != st.st_dev || now.st_ino != st.st_ino) return false;
  return true;
}

}  // namespace

PortFileClaim::PortFileClaim(const std::string& path, const std::string& text) : path_(path) {
  struct stat st {};
  if (::lstat(path.c_str(), &st) == 0 && S_ISLNK(st.st_mode)) {
    refusePortFile(path,
                   "is a symbolic link: refused (the port file is written where it is "
                   "named, never through a link)");
  }
  // The temporary file: never an existing one, never through a link, private from the start.
  static std::atomic<unsigned> counter{0};
  std::string temp;
  int fd = -1;
  for (int attempt = 0; attempt < 100 && fd < 0; ++attempt) {
    temp = path + ".tmp-" + std::to_string(::getpid()) + "-" + std::to_string(counter++);
    fd = ::open(temp.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_NOFOLLOW | O_CLOEXEC, 0600);
    if (fd < 0 && errno != EEXIST) cannotWritePortFile(path, errno);
  }
  if (fd < 0) cannotWritePortFile(path, EEXIST);
  const auto fail = [&](int err) {
    ::close(fd);
    ::unlink(temp.c_str());
    cannotWritePortFile(path, err);
  };
  if (::fchmod(fd, 0600) != 0) fail(errno);
  if (::flock(fd, LOCK_EX | LOCK_NB) != 0 && !noLocksHere(errno)) fail(errno);
  if (!writeAll(fd, text) || ::fsync(fd) != 0) fail(errno != 0 ? errno : EIO);
  // Into place: link(2) when nothing is there; over a stale port file, rename(2).
  bool placed = false;
  for (int attempt = 0; attempt < 20 && !placed; ++attempt) {
    if (::link(temp.c_str(), path.c_str()) == 0) {
      ::unlink(temp.c_str());
      placed = true;
      break;
    }
    const int err = errno;
    // A file system without hard links: only rename(2) is left.
    const bool noLinks = err == EPERM || err == EOPNOTSUPP || err == EMLINK;
    if (err != EEXIST && !noLinks) fail(err);
    try {
      // (Without hard links and with nothing there, the rename places it straight away.)
      if ((!noLinks || ::lstat(path.c_str(), &st) == 0) && !staleAt(path)) continue;
    } catch (...) {
      ::close(fd);
      ::unlink(temp.c_str());
      throw;
    }
    if (::rename(temp.c_str(), path.c_str()) != 0) fail(errno);
    placed = true;
  }
  if (!placed) fail(EBUSY);
  if (::fstat(fd, &st) != 0) fail(errno);
  fd_ = fd;
  device_ = st.st_dev;
  inode_ = st.st_ino;
}

PortFileClaim::~PortFileClaim() {
  release();
}

PortFileClaim::PortFileClaim(PortFileClaim&& other) noexcept
    : path_(std::move(other.path_)),
      fd_(std::exchange(other.fd_, -1)),
      device_(other.device_),
      inode_(other.inode_) {}

PortFileClaim& PortFileClaim::operator=(PortFileClaim&& other) noexcept {
  if (this != &other) {
    release();
    path_ = std::move(other.path_);
    fd_ = std::exchange(other.fd_, -1);
    device_ = other.device_;
    inode_ = other.inode_;
  }
  return *this;
}

void PortFileClaim::release() {
  if (fd_ < 0) return;
  struct stat st {};
  if (::lstat(path_.c_str(), &st) == 0 && st.st_dev == device_ && st.st_ino == inode_) {
    ::unlink(path_.c_str());
  }
  ::close(fd_);
  fd_ = -1;
}

}  // namespace prt
