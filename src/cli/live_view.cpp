#include "cli/live_view.h"

#include <chrono>
#include <cstdio>

namespace prt::cli {

LiveView::LiveView(const RenderOptions& o, ProgressBoard::RunFacts facts) {
  board_.setFacts(std::move(facts));
  if (!o.serve.empty()) {
    server_ = std::make_unique<LiveServer>(board_, parseServeAddress(o.serve));
    std::fprintf(stderr, "prt: live page at %s\n", server_->url().c_str());
    std::fflush(stderr);
  }
  terminal_.emplace(board_, !o.quiet);
}

LiveView::~LiveView() { finish(); }

void LiveView::stopLines() {
  if (terminal_) terminal_->stop();
}

void LiveView::finish() {
  stopLines();
  if (server_) server_->finish();
  server_.reset();
}

double steadySeconds() {
  return std::chrono::duration<double>(std::chrono::steady_clock::now().time_since_epoch())
      .count();
}

}  // namespace prt::cli
