#pragma once
// BoundedHttpServer: cpp-httplib's request handling (routes, handlers, responses) behind an
// accept loop and a socket stream of our own, so that no client can hold the server: httplib's
// own loop gives a connection to a small thread pool for as long as bytes trickle in (a
// "slowloris" client sending a header line every few seconds keeps a thread for ever) and, when
// stopping, waits for every such connection to end.
//
//   - each connection has a thread of its own, at most `perClient` from one address and
//     `total` in all; one more is answered 503 at once and closed;
//   - a request must arrive whole (request line and headers, at most `requestBytes`) within
//     `requestSeconds` of the connection waiting for it (after its last response, for a
//     kept-alive one): a client that is slower is cut off;
//   - a response that makes no progress for `stallSeconds`, or takes `responseSeconds` in all,
//     is abandoned;
//   - stop() ends every connection at once (an idle or slow client waits on nothing), finishes
//     the handlers running, and joins every thread.
// Internal to src/live: it includes <httplib.h> (Debian's libcpp-httplib, 0.11).

#include <httplib.h>

#include <atomic>
#include <cstddef>
#include <list>
#include <map>
#include <memory>
#include <mutex>
#include <string>
#include <thread>

namespace prt {

struct HttpLimits {
  int perClient = 6;
  int total = 16;
  double requestSeconds = 5;
  double stallSeconds = 5;
  double responseSeconds = 60;
  size_t requestBytes = 32 * 1024;
  int requestsPerConnection = 100;
};

// Whether every address `host` resolves to (a name, or a numeric address) is a loopback one:
// 127.0.0.0/8, ::1, or an IPv4-mapped 127.x. False when it does not resolve.
bool resolvesToLoopbackOnly(const std::string& host);

class BoundedHttpServer : public httplib::Server {
 public:
  explicit BoundedHttpServer(HttpLimits limits = {});
  ~BoundedHttpServer() override;
  BoundedHttpServer(const BoundedHttpServer&) = delete;
  BoundedHttpServer& operator=(const BoundedHttpServer&) = delete;

  // Binds `host`:`port` (0: any free port) to the first address `host` resolves to that can be
  // had, and listens. Returns the port, or -1 (`why` says why). `loopback` tells whether every
  // address the name resolves to, the bound one included, is a loopback one.
  int bindAndListen(const std::string& host, int port, bool& loopback, std::string& why);
  // Serves from threads of its own until stop().
  void start();
  // Closes the listening socket and every connection, and joins every thread. Idempotent.
  void stop();

  // Connections open now (for tests).
  int openConnections() const;

 private:
  struct Connection {
    std::thread thread;
    std::atomic<bool> done{false};
  };
  class Stream;
  void acceptLoop();
  void serve(int fd, const std::string& peer, Connection& self);
  void reapFinished(bool all);

  HttpLimits limits_;
  int listenFd_ = -1;
  int wakeFd_ = -1;  // an eventfd, readable once stopping: wakes every poll at once
  std::atomic<bool> stopping_{false};
  std::thread acceptThread_;
  mutable std::mutex mutex_;
  std::list<std::unique_ptr<Connection>> connections_;
  std::map<std::string, int> perClient_;  // open connections by client address
  int open_ = 0;
};

}  // namespace prt
