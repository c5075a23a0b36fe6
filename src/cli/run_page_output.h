#pragma once
// The files that describe a parallel run, written after it: the saved report (--report
// FILE.json) and the run's page (--html FILE.html), for prt render under either driver and
// for prt simulate. Both come from one report document (report/report_document.h).

#include <string>
#include <utility>
#include <vector>

#include "balance/strategy.h"
#include "cli/render_options.h"
#include "farm/parallel_run.h"
#include "image/image.h"
#include "report/report_document.h"
#include "report/run_page.h"
#include "sim/cost_map.h"
#include "trace/scene.h"

namespace prt::cli {

// Throws InputError unless `path` is empty, or ends in .html or .htm in a folder that exists
// (checked before a run, so that a typo does not cost the render).
void checkHtmlPath(const std::string& path);

// The strategy's own parameters (those it reads from StrategyOptions), by name.
std::vector<std::pair<std::string, std::string>> strategyParameters(const std::string& strategy,
                                                                    const StrategyOptions& options);

// A number as the command line would take it: "80", "0.5".
std::string parameterText(double value);

// Writes whichever of the two paths is not empty, each atomically.
void writeReportAndPage(const std::string& reportPath, const std::string& htmlPath,
                        const nlohmann::json& document, const PagePicture& picture);

// --report and --html of prt render (local and MPI drivers): the document with the run's
// context (command line, scene, machine, parameters, files written) and the page with the
// rendered image.
void writeRenderReportAndPage(const RenderOptions& o, const Scene& scene, const ParallelRun& run);

// The picture for a page: the image, averaged down by a whole factor to at most `maxSide`
// pixels on its longest side.
PagePicture renderPicture(const Image& image, int maxSide = 1600);
// A simulated run's picture: the cost map as a heat map (brighter is costlier, square-root
// scale up to the 99th percentile).
// A sheet of a sequence's frames (stacked in `frames`, `frameHeight` rows each) for the page.
PagePicture framesPicture(const Image& frames, int frameHeight, const FrameSequence& sequence);
PagePicture costPicture(const CostMap& costs, int maxSide = 1600);

}  // namespace prt::cli
