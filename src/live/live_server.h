#pragma once
// LiveServer: `prt render --serve [HOST:]PORT`, a read-only web view of the running render,
// served from a ProgressBoard by threads of its own (cpp-httplib), so the render's loop never
// waits for a browser.
//
//   /             a page that updates itself: the image filling in, the ownership map, a row
//                 per worker, the ETA; once the render ends it says how and where the image is
//   /status.json  the snapshot: pixels_done, pixels_total, elapsed_s, eta_s, workers, ...
//   /image.png    the image so far, pixels not yet rendered shown as a grey checkerboard
//   /ownership.png  each finished pixel in the colour of the worker that rendered it
// Every other path is 404, every method but GET and HEAD is 405. A HOST whose every address is
// a loopback one serves anyone on this machine; any other HOST (decided from the addresses it
// resolves to, not from its text) needs the access token printed at the start (the page's
// address carries it as ?token=). No client can hold the page or its end (live/bounded_http.h:
// a few connections per client, a request whole within 5 s, stopping closes every connection
// at once). Memory is bounded: at most 16 connections, small request limits, one cached PNG
// per image.

#include <cstdint>
#include <memory>
#include <string>

#include "farm/progress_board.h"

namespace prt {

struct ServeAddress {
  std::string host = "127.0.0.1";
  int port = 0;  // 0: any free port
};
// "8080", ":8080", "127.0.0.1:8080", "0.0.0.0:0", "[::1]:8080". Throws InputError.
ServeAddress parseServeAddress(const std::string& text);

class LiveServer {
 public:
  // Binds now (throws InputError when the address cannot be had) and serves from a thread.
  LiveServer(ProgressBoard& board, const ServeAddress& address);
  ~LiveServer();  // stops serving
  LiveServer(const LiveServer&) = delete;
  LiveServer& operator=(const LiveServer&) = delete;

  int port() const { return port_; }
  // The page's address, with the token when one is needed.
  std::string url() const;
  const std::string& token() const { return token_; }
  // The render has ended (its last snapshot is published): gives a page that was polling a
  // moment to fetch the end, at most `maxSeconds`, then stops serving.
  void finish(double maxSeconds = 3);

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
  std::string host_;
  std::string token_;
  int port_ = 0;
};

}  // namespace prt
