#pragma once
// The event stream reduced to what a page can draw, bounded in size whatever the run.
//
// Time is cut into `ticks` equal steps of the elapsed time. Up to `maxRows` workers, each has
// a row with its setup and rendering spans in ticks (spans less than a tick apart merge; a
// span shorter than a tick still covers one), the ticks in which it sent or received a
// message, and marks for every other event on it (a loss, a reissue, any kind added later:
// named by eventKindName). Beyond `maxRows` workers, a row stands for a group of consecutive
// workers and carries, per time bin (`shareBins` over the run), the share of the group's time
// spent rendering and setting up; messages are then not drawn one by one (the JSON says so:
// "aggregated": true). Events of the master other than messages are marks of their own. Every
// run also gets the share of all workers rendering in each bin, the curve of how well the work
// was shared out.
//
// JSON (all times in ticks unless named _s):
//   {"elapsed_s", "ticks", "tick_s", "share_bins", "workers", "workers_per_row", "aggregated",
//    "rendering_share": [per bin],             // all workers, 0..1, three decimals
//    "rows": [{"first", "last",                // the workers the row stands for
//              "rendering": [[from, to], ...], "setup": [[from, to], ...], "messages": [t, ...]
//              | "rendering_share": [...], "setup_share": [...],
//              "finished_s",                    // last rendering end of the row's workers
//              "marks": [{"kind", "label", "t_s", "end_s"?, "worker"}]}],
//    "master_marks": [...], "marks_dropped": N}
// Pure; thread-safe.

#include <nlohmann/json.hpp>
#include <vector>

#include "metrics/events.h"

namespace prt {

struct TimelineOptions {
  int ticks = 1000;          // time steps across the run; also the bins of the shares
  int maxRows = 64;          // workers drawn one by one; above, rows are groups
  int maxMarksPerRow = 100;  // marks kept per row (and for the master); the rest are counted
  int shareBins = 250;       // time bins of the shares (all workers', and grouped rows')
};

nlohmann::json timelineJson(const std::vector<Event>& events, int workers, double elapsedSeconds,
                            const TimelineOptions& options = {});

}  // namespace prt
