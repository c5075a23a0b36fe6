#pragma once
// Chrome trace-event JSON (opens in Perfetto and chrome://tracing): one track per worker with
// its setup, rendering and idle spans and its messages, and one for the master.

#include <string>
#include <vector>

#include "metrics/events.h"

namespace prt {

std::string chromeTraceJson(const std::vector<Event>& events, int workerCount,
                            double elapsedSeconds);

}  // namespace prt
