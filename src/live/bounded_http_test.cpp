#include "live/bounded_http.h"

#include <gtest/gtest.h>
#include <httplib.h>
#include <sys/socket.h>
#include <unistd.h>

#include <chrono>
#include <memory>
#include <thread>
#include <vector>

#include "live/slow_http_client.h"

namespace prt {
namespace {

using test_clients::SlowHttpClient;

// A server with one route, bound to 127.0.0.1 and serving.
struct BoundedTestServer {
  explicit BoundedTestServer(HttpLimits limits) : server(limits) {
    server.Get("/status.json", [](const httplib::Request&, httplib::Response& response) {
      response.set_content("{}", "application/json");
    });
    bool loopback = false;
    std::string why;
    port = server.bindAndListen("127.0.0.1", 0, loopback, why);
    EXPECT_TRUE(loopback);
    EXPECT_GT(port, 0) << why;
    server.start();
  }
  int get(const std::string& path = "/status.json") {
    httplib::Client client("127.0.0.1", port);
    client.set_connection_timeout(2);
    client.set_read_timeout(2);
    const auto r = client.Get(path.c_str());
    return r ? r->status : -1;
  }
  BoundedHttpServer server;
  int port = 0;
};

double boundedSince(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

TEST(BoundedHttpServer, ASlowClientIsCutOffAtTheRequestDeadline) {
  HttpLimits limits;
  limits.requestSeconds = 1;
  BoundedTestServer t(limits);
  SlowHttpClient slow(t.port, "127.0.0.1", 0.2, 20);
  ASSERT_TRUE(slow.connected());
  for (int i = 0; i < 100 && !slow.cutAfter(); ++i) {
    std::this_thread::sleep_for(std::chrono::milliseconds(50));
  }
  ASSERT_TRUE(slow.cutAfter().has_value()) << "still connected after 5 s";
  EXPECT_LT(*slow.cutAfter(), 4.0);
  EXPECT_EQ(t.get(), 200);
  // Every connection ends (its thread counts it out just after closing it).
  for (int i = 0; i < 40 && t.server.openConnections() > 0; ++i) {
    std::this_thread::sleep_for(std::chrono::milliseconds(50));
  }
  EXPECT_EQ(t.server.openConnections(), 0);
  EXPECT_EQ(slow.received().rfind("HTTP/1.1 400", 0), 0u) << slow.received();
}

// Another machine (127.0.0.2 here) with many connections gets only its share: the rest are
// closed at once (answered 503 when the client has not sent on meanwhile), and a client from
// elsewhere is served.
TEST(BoundedHttpServer, OneClientCannotTakeEveryConnection) {
  HttpLimits limits;
  limits.perClient = 2;
  limits.total = 8;
  BoundedTestServer t(limits);
  std::vector<std::unique_ptr<SlowHttpClient>> slow;
  for (int i = 0; i < 5; ++i) {
    slow.push_back(std::make_unique<SlowHttpClient>(t.port, "127.0.0.2", 0.5, 20));
    ASSERT_TRUE(slow.back()->connected());
  }
  std::this_thread::sleep_for(std::chrono::milliseconds(400));
  int refused = 0;
  for (const auto& s : slow) {
    if (s->cutAfter()) {
      ++refused;
      const std::string got = s->received();
      EXPECT_TRUE(got.empty() || got.rfind("HTTP/1.1 503", 0) == 0) << got;
    }
  }
  EXPECT_EQ(refused, 3);
  EXPECT_EQ(t.server.openConnections(), 2);
  EXPECT_EQ(t.get(), 200);
}

// stop() ends idle and slow connections at once, and joins every thread.
TEST(BoundedHttpServer, StopClosesIdleAndSlowConnectionsAtOnce) {
  BoundedTestServer t(HttpLimits{});
  std::vector<std::unique_ptr<SlowHttpClient>> slow;
  for (int i = 0; i < 3; ++i) {
    slow.push_back(std::make_unique<SlowHttpClient>(t.port, "127.0.0.1", 0.5, 20));
  }
  // A kept-alive client, idle after its request.
  httplib::Client idle("127.0.0.1", t.port);
  idle.set_keep_alive(true);
  const auto r = idle.Get("/status.json");
  ASSERT_TRUE(r);
  EXPECT_EQ(r->status, 200);
  std::this_thread::sleep_for(std::chrono::milliseconds(300));
  EXPECT_EQ(t.server.openConnections(), 4);
  const auto start = std::chrono::steady_clock::now();
  t.server.stop();
  EXPECT_LT(boundedSince(start), 1.0);
  EXPECT_EQ(t.server.openConnections(), 0);
  for (int i = 0; i < 40; ++i) {
    bool all = true;
    for (const auto& s : slow) all = all && s->cutAfter().has_value();
    if (all) break;
    std::this_thread::sleep_for(std::chrono::milliseconds(50));
  }
  for (const auto& s : slow) EXPECT_TRUE(s->cutAfter().has_value());
}

// A request larger than the limit is cut off as soon as it passes it, however fast it comes.
TEST(BoundedHttpServer, ARequestPastItsByteLimitIsCutOff) {
  HttpLimits limits;
  limits.requestBytes = 4096;
  BoundedTestServer t(limits);
  const int fd = ::socket(AF_INET, SOCK_STREAM, 0);
  sockaddr_in server{};
  server.sin_family = AF_INET;
  server.sin_port = htons(static_cast<uint16_t>(t.port));
  server.sin_addr.s_addr = htonl(INADDR_LOOPBACK);
  ASSERT_EQ(::connect(fd, reinterpret_cast<sockaddr*>(&server), sizeof server), 0);
  std::string request = "GET /status.json HTTP/1.1\r\nHost: x\r\n";
  for (int i = 0; i < 2000; ++i) request += "X-Filler-" + std::to_string(i) + ": 0123456789\r\n";
  const auto start = std::chrono::steady_clock::now();
  size_t sent = 0;
  while (sent < request.size()) {
    const ssize_t n = ::send(fd, request.data() + sent, request.size() - sent, MSG_NOSIGNAL);
    if (n <= 0) break;
    sent += static_cast<size_t>(n);
  }
  std::string reply;
  char buffer[4096];
  for (ssize_t n; (n = ::recv(fd, buffer, sizeof buffer, 0)) > 0;)
    reply.append(buffer, static_cast<size_t>(n));
  ::close(fd);
  EXPECT_LT(boundedSince(start), 3.0);
  EXPECT_EQ(reply.find("200 OK"), std::string::npos) << reply;
  EXPECT_EQ(t.get(), 200);
}

TEST(BoundedHttpServer, ServesManyRequestsOnAKeptAliveConnection) {
  BoundedTestServer t(HttpLimits{});
  httplib::Client client("127.0.0.1", t.port);
  client.set_keep_alive(true);
  for (int i = 0; i < 5; ++i) {
    const auto r = client.Get("/status.json");
    ASSERT_TRUE(r);
    EXPECT_EQ(r->status, 200);
    EXPECT_EQ(r->body, "{}");
  }
  const auto missing = client.Get("/other");
  ASSERT_TRUE(missing);
  EXPECT_EQ(missing->status, 404);
  EXPECT_EQ(t.server.openConnections(), 1);
}

}  // namespace
}  // namespace prt
