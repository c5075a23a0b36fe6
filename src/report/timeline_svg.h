#pragma once
// The run page's timeline as inline SVG, drawn from a saved report's "timeline" (timeline.h):
// on top the share of all workers rendering over time; below one row per worker (or group)
// with waiting as the background, setup, rendering in the worker's colour, message ticks, a
// hatched stretch after a loss and a diamond for any other event, each with a tooltip; a
// time axis underneath; for a frame sequence, a dashed line across the rows where each frame
// was complete (from the report's "frames"). Rows carry data-first and data-last so the page's script can
// highlight a worker. Pure; thread-safe.

#include <nlohmann/json.hpp>
#include <string>
#include <vector>

namespace prt {

// `colours`: "#rrggbb" per worker. `frames`: the report's per-frame entries ({"frame",
// "completed_s", ...}), or null for a still. Returns the <svg> element; an empty string if the
// timeline has no rows.
std::string timelineSvg(const nlohmann::json& timeline, const std::vector<std::string>& colours,
                        const nlohmann::json& frames = nullptr);

}  // namespace prt
