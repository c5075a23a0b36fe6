#pragma once
// The run page's workers: the per-worker table (speed index, relative speed, slowdown, tasks,
// pixels, busy share, messages, bytes, lost, and any key added later), past 64 workers a
// summary by speed class first with the full table folded away; and the one-line description
// of a worker the page shows when it is picked. Internal to the report library. Pure.

#include <nlohmann/json.hpp>
#include <string>
#include <vector>

namespace prt::page {

inline constexpr size_t kWorkersListed = 64;  // beyond: summaries instead of one line each

std::string workersSection(const nlohmann::json& report, const std::vector<std::string>& colours);
// "worker 2: 10,370 pixels (13.5 %), rendering 10.7 % of the run, speed index 160 ms, ...".
std::string workerInfo(const nlohmann::json& worker, const nlohmann::json& report,
                       double totalPixels);

}  // namespace prt::page
