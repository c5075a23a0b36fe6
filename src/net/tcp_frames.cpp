#include "net/tcp_frames.h"

#include <fcntl.h>
#include <netdb.h>
#include <netinet/in.h>
#include <netinet/tcp.h>
#include <poll.h>
#include <sys/socket.h>
#include <unistd.h>

#include <cerrno>
#include <chrono>
#include <cstring>

namespace prt {
namespace {

constexpr size_t kHeader = 8;

double secondsSince(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

}  // namespace

void prepareSocket(int fd) {
  ::fcntl(fd, F_SETFL, ::fcntl(fd, F_GETFL) | O_NONBLOCK);
  ::fcntl(fd, F_SETFD, FD_CLOEXEC);
  int one = 1;
  ::setsockopt(fd, IPPROTO_TCP, TCP_NODELAY, &one, sizeof one);
}

FramedSocket::FramedSocket(int fd, uint64_t maxFrameBytes) : fd_(fd), maxFrame_(maxFrameBytes) {}

FramedSocket::~FramedSocket() {
  close();
}

void FramedSocket::close() {
  if (fd_ >= 0) ::close(fd_);
  fd_ = -1;
}

bool FramedSocket::receive() {
  if (fd_ < 0) return false;
  uint8_t buffer[65536];
  for (;;) {
    const ssize_t n = ::recv(fd_, buffer, sizeof buffer, 0);
    if (n > 0) {
      in_.insert(in_.end(), buffer, buffer + n);
      // A frame header that announces too much ends the connection before it is read.
      if (in_.size() - inOffset_ >= kHeader) {
        uint32_t length = 0;
        std::memcpy(&length, in_.data() + inOffset_, sizeof length);
        if (length < 4 || length - 4 > maxFrame_) {
          close();
          return false;
        }
      }
      continue;
    }
    if (n == 0) {
      close();
      return false;
    }
    if (errno == EINTR) continue;
    if (errno == EAGAIN || errno == EWOULDBLOCK) return true;
    close();
    return false;
  }
}

bool FramedSocket::hasFrame() const {
  if (in_.size() - inOffset_ < kHeader) return false;
  uint32_t length = 0;
  std::memcpy(&length, in_.data() + inOffset_, sizeof length);
  return in_.size() - inOffset_ >= 4 + uint64_t{length};
}

std::optional<Frame> FramedSocket::next() {
  if (in_.size() - inOffset_ < kHeader) return std::nullopt;
  uint32_t length = 0, tag = 0;
  std::memcpy(&length, in_.data() + inOffset_, sizeof length);
  std::memcpy(&tag, in_.data() + inOffset_ + 4, sizeof tag);
  if (length < 4 || length - 4 > maxFrame_) {
    close();
    return std::nullopt;
  }
  if (in_.size() - inOffset_ < 4 + uint64_t{length}) return std::nullopt;
  Frame f;
  f.tag = static_cast<int>(tag);
  const auto begin = in_.begin() + static_cast<std::ptrdiff_t>(inOffset_ + kHeader);
  f.bytes.assign(begin, begin + (length - 4));
  inOffset_ += 4 + length;
  if (inOffset_ == in_.size()) {
    in_.clear();
    inOffset_ = 0;
  } else if (inOffset_ > (1u << 20) && inOffset_ > in_.size() / 2) {
    in_.erase(in_.begin(), in_.begin() + static_cast<std::ptrdiff_t>(inOffset_));
    inOffset_ = 0;
  }
  return f;
}

void FramedSocket::send(int tag, const Bytes& bytes) {
  if (fd_ < 0) return;
  const auto length = static_cast<uint32_t>(bytes.size() + 4);
  const auto t = static_cast<uint32_t>(tag);
  const size_t at = out_.size();
  out_.resize(at + kHeader + bytes.size());
  std::memcpy(out_.data() + at, &length, 4);
  std::memcpy(out_.data() + at + 4, &t, 4);
  if (!bytes.empty()) std::memcpy(out_.data() + at + kHeader, bytes.data(), bytes.size());
  transmit();
}

bool FramedSocket::transmit() {
  if (fd_ < 0) return false;
  while (outOffset_ < out_.size()) {
    const ssize_t n =
        ::send(fd_, out_.data() + outOffset_, out_.size() - outOffset_, MSG_NOSIGNAL);
    if (n > 0) {
      outOffset_ += static_cast<size_t>(n);
      continue;
    }
    if (n < 0 && errno == EINTR) continue;
    if (n < 0 && (errno == EAGAIN || errno == EWOULDBLOCK)) return true;
    close();
    return false;
  }
  out_.clear();
  outOffset_ = 0;
  return true;
}

bool FramedSocket::drain(double timeoutSeconds) {
  const auto start = std::chrono::steady_clock::now();
  while (pendingOutput()) {
    if (!transmit()) return false;
    if (!pendingOutput()) break;
    const double left = timeoutSeconds - secondsSince(start);
    if (left <= 0) return false;
    pollfd p{fd_, POLLOUT, 0};
    ::poll(&p, 1, static_cast<int>(left * 1000) + 1);
  }
  return true;
}

int connectTo(const std::string& address, double timeoutSeconds, std::string& why) {
  const size_t colon = address.rfind(':');
  if (colon == std::string::npos || colon == 0) {
    why = "'" + address + "' is not HOST:PORT";
    return -1;
  }
  const std::string host = address.substr(0, colon), port = address.substr(colon + 1);
  addrinfo hints{};
  hints.ai_family = AF_INET;
  hints.ai_socktype = SOCK_STREAM;
  addrinfo* found = nullptr;
  if (const int e = ::getaddrinfo(host.c_str(), port.c_str(), &hints, &found); e != 0) {
    why = address + ": " + ::gai_strerror(e);
    return -1;
  }
  int fd = -1;
  why = address + ": no address";
  for (addrinfo* a = found; a != nullptr && fd < 0; a = a->ai_next) {
    fd = ::socket(a->ai_family, a->ai_socktype | SOCK_CLOEXEC, a->ai_protocol);
    if (fd < 0) continue;
    prepareSocket(fd);
    int r = ::connect(fd, a->ai_addr, a->ai_addrlen);
    if (r != 0 && errno == EINPROGRESS) {
      pollfd p{fd, POLLOUT, 0};
      r = ::poll(&p, 1, static_cast<int>(timeoutSeconds * 1000));
      int error = 0;
      socklen_t size = sizeof error;
      if (r == 1 && ::getsockopt(fd, SOL_SOCKET, SO_ERROR, &error, &size) == 0 && error == 0) {
        r = 0;
      } else {
        errno = r == 0 ? ETIMEDOUT : (error != 0 ? error : errno);
        r = -1;
      }
    }
    if (r != 0) {
      why = address + ": " + std::strerror(errno);
      ::close(fd);
      fd = -1;
    }
  }
  ::freeaddrinfo(found);
  return fd;
}

}  // namespace prt
