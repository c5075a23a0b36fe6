// prt report RUN.json -o FILE.html: the run's page drawn again from a saved report (written by
// --report of prt render or prt simulate). The report carries the timeline and the ownership
// map; the picture comes from the image file the report names (found as written, or beside
// the report), or from --image; for a simulated run, from its cost map.

#include <filesystem>
#include <memory>
#include <string>
#include <vector>

#include "cli/commands.h"
#include "cli/run_page_output.h"
#include "core/input_error.h"
#include "image/atomic_file.h"
#include "image/image_io.h"
#include "sim/cost_map_file.h"
#include "sim/synthetic_cost.h"

namespace prt::cli {
namespace {

namespace fs = std::filesystem;

struct ReportOptions {
  std::string reportPath;
  std::string htmlPath;
  std::string imagePath;  // overrides the image the report names
};

// `path` as written if it exists, else beside the report; empty if neither.
std::string locate(const std::string& path, const std::string& reportPath) {
  if (path.empty()) return "";
  if (fs::exists(path)) return path;
  const fs::path beside = fs::path(reportPath).parent_path() / fs::path(path).filename();
  return fs::exists(beside) ? beside.string() : "";
}

std::string output(const nlohmann::json& doc, const char* name) {
  const nlohmann::json& outputs =
      doc.value("context", nlohmann::json::object()).value("outputs", nlohmann::json::object());
  return outputs.contains(name) && outputs[name].is_string() ? outputs[name].get<std::string>()
                                                             : "";
}

PagePicture picture(const ReportOptions& o, const nlohmann::json& doc) {
  if (!o.imagePath.empty()) return renderPicture(readImage(o.imagePath));
  if (doc.value("driver", "") == "simulated") {
    if (const std::string map = output(doc, "cost_map"); !map.empty()) {
      if (const std::string found = locate(map, o.reportPath); !found.empty()) {
        return costPicture(readCostMapFile(found));
      }
      return PagePicture{"", "", false,
                         "The cost map '" + map +
                             "' named by the report was not "
                             "found."};
    }
    const auto serial = doc.value("serial_s", 0.0);
    const int width = doc.value("width", 0), height = doc.value("height", 0);
    if (serial > 0 && width > 0 && height > 0) {
      return costPicture(complexSceneCostMap(width, height, serial));
    }
    return PagePicture{"", "", false, "A simulated run renders no image."};
  }
  const std::string image = output(doc, "image");
  if (const std::string found = locate(image, o.reportPath); !found.empty()) {
    return renderPicture(readImage(found));
  }
  return PagePicture{"", "", true,
                     image.empty() ? "The report names no image; pass --image FILE."
                                   : "The image '" + image +
                                         "' named by the report was not "
                                         "found (looked as written and beside the report); pass "
                                         "--image FILE."};
}

// "[json.exception.type_error.302] (/workers/0/pixels) type must be number, but is string"
// as "the field /workers/0/pixels: type must be number, but is string".
std::string fieldProblem(const nlohmann::json::exception& e) {
  std::string what = e.what();
  if (const size_t end = what.find("] "); end != std::string::npos) what.erase(0, end + 2);
  if (what.size() > 1 && what[0] == '(') {
    const size_t close = what.find(") ");
    if (close != std::string::npos) {
      return "the field " + what.substr(1, close - 1) + ": " + what.substr(close + 2);
    }
  }
  return "a field of the wrong type: " + what;
}

int runReport(const ReportOptions& o) {
  checkHtmlPath(o.htmlPath);
  const nlohmann::json doc = readReportDocument(o.reportPath);
  try {
    writeReportAndPage("", o.htmlPath, doc, picture(o, doc));
  } catch (const nlohmann::json::exception& e) {
    throw InputError("report '" + o.reportPath + "' holds " + fieldProblem(e) +
                     "; is it a report prt wrote?");
  }
  return 0;
}

}  // namespace

Action addReportCommand(CLI::App& app) {
  auto o = std::make_shared<ReportOptions>();
  auto* cmd = app.add_subcommand(
      "report",
      "Draw a run's page (one self-contained HTML file) from the report that prt render or "
      "prt simulate wrote with --report");
  cmd->add_option("report", o->reportPath, "The saved report (.json)")->required();
  cmd->add_option("-o,--output", o->htmlPath, "The page to write (.html)")->required();
  cmd->add_option("--image", o->imagePath,
                  "The rendered image to show (default: the one the report names, found as "
                  "written or beside the report)");
  return [o] { return runReport(*o); };
}

}  // namespace prt::cli
