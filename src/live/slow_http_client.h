#pragma once
// For tests: a "slowloris" client that starts a request and sends one more header line every
// `interval` seconds without ever ending the headers, on a thread of its own, until it is
// stopped, `lifetime` seconds have passed, or the server cuts it off. It can connect from
// another loopback address (127.0.0.2, ...) to stand for another machine.

#include <arpa/inet.h>
#include <netinet/in.h>
#include <poll.h>
#include <sys/socket.h>
#include <unistd.h>

#include <atomic>
#include <chrono>
#include <mutex>
#include <optional>
#include <string>
#include <thread>

namespace prt::test_clients {

class SlowHttpClient {
 public:
  SlowHttpClient(int port, const std::string& from = "127.0.0.1", double interval = 1.0,
                 double lifetime = 40.0)
      : start_(std::chrono::steady_clock::now()) {
    fd_ = ::socket(AF_INET, SOCK_STREAM | SOCK_CLOEXEC, 0);
    sockaddr_in local{};
    local.sin_family = AF_INET;
    ::inet_pton(AF_INET, from.c_str(), &local.sin_addr);
    sockaddr_in server{};
    server.sin_family = AF_INET;
    server.sin_port = htons(static_cast<uint16_t>(port));
    ::inet_pton(AF_INET, "127.0.0.1", &server.sin_addr);
    connected_ = fd_ >= 0 && ::bind(fd_, reinterpret_cast<sockaddr*>(&local), sizeof local) == 0 &&
                 ::connect(fd_, reinterpret_cast<sockaddr*>(&server), sizeof server) == 0;
    if (!connected_) return;
    thread_ = std::thread([this, interval, lifetime] { trickle(interval, lifetime); });
  }
  ~SlowHttpClient() {
    stop();
    if (fd_ >= 0) ::close(fd_);
  }
  SlowHttpClient(const SlowHttpClient&) = delete;
  SlowHttpClient& operator=(const SlowHttpClient&) = delete;

  bool connected() const { return connected_; }
  // Seconds from its start until the server closed the connection; none while it is open.
  std::optional<double> cutAfter() const {
    const std::lock_guard<std::mutex> lock(mutex_);
    return cutAfter_;
  }
  // What the server sent it (a response to the part of the request it got, if any).
  std::string received() const {
    const std::lock_guard<std::mutex> lock(mutex_);
    return received_;
  }
  void stop() {
    stop_ = true;
    if (thread_.joinable()) thread_.join();
  }

 private:
  double elapsed() const {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
  }
  bool sendLine(const std::string& line) {
    return ::send(fd_, line.data(), line.size(), MSG_NOSIGNAL) == static_cast<ssize_t>(line.size());
  }
  void trickle(double interval, double lifetime) {
    bool open = sendLine("GET /status.json HTTP/1.1\r\n") && sendLine("Host: 127.0.0.1\r\n");
    for (int line = 0; open && !stop_ && elapsed() < lifetime;) {
      // Listen for the server in slices of 50 ms until the next line is due.
      const double due = elapsed() + interval;
      while (open && !stop_ && elapsed() < due) {
        pollfd p{fd_, POLLIN, 0};
        if (::poll(&p, 1, 50) > 0) {
          char buffer[4096];
          const ssize_t n = ::recv(fd_, buffer, sizeof buffer, 0);
          const std::lock_guard<std::mutex> lock(mutex_);
          if (n > 0) {
            received_.append(buffer, static_cast<size_t>(n));
          } else {
            open = false;
          }
        }
      }
      if (open && !stop_) open = sendLine("X-Slow-" + std::to_string(line++) + ": still here\r\n");
    }
    if (!open) {
      const std::lock_guard<std::mutex> lock(mutex_);
      cutAfter_ = elapsed();
    }
  }

  std::chrono::steady_clock::time_point start_;
  int fd_ = -1;
  bool connected_ = false;
  std::atomic<bool> stop_{false};
  mutable std::mutex mutex_;
  std::optional<double> cutAfter_;
  std::string received_;
  std::thread thread_;
};

}  // namespace prt::test_clients
