#include "live/live_server.h"

#include <gtest/gtest.h>
#include <httplib.h>

#include <chrono>
#include <memory>
#include <nlohmann/json.hpp>
#include <thread>
#include <vector>

#include "core/input_error.h"
#include "live/bounded_http.h"
#include "live/slow_http_client.h"

namespace prt {
namespace {

TEST(ServeAddress, ParsesPortHostAndIpv6) {
  EXPECT_EQ(parseServeAddress("8080").port, 8080);
  EXPECT_EQ(parseServeAddress("8080").host, "127.0.0.1");
  EXPECT_EQ(parseServeAddress(":0").port, 0);
  EXPECT_EQ(parseServeAddress("0.0.0.0:81").host, "0.0.0.0");
  EXPECT_EQ(parseServeAddress("[::1]:9").host, "::1");
  for (const char* bad : {"", "x", "-1", "65536", "host:", ":", "[::1]9", "1e3", "123456"}) {
    EXPECT_THROW(parseServeAddress(bad), InputError) << bad;
  }
}

// Loopback is decided from the addresses a name resolves to, never from its text.
TEST(ServeAddress, LoopbackOnlyWhenEveryAddressIsLoopback) {
  for (const char* loopback : {"127.0.0.1", "127.0.0.5", "localhost", "::1", "::ffff:127.0.0.1"}) {
    EXPECT_TRUE(resolvesToLoopbackOnly(loopback)) << loopback;
  }
  for (const char* other : {"0.0.0.0", "::", "10.1.2.3", "192.168.0.1", "::ffff:10.0.0.1",
                            "name.that.does.not.resolve.invalid"}) {
    EXPECT_FALSE(resolvesToLoopbackOnly(other)) << other;
  }
}

ProgressBoard& boardWithWorkers(ProgressBoard& board) {
  board.setFacts({"threads", "adaptive", 4, 2, 1, "out.png"});
  ProgressSnapshot s;
  s.phase = ProgressSnapshot::Phase::Rendering;
  s.pixelsDone = 3;
  s.pixelsTotal = 8;
  s.elapsedSeconds = 1.5;
  s.etaSeconds = 2.5;
  WorkerProgress w;
  w.state = WorkerProgress::State::Working;
  w.pixels = 2;
  s.workers.push_back(w);
  w.state = WorkerProgress::State::Lost;
  w.pixels = 1;
  w.lostAt = 1.0;
  w.lostReason = "connection dropped";
  s.workers.push_back(w);
  board.publish(s);
  return board;
}

TEST(LiveServer, ServesTheStatusTheImageAndNothingElse) {
  ProgressBoard board;
  LiveServer server(boardWithWorkers(board), parseServeAddress("127.0.0.1:0"));
  ASSERT_GT(server.port(), 0);
  EXPECT_TRUE(server.token().empty());
  httplib::Client client("127.0.0.1", server.port());

  auto status = client.Get("/status.json");
  ASSERT_TRUE(status);
  EXPECT_EQ(status->status, 200);
  const auto j = nlohmann::json::parse(status->body);
  EXPECT_EQ(j["pixels_done"], 3);
  EXPECT_EQ(j["pixels_total"], 8);
  EXPECT_EQ(j["eta_s"], 2.5);
  EXPECT_EQ(j["elapsed_s"], 1.5);
  ASSERT_EQ(j["workers"].size(), 2u);
  EXPECT_EQ(j["workers"][0]["state"], "working");
  EXPECT_EQ(j["workers"][1]["state"], "lost");
  EXPECT_EQ(j["workers"][1]["pixels"], 1);

  auto page = client.Get("/");
  ASSERT_TRUE(page);
  EXPECT_EQ(page->status, 200);
  EXPECT_NE(page->body.find("/status.json"), std::string::npos);

  // No image copied yet: 503 and a request for one.
  auto none = client.Get("/image.png");
  ASSERT_TRUE(none);
  EXPECT_EQ(none->status, 503);
  EXPECT_TRUE(board.imageWanted());
  PartialImage image;
  image.image = Image(4, 2);
  image.done = {1, 1, 1, 0, 0, 0, 0, 0};
  image.owner = {0, 0, 1, -1, -1, -1, -1, -1};
  board.publishImage(image);
  for (const char* path : {"/image.png", "/ownership.png"}) {
    auto png = client.Get(path);
    ASSERT_TRUE(png);
    EXPECT_EQ(png->status, 200) << path;
    EXPECT_EQ(png->body.substr(1, 3), "PNG") << path;
  }

  for (const char* path : {"/../etc/passwd", "/etc/passwd", "/status.json/..", "/x"}) {
    auto r = client.Get(path);
    ASSERT_TRUE(r);
    EXPECT_EQ(r->status, 404) << path;
  }
  auto post = client.Post("/status.json", "x", "text/plain");
  ASSERT_TRUE(post);
  EXPECT_EQ(post->status, 405);
}

TEST(LiveServer, AnyAddressButLoopbackNeedsTheToken) {
  ProgressBoard board;
  LiveServer server(boardWithWorkers(board), parseServeAddress("0.0.0.0:0"));
  ASSERT_EQ(server.token().size(), 32u);
  EXPECT_NE(server.url().find("?token=" + server.token()), std::string::npos);
  httplib::Client client("127.0.0.1", server.port());
  auto refused = client.Get("/status.json");
  ASSERT_TRUE(refused);
  EXPECT_EQ(refused->status, 403);
  auto wrong = client.Get("/status.json?token=" + std::string(32, '0'));
  ASSERT_TRUE(wrong);
  EXPECT_EQ(wrong->status, 403);
  auto right = client.Get("/status.json?token=" + server.token());
  ASSERT_TRUE(right);
  EXPECT_EQ(right->status, 200);
}

TEST(LiveServer, APortInUseIsAnInputError) {
  ProgressBoard board;
  LiveServer first(board, parseServeAddress("127.0.0.1:0"));
  EXPECT_THROW(LiveServer(board, parseServeAddress("127.0.0.1:" + std::to_string(first.port()))),
               InputError);
}

TEST(LiveServer, FinishReturnsAtOnceWithoutAPage) {
  ProgressBoard board;
  LiveServer server(boardWithWorkers(board), parseServeAddress("127.0.0.1:0"));
  const auto start = std::chrono::steady_clock::now();
  server.finish(3);
  EXPECT_LT(std::chrono::steady_clock::now() - start, std::chrono::seconds(1));
}

// Two "slowloris" clients (a header line a second, the headers never ended) hold neither the
// page, which keeps answering, nor its end: finish() stops the server within its 3 s.
TEST(LiveServer, SlowClientsHoldNeitherThePageNorItsEnd) {
  ProgressBoard board;
  LiveServer server(boardWithWorkers(board), parseServeAddress("127.0.0.1:0"));
  std::vector<std::unique_ptr<test_clients::SlowHttpClient>> slow;
  for (int i = 0; i < 2; ++i) {
    slow.push_back(
        std::make_unique<test_clients::SlowHttpClient>(server.port(), "127.0.0.1", 1.0, 30.0));
    ASSERT_TRUE(slow.back()->connected());
  }
  std::this_thread::sleep_for(std::chrono::milliseconds(300));
  int answered = 0, probes = 0;
  for (; probes < 6; ++probes) {
    httplib::Client client("127.0.0.1", server.port());
    client.set_connection_timeout(2);
    client.set_read_timeout(2);
    const auto r = client.Get("/status.json");
    if (r && r->status == 200) ++answered;
    std::this_thread::sleep_for(std::chrono::milliseconds(250));
  }
  EXPECT_EQ(answered, probes) << "the page did not answer while two slow clients were connected";
  const auto start = std::chrono::steady_clock::now();
  server.finish(3);
  const double took =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  EXPECT_LT(took, 4.0) << "finish() waited for the slow clients";
}

}  // namespace
}  // namespace prt
