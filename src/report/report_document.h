#pragma once
// The saved run report: what --report FILE.json writes and `prt report` reads back to draw
// the run's page. It is RunReport::toJson()'s document (elapsed_s, speedup, ..., workers)
// with three more keys:
//   "context":       how the run was made: command line, scene, machine, start time, the
//                    strategy's and the run's parameters, and the files it wrote ("outputs",
//                    paths as given on the command line);
//   "timeline":      the event stream reduced to a drawable, bounded size (timeline.h);
//   "ownership_map": which worker rendered each pixel, run-length coded (ownership_map.h);
//                    absent when the driver does not know it.
// Keys other engineers add to the report (lost_workers, reissued_tasks, ...) pass through.
// Pure except readReportDocument, which reads a file.

#include <cstdint>
#include <nlohmann/json.hpp>
#include <string>
#include <utility>
#include <vector>

#include "metrics/events.h"
#include "metrics/run_report.h"

namespace prt {

struct RunContext {
  std::string commandLine;  // as typed: "prt render scenes/complex.scene --workers 4 ..."
  std::string scene;        // the scene file, or for a simulated run the cost map's source
  std::string machine;      // the master's machine (core/machine.h)
  std::string dateUtc;      // when the report was written, "2026-12-01 19:42 UTC"
  std::vector<std::pair<std::string, std::string>> parameters;  // in order, name -> value
  std::vector<std::pair<std::string, std::string>> outputs;     // "image" -> "out.png", ...
};

// The current time as "YYYY-MM-DD HH:MM UTC".
std::string utcNow();

// `owner`: per pixel of the width x height image, the worker that rendered it (-1: none);
// empty: no ownership map.
nlohmann::json reportDocument(const RunReport& report, const RunContext& context,
                              const std::vector<Event>& events, const std::vector<int32_t>& owner);

// The document as the file holds it: indented for reading, except the bulky "timeline" and
// "ownership_map", one line each.
std::string reportDocumentText(const nlohmann::json& document);

// Parses a saved report. Throws InputError naming `path` (with line:col for malformed JSON)
// when it cannot be read, is not JSON, or lacks the keys every report has.
nlohmann::json parseReportDocument(const std::string& text, const std::string& path);
nlohmann::json readReportDocument(const std::string& path);

}  // namespace prt
