#include "live/live_server.h"

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cmath>
#include <mutex>
#include <nlohmann/json.hpp>
#include <random>
#include <thread>

#include "core/input_error.h"
#include "farm/parallel_run.h"
#include "image/image_io.h"
#include "live/bounded_http.h"
#include "live/live_page.h"
#include "live/progress_text.h"

namespace prt {
namespace {

using Clock = std::chrono::steady_clock;

std::string randomToken() {
  std::random_device device;  // /dev/urandom
  std::string token;
  static const char kHex[] = "0123456789abcdef";
  for (int i = 0; i < 8; ++i) {
    const unsigned value = device();
    for (int k = 0; k < 4; ++k) token += kHex[(value >> (4 * k)) & 0xF];
  }
  return token;
}

bool sameToken(const std::string& a, const std::string& b) {
  if (a.size() != b.size()) return false;
  unsigned diff = 0;
  for (size_t i = 0; i < a.size(); ++i) diff |= static_cast<unsigned>(a[i] ^ b[i]);
  return diff == 0;
}

nlohmann::json optionalNumber(const std::optional<double>& value) {
  return value && std::isfinite(*value) ? nlohmann::json(*value) : nlohmann::json(nullptr);
}

// The image so far: finished pixels as rendered, the rest a grey checkerboard of 8 px.
Image markedImage(const PartialImage& p) {
  Image out = p.image;
  for (int y = 0; y < out.height(); ++y) {
    for (int x = 0; x < out.width(); ++x) {
      const size_t i = out.pixelIndex(x, y);
      if (p.done[i]) continue;
      const double grey = ((x / 8 + y / 8) % 2 == 0) ? 0.16 : 0.09;
      out.set(i, Color(grey));
    }
  }
  return out;
}

}  // namespace

ServeAddress parseServeAddress(const std::string& text) {
  ServeAddress a;
  std::string port = text;
  const auto fail = [&](const std::string& why) {
    throw InputError("--serve '" + text + "': " + why +
                     "; expected [HOST:]PORT, e.g. 8080 or 0.0.0.0:8080 (PORT 0: any free port)");
  };
  if (!text.empty() && text.front() == '[') {
    const size_t close = text.find(']');
    if (close == std::string::npos || close + 1 >= text.size() || text[close + 1] != ':') {
      fail("an IPv6 host is written [HOST]:PORT");
    }
    a.host = text.substr(1, close - 1);
    port = text.substr(close + 2);
  } else if (const size_t colon = text.rfind(':'); colon != std::string::npos) {
    if (colon > 0) a.host = text.substr(0, colon);
    port = text.substr(colon + 1);
  }
  if (port.empty() || port.size() > 5 ||
      !std::all_of(port.begin(), port.end(), [](char c) { return c >= '0' && c <= '9'; })) {
    fail("PORT must be a number from 0 to 65535");
  }
  a.port = std::stoi(port);
  if (a.port > 65535) fail("PORT must be a number from 0 to 65535");
  if (a.host.empty()) fail("HOST is empty");
  return a;
}

struct LiveServer::Impl {
  ProgressBoard& board;
  BoundedHttpServer server;
  std::mutex cacheMutex;
  // One cached PNG per image, keyed by the image's version.
  uint64_t imageVersion = UINT64_MAX, ownershipVersion = UINT64_MAX;
  std::string imagePng, ownershipPng;
  std::atomic<int64_t> lastStatusServed{0};  // steady-clock ns of the last /status.json
  std::atomic<uint64_t> lastVersionServed{0};

  explicit Impl(ProgressBoard& b) : board(b) {}

  std::string statusJson() {
    const ProgressSnapshot s = board.snapshot();
    const ProgressBoard::RunFacts facts = board.facts();
    nlohmann::json j;
    j["phase"] = phaseName(s.phase);
    j["version"] = s.version;
    j["driver"] = facts.driver;
    j["strategy"] = facts.strategy;
    j["width"] = facts.width;
    j["height"] = facts.height;
    j["frames"] = facts.frames;
    j["output"] = facts.output;
    j["pixels_done"] = s.pixelsDone;
    j["pixels_total"] = s.pixelsTotal;
    j["resumed_pixels"] = s.resumedPixels;
    j["elapsed_s"] = s.elapsedSeconds;
    j["eta_s"] = optionalNumber(s.etaSeconds);
    j["done_fraction"] = optionalNumber(s.doneFraction);
    j["summary"] = progressSummary(s);
    j["message"] = s.message;
    nlohmann::json workers = nlohmann::json::array();
    for (size_t i = 0; i < s.workers.size(); ++i) {
      const WorkerProgress& w = s.workers[i];
      nlohmann::json row;
      row["id"] = i;
      row["state"] = stateName(w.state);
      row["pixels"] = w.pixels;
      row["share"] = s.pixelsTotal > 0 ? static_cast<double>(w.pixels) /
                                             static_cast<double>(s.pixelsTotal)
                                       : 0.0;
      row["pixels_per_s"] = w.pixelsPerSecond;
      row["silent_s"] = w.silentSeconds;
      row["joined_at_s"] = optionalNumber(w.joinedAt);
      row["lost_at_s"] = optionalNumber(w.lostAt);
      row["lost_reason"] = w.lostReason;
      workers.push_back(std::move(row));
    }
    j["workers"] = std::move(workers);
    lastVersionServed = s.version;
    lastStatusServed = Clock::now().time_since_epoch().count();
    return j.dump();
  }

  // The PNG of the latest image copy (or nothing yet); `ownership` picks the map.
  std::optional<std::string> png(bool ownership) {
    const std::shared_ptr<const PartialImage> image = board.image();
    if (!image) return std::nullopt;
    std::lock_guard lock(cacheMutex);
    uint64_t& version = ownership ? ownershipVersion : imageVersion;
    std::string& cache = ownership ? ownershipPng : imagePng;
    if (version != image->version) {
      cache = encodePng(ownership ? ownershipImage(image->image, image->owner)
                                  : markedImage(*image));
      version = image->version;
    }
    return cache;
  }
};

LiveServer::LiveServer(ProgressBoard& board, const ServeAddress& address)
    : impl_(std::make_unique<Impl>(board)), host_(address.host) {
  board.watch();  // the page shows the image: the render copies it for the page
  BoundedHttpServer& s = impl_->server;
  // Loopback, and no token, only when every address the name resolves to is a loopback one
  // (the bound one included): "127.example.test" may well resolve to 0.0.0.0.
  bool loopback = false;
  std::string why;
  port_ = s.bindAndListen(address.host, address.port, loopback, why);
  if (port_ < 0) {
    throw InputError("--serve: cannot listen on " + address.host + ":" +
                     std::to_string(address.port) + " (" + why +
                     "); choose another, or PORT 0 for any free one");
  }
  if (!loopback) token_ = randomToken();
  s.set_payload_max_length(1024);
  const std::string token = token_;
  s.set_pre_routing_handler([token](const httplib::Request& request, httplib::Response& response) {
    if (request.method != "GET" && request.method != "HEAD") {
      response.status = 405;
      response.set_header("Allow", "GET, HEAD");
      response.set_content("read-only: GET only\n", "text/plain");
      return httplib::Server::HandlerResponse::Handled;
    }
    if (!token.empty() && !sameToken(request.get_param_value("token"), token)) {
      response.status = 403;
      response.set_content("this page needs the access token prt printed: add ?token=...\n",
                           "text/plain");
      return httplib::Server::HandlerResponse::Handled;
    }
    response.set_header("Cache-Control", "no-store");
    response.set_header("X-Content-Type-Options", "nosniff");
    return httplib::Server::HandlerResponse::Unhandled;
  });
  Impl* impl = impl_.get();
  s.Get("/", [](const httplib::Request&, httplib::Response& response) {
    response.set_content(livePageHtml(), "text/html; charset=utf-8");
  });
  s.Get("/status.json", [impl](const httplib::Request&, httplib::Response& response) {
    response.set_content(impl->statusJson(), "application/json");
  });
  const auto image = [impl](bool ownership) {
    return [impl, ownership](const httplib::Request&, httplib::Response& response) {
      if (const std::optional<std::string> png = impl->png(ownership)) {
        response.set_content(*png, "image/png");
      } else {
        response.status = 503;
        response.set_header("Retry-After", "1");
        response.set_content("no pixels yet\n", "text/plain");
      }
    };
  };
  s.Get("/image.png", image(false));
  s.Get("/ownership.png", image(true));
  s.start();
}

LiveServer::~LiveServer() {
  impl_->server.stop();
}

std::string LiveServer::url() const {
  const std::string host = host_.find(':') != std::string::npos ? "[" + host_ + "]" : host_;
  std::string u = "http://" + host + ":" + std::to_string(port_) + "/";
  if (!token_.empty()) u += "?token=" + token_;
  return u;
}

void LiveServer::finish(double maxSeconds) {
  const uint64_t last = impl_->board.snapshot().version;
  const auto deadline = Clock::now() + std::chrono::duration_cast<Clock::duration>(
                                           std::chrono::duration<double>(maxSeconds));
  const auto recent = [&] {
    const auto served = Clock::time_point(Clock::duration(impl_->lastStatusServed.load()));
    return Clock::now() - served < std::chrono::seconds(5);
  };
  // Only a page that was polling lately is waited for, until it has seen the last snapshot.
  bool waited = false;
  while (Clock::now() < deadline && recent() && impl_->lastVersionServed.load() < last) {
    std::this_thread::sleep_for(std::chrono::milliseconds(50));
    waited = true;
  }
  // Then its last fetch of the images.
  if (waited || recent()) std::this_thread::sleep_until(std::min(deadline, Clock::now() + std::chrono::seconds(1)));
  // Every connection ends now, an idle or slow client's included.
  impl_->server.stop();
}

}  // namespace prt
