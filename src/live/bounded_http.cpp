#include "live/bounded_http.h"

#include <arpa/inet.h>
#include <netdb.h>
#include <netinet/in.h>
#include <poll.h>
#include <sys/eventfd.h>
#include <sys/socket.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <chrono>
#include <climits>
#include <cstdint>
#include <cstring>
#include <stdexcept>
#include <vector>

#include "core/thread_start.h"

namespace prt {
namespace {

using HttpClock = std::chrono::steady_clock;

HttpClock::time_point httpAfter(double seconds) {
  return HttpClock::now() +
         std::chrono::duration_cast<HttpClock::duration>(std::chrono::duration<double>(seconds));
}

// Waits until `fd` has `events`, `until` passes, or the server stops (`wakeFd` readable):
// 1 ready (or in error: the next call on it says which), 0 the time is up, -1 stopping.
int awaitSocket(int fd, short events, int wakeFd, HttpClock::time_point until) {
  for (;;) {
    const auto left = std::chrono::ceil<std::chrono::milliseconds>(until - HttpClock::now());
    if (left.count() <= 0) return 0;
    pollfd fds[2] = {{fd, events, 0}, {wakeFd, POLLIN, 0}};
    const int n = ::poll(fds, 2, static_cast<int>(std::min<int64_t>(left.count(), INT_MAX)));
    if (n < 0) {
      if (errno == EINTR) continue;
      return -1;
    }
    if (fds[1].revents != 0) return -1;
    if (fds[0].revents != 0) return 1;
  }
}

std::string numericHost(const sockaddr* address, socklen_t length, int* port = nullptr) {
  char host[NI_MAXHOST] = {};
  char service[NI_MAXSERV] = {};
  if (::getnameinfo(address, length, host, sizeof host, service, sizeof service,
                    NI_NUMERICHOST | NI_NUMERICSERV) != 0) {
    return "?";
  }
  if (port) *port = std::atoi(service);
  return host;
}

bool isLoopbackAddress(const sockaddr* address) {
  if (address->sa_family == AF_INET) {
    const auto* v4 = reinterpret_cast<const sockaddr_in*>(address);
    return (ntohl(v4->sin_addr.s_addr) >> 24) == 127;
  }
  if (address->sa_family == AF_INET6) {
    const in6_addr& a = reinterpret_cast<const sockaddr_in6*>(address)->sin6_addr;
    if (IN6_IS_ADDR_LOOPBACK(&a)) return true;
    return IN6_IS_ADDR_V4MAPPED(&a) && a.s6_addr[12] == 127;
  }
  return false;
}

struct AddressList {
  addrinfo* list = nullptr;
  int error = 0;
  AddressList(const std::string& host, int port) {
    addrinfo hints{};
    hints.ai_family = AF_UNSPEC;
    hints.ai_socktype = SOCK_STREAM;
    hints.ai_flags = AI_PASSIVE | AI_NUMERICSERV;
    error = ::getaddrinfo(host.c_str(), std::to_string(port).c_str(), &hints, &list);
    if (error != 0) list = nullptr;
  }
  ~AddressList() {
    if (list) ::freeaddrinfo(list);
  }
  AddressList(const AddressList&) = delete;
  AddressList& operator=(const AddressList&) = delete;
  bool allLoopback() const {
    if (!list) return false;
    for (const addrinfo* a = list; a; a = a->ai_next) {
      if (!isLoopbackAddress(a->ai_addr)) return false;
    }
    return true;
  }
};

constexpr char kBusyResponse[] =
    "HTTP/1.1 503 Service Unavailable\r\nRetry-After: 1\r\nConnection: close\r\n"
    "Content-Type: text/plain\r\nContent-Length: 35\r\n\r\ntoo many connections from you: wait\n";

}  // namespace

bool resolvesToLoopbackOnly(const std::string& host) {
  return AddressList(host, 0).allLoopback();
}

// One connection's bytes, with the deadlines of the header: reads end at the request's
// deadline or byte budget (then cut() is true), writes when one makes no progress or the
// response's time is up; both at once when the server stops.
class BoundedHttpServer::Stream : public httplib::Stream {
 public:
  Stream(int fd, int wakeFd, const HttpLimits& limits) : fd_(fd), wake_(wakeFd), limits_(limits) {}

  void beginRequest() {
    readUntil_ = httpAfter(limits_.requestSeconds);
    responseUntil_ = httpAfter(limits_.responseSeconds);
    consumed_ = 0;
  }
  bool cut() const { return cut_; }

  bool is_readable() const override {
    return pos_ < end_ || awaitSocket(fd_, POLLIN, wake_, readUntil_) == 1;
  }
  bool is_writable() const override { return awaitSocket(fd_, POLLOUT, wake_, writeUntil()) == 1; }

  ssize_t read(char* ptr, size_t size) override {
    if (size == 0) return 0;
    if (consumed_ >= limits_.requestBytes) {
      cut_ = true;
      return -1;
    }
    while (pos_ == end_) {
      if (awaitSocket(fd_, POLLIN, wake_, readUntil_) != 1) {
        cut_ = true;
        return -1;
      }
      const ssize_t n = ::recv(fd_, buffer_, sizeof buffer_, MSG_DONTWAIT);
      if (n < 0 && (errno == EAGAIN || errno == EWOULDBLOCK || errno == EINTR)) continue;
      if (n <= 0) return n;  // 0: the client closed; -1: an error
      pos_ = 0;
      end_ = static_cast<size_t>(n);
    }
    const size_t n = std::min({size, end_ - pos_, limits_.requestBytes - consumed_});
    std::memcpy(ptr, buffer_ + pos_, n);
    pos_ += n;
    consumed_ += n;
    return static_cast<ssize_t>(n);
  }

  ssize_t write(const char* ptr, size_t size) override {
    for (;;) {
      if (awaitSocket(fd_, POLLOUT, wake_, writeUntil()) != 1) return -1;
      const ssize_t n = ::send(fd_, ptr, size, MSG_DONTWAIT | MSG_NOSIGNAL);
      if (n < 0 && (errno == EAGAIN || errno == EWOULDBLOCK || errno == EINTR)) continue;
      return n;
    }
  }

  void get_remote_ip_and_port(std::string& ip, int& port) const override {
    sockaddr_storage address{};
    socklen_t length = sizeof address;
    port = 0;
    ip = ::getpeername(fd_, reinterpret_cast<sockaddr*>(&address), &length) == 0
             ? numericHost(reinterpret_cast<sockaddr*>(&address), length, &port)
             : "";
  }
  void get_local_ip_and_port(std::string& ip, int& port) const override {
    sockaddr_storage address{};
    socklen_t length = sizeof address;
    port = 0;
    ip = ::getsockname(fd_, reinterpret_cast<sockaddr*>(&address), &length) == 0
             ? numericHost(reinterpret_cast<sockaddr*>(&address), length, &port)
             : "";
  }
  socket_t socket() const override { return fd_; }

 private:
  HttpClock::time_point writeUntil() const {
    return std::min(httpAfter(limits_.stallSeconds), responseUntil_);
  }

  int fd_;
  int wake_;
  const HttpLimits& limits_;
  HttpClock::time_point readUntil_{}, responseUntil_{};
  size_t consumed_ = 0;
  bool cut_ = false;
  char buffer_[4096];
  size_t pos_ = 0, end_ = 0;
};

BoundedHttpServer::BoundedHttpServer(HttpLimits limits) : limits_(limits) {
  wakeFd_ = ::eventfd(0, EFD_CLOEXEC | EFD_NONBLOCK);
  if (wakeFd_ < 0) throw std::runtime_error(std::string("eventfd: ") + std::strerror(errno));
  set_keep_alive_max_count(static_cast<size_t>(limits_.requestsPerConnection));
  set_keep_alive_timeout(static_cast<time_t>(limits_.requestSeconds));
}

BoundedHttpServer::~BoundedHttpServer() {
  stop();
  ::close(wakeFd_);
}

int BoundedHttpServer::bindAndListen(const std::string& host, int port, bool& loopback,
                                     std::string& why) {
  const AddressList addresses(host, port);
  if (!addresses.list) {
    why = std::string("cannot resolve '") + host + "': " + ::gai_strerror(addresses.error);
    return -1;
  }
  loopback = addresses.allLoopback();
  why = "the port is taken, or the address is not this machine's";
  for (const addrinfo* a = addresses.list; a; a = a->ai_next) {
    const int fd = ::socket(a->ai_family, a->ai_socktype | SOCK_CLOEXEC, a->ai_protocol);
    if (fd < 0) continue;
    // SO_REUSEADDR only: SO_REUSEPORT would let a second render share the port silently.
    const int yes = 1;
    ::setsockopt(fd, SOL_SOCKET, SO_REUSEADDR, &yes, sizeof yes);
    if (::bind(fd, a->ai_addr, a->ai_addrlen) != 0 || ::listen(fd, 16) != 0) {
      why = std::strerror(errno);
      ::close(fd);
      continue;
    }
    sockaddr_storage bound{};
    socklen_t length = sizeof bound;
    if (::getsockname(fd, reinterpret_cast<sockaddr*>(&bound), &length) != 0) {
      ::close(fd);
      continue;
    }
    loopback = loopback && isLoopbackAddress(reinterpret_cast<sockaddr*>(&bound));
    int boundPort = 0;
    numericHost(reinterpret_cast<sockaddr*>(&bound), length, &boundPort);
    listenFd_ = fd;
    return boundPort;
  }
  return -1;
}

void BoundedHttpServer::start() {
  acceptThread_ = startThread([this] { acceptLoop(); });
}

void BoundedHttpServer::acceptLoop() {
  while (!stopping_) {
    pollfd fds[2] = {{listenFd_, POLLIN, 0}, {wakeFd_, POLLIN, 0}};
    const int ready = ::poll(fds, 2, 1000);
    if (stopping_) break;
    reapFinished(false);
    if (ready <= 0 || (fds[0].revents & POLLIN) == 0) continue;
    sockaddr_storage address{};
    socklen_t length = sizeof address;
    const int fd =
        ::accept4(listenFd_, reinterpret_cast<sockaddr*>(&address), &length, SOCK_CLOEXEC);
    if (fd < 0) {
      // Out of descriptors or memory: let the connections open now end first.
      if (errno == EMFILE || errno == ENFILE || errno == ENOBUFS || errno == ENOMEM) {
        std::this_thread::sleep_for(std::chrono::milliseconds(20));
      }
      continue;
    }
    const std::string peer = numericHost(reinterpret_cast<sockaddr*>(&address), length);
    bool admitted = false;
    {
      const std::lock_guard<std::mutex> lock(mutex_);
      int& mine = perClient_[peer];
      if (open_ < limits_.total && mine < limits_.perClient) {
        ++mine;
        ++open_;
        admitted = true;
      } else if (mine == 0) {
        perClient_.erase(peer);
      }
    }
    if (!admitted) {
      // Best effort: what the client sent is read first, so that closing does not reset the
      // connection before the 503 reaches it (a client that sends on may still see a reset).
      char discard[4096];
      for (int i = 0; i < 16 && ::recv(fd, discard, sizeof discard, MSG_DONTWAIT) > 0; ++i) {
      }
      ::send(fd, kBusyResponse, sizeof kBusyResponse - 1, MSG_DONTWAIT | MSG_NOSIGNAL);
      ::shutdown(fd, SHUT_WR);
      ::close(fd);
      continue;
    }
    auto connection = std::make_unique<Connection>();
    Connection& self = *connection;
    const std::lock_guard<std::mutex> lock(mutex_);
    try {
      self.thread = startThread([this, fd, peer, &self] { serve(fd, peer, self); });
      connections_.push_back(std::move(connection));
    } catch (...) {
      // No thread to be had: the connection is refused as one too many.
      ::close(fd);
      --open_;
      if (--perClient_[peer] == 0) perClient_.erase(peer);
    }
  }
}

void BoundedHttpServer::serve(int fd, const std::string& peer, Connection& self) {
  try {
    Stream stream(fd, wakeFd_, limits_);
    for (int n = 0; n < limits_.requestsPerConnection && !stopping_; ++n) {
      stream.beginRequest();
      bool closed = false;
      const bool last = n + 1 == limits_.requestsPerConnection;
      if (!process_request(stream, last, closed, nullptr) || closed || stream.cut()) break;
    }
  } catch (...) {
    // Out of memory in a request: this connection ends, the server goes on.
  }
  ::shutdown(fd, SHUT_RDWR);
  ::close(fd);
  {
    const std::lock_guard<std::mutex> lock(mutex_);
    --open_;
    if (--perClient_[peer] <= 0) perClient_.erase(peer);
  }
  self.done = true;
}

void BoundedHttpServer::reapFinished(bool all) {
  std::vector<std::unique_ptr<Connection>> ended;
  {
    const std::lock_guard<std::mutex> lock(mutex_);
    for (auto it = connections_.begin(); it != connections_.end();) {
      if (all || (*it)->done) {
        ended.push_back(std::move(*it));
        it = connections_.erase(it);
      } else {
        ++it;
      }
    }
  }
  for (const std::unique_ptr<Connection>& c : ended) {
    if (c->thread.joinable()) c->thread.join();
  }
}

void BoundedHttpServer::stop() {
  stopping_ = true;
  const uint64_t one = 1;
  const ssize_t written = ::write(wakeFd_, &one, sizeof one);
  (void)written;  // already readable when it fails (the counter is full): either wakes all
  if (acceptThread_.joinable()) acceptThread_.join();
  reapFinished(true);
  if (listenFd_ >= 0) {
    ::close(listenFd_);
    listenFd_ = -1;
  }
}

int BoundedHttpServer::openConnections() const {
  const std::lock_guard<std::mutex> lock(mutex_);
  return open_;
}

}  // namespace prt
