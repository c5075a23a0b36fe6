#pragma once
// The live page that LiveServer serves at `/`: one HTML document with its style and script,
// which polls /status.json and redraws itself (see live_server.h).

#include <string>

namespace prt {

const std::string& livePageHtml();

}  // namespace prt
