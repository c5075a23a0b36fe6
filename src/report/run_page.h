#pragma once
// The run page: one self-contained HTML file (no network fetches; the image embedded as a
// data: URI, the style sheet and script inline) that opens from the disk in any browser and
// shows a parallel run to someone who has never read its JSON:
//   - at a glance: what balancing bought (speed-up against what the workers' speeds allow,
//     how busy the workers were, how close together they finished), then the measures
//     (elapsed, speed-up, efficiency, MASU, ASU, messages, bytes) and any fault and recovery
//     counts the report carries;
//   - the rendered image beside the ownership map; hovering or clicking a worker (on the
//     map, in the table, the legend or the timeline) highlights its pixels;
//   - the timeline (timeline_svg.h);
//   - the per-worker table with speed indices (and, past 64 workers, a summary by speed
//     class with the full table folded away);
//   - the strategy and its parameters, the scene, the command line and the machine.
// Drawn from a saved report document (report_document.h), which the page also embeds as JSON
// in <script type="application/json" id="prt-run">, so `prt report RUN.json` and a run's
// --html give the same page. Keys it does not know are shown generically. Pure; thread-safe.

#include <nlohmann/json.hpp>
#include <string>

namespace prt {

struct PagePicture {
  std::string png;       // PNG bytes; empty: no picture
  std::string caption;   // under the picture
  bool isRender = true;  // the rendered image (the ownership map is then shaded by it)
  std::string missing;   // why there is no picture, shown in its place
};

std::string runPageHtml(const nlohmann::json& report, const PagePicture& picture);

// "#rrggbb" per worker: Tableau 10 (as the --ownership image) up to ten workers, else hues
// spread by the golden angle.
std::vector<std::string> workerColours(int workers);

}  // namespace prt
