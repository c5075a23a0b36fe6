#include "cli/run_page_output.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdio>
#include <filesystem>

#include "cli/strategy_flags.h"
#include "core/input_error.h"
#include "core/machine.h"
#include "image/atomic_file.h"
#include "image/image_io.h"
#include "scene/number_text.h"

namespace prt::cli {

void checkHtmlPath(const std::string& path) {
  if (path.empty()) return;
  const size_t dot = path.rfind('.');
  std::string extension = dot == std::string::npos ? "" : path.substr(dot);
  for (char& c : extension) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  if (extension != ".html" && extension != ".htm") {
    throw InputError("--html '" + path + "': the page's file name must end in .html or .htm");
  }
  const std::filesystem::path folder = std::filesystem::path(path).parent_path();
  if (!folder.empty() && !std::filesystem::is_directory(folder)) {
    throw InputError("--html '" + path + "': no folder '" + folder.string() + "' to write it in");
  }
}

std::string parameterText(double value) {
  char buffer[32];
  std::snprintf(buffer, sizeof buffer, "%.10g", value);
  return buffer;
}

std::vector<std::pair<std::string, std::string>> strategyParameters(
    const std::string& strategy, const StrategyOptions& options) {
  std::vector<std::pair<std::string, std::string>> out;
  if (strategy.rfind("reservoir", 0) == 0) {
    out.emplace_back("initial_percent", parameterText(options.initialPercent));
  }
  if (strategy == "self") out.emplace_back("chunk", std::to_string(options.chunk));
  return out;
}

void writeReportAndPage(const std::string& reportPath, const std::string& htmlPath,
                        const nlohmann::json& document, const PagePicture& picture) {
  if (!reportPath.empty()) writeFileAtomically(reportPath, reportDocumentText(document));
  if (!htmlPath.empty()) writeFileAtomically(htmlPath, runPageHtml(document, picture));
}

namespace {

Image shrink(const Image& image, int maxSide) {
  const int factor = std::max(1, (std::max(image.width(), image.height()) + maxSide - 1) / maxSide);
  if (factor == 1) return image;
  const int w = image.width() / factor, h = image.height() / factor;
  Image out(std::max(1, w), std::max(1, h));
  for (int y = 0; y < out.height(); ++y) {
    for (int x = 0; x < out.width(); ++x) {
      Color sum(0);
      for (int dy = 0; dy < factor; ++dy) {
        for (int dx = 0; dx < factor; ++dx) {
          sum = sum + image.at(std::min(image.width() - 1, x * factor + dx),
                               std::min(image.height() - 1, y * factor + dy));
        }
      }
      out.set(x, y, sum * (1.0 / (factor * factor)));
    }
  }
  return out;
}

}  // namespace

PagePicture renderPicture(const Image& image, int maxSide) {
  PagePicture p;
  p.png = encodePng(shrink(image, maxSide));
  p.caption = "The rendered image (" + std::to_string(image.width()) + "×" +
              std::to_string(image.height()) + "), identical to a serial render.";
  return p;
}

PagePicture framesPicture(const Image& frames, int frameHeight, const FrameSequence& sequence) {
  // At most 12 frames, evenly spread from the first to the last, 4 to a row, each 160 wide.
  const uint64_t count = sequence.count();
  const uint64_t shown = std::min<uint64_t>(12, count);
  const int columns = static_cast<int>(std::min<uint64_t>(4, shown));
  const int rows = static_cast<int>((shown + 3) / 4);
  const int width = frames.width();
  const int factor = std::max(1, (width + 159) / 160);
  const int tw = std::max(1, width / factor), th = std::max(1, frameHeight / factor);
  Image sheet(columns * (tw + 4), rows * (th + 4));
  std::string numbers;
  for (uint64_t k = 0; k < shown; ++k) {
    const uint64_t ordinal = shown == 1 ? 0 : k * (count - 1) / (shown - 1);
    const int ox = static_cast<int>(k % 4) * (tw + 4) + 2, oy = static_cast<int>(k / 4) * (th + 4) + 2;
    const int top = static_cast<int>(ordinal) * frameHeight;
    for (int y = 0; y < th; ++y) {
      for (int x = 0; x < tw; ++x) {
        Color sum(0);
        for (int dy = 0; dy < factor; ++dy) {
          for (int dx = 0; dx < factor; ++dx) {
            sum = sum + frames.at(std::min(width - 1, x * factor + dx),
                                  top + std::min(frameHeight - 1, y * factor + dy));
          }
        }
        sheet.set(ox + x, oy + y, sum * (1.0 / (factor * factor)));
      }
    }
    numbers += (numbers.empty() ? "" : ", ") + std::to_string(sequence.number(ordinal));
  }
  PagePicture p;
  p.png = encodePng(sheet);
  p.caption = std::to_string(count) + " frames of " + std::to_string(width) + "×" +
              std::to_string(frameHeight) + ", each identical to a serial render; shown: frames " +
              numbers + ". The ownership map is frame " +
              std::to_string(sequence.number(count / 2)) + "'s.";
  return p;
}

PagePicture costPicture(const CostMap& costs, int maxSide) {
  std::vector<float> sorted = costs.secondsPerPixel();
  const size_t k = sorted.size() * 99 / 100;
  std::nth_element(sorted.begin(), sorted.begin() + static_cast<long>(k), sorted.end());
  const double top = sorted.empty() ? 0 : std::max(1e-30, static_cast<double>(sorted[k]));
  Image heat(costs.width(), costs.height());
  for (uint64_t p = 0; p < costs.pixelCount(); ++p) {
    const double v = std::sqrt(std::clamp(costs.pixelSeconds(p) / top, 0.0, 1.0));
    // Dark blue through magenta to pale yellow, in linear light.
    const Color c(
        std::pow(std::clamp(1.6 * v, 0.0, 1.0), 2.2),
        std::pow(std::clamp(1.6 * v - 0.6, 0.0, 1.0), 2.2),
        std::pow(std::clamp(0.35 + 0.9 * v - 1.1 * v * v + 0.6 * v * v * v, 0.0, 1.0), 2.2));
    heat.set(p, c);
  }
  PagePicture picture;
  picture.png = encodePng(shrink(heat, maxSide));
  picture.caption =
      "The cost map the simulator replayed: each pixel's render time, brighter "
      "where costlier (nothing is rendered in a simulated run).";
  picture.isRender = false;
  return picture;
}

void writeRenderReportAndPage(const RenderOptions& o, const Scene& scene, const ParallelRun& run) {
  if (o.reportPath.empty() && o.htmlPath.empty()) return;
  RunContext context;
  context.commandLine = o.commandLine;
  context.scene = o.scene.path;
  context.machine = describeMachine();
  context.dateUtc = utcNow();
  context.parameters =
      strategyParameters(o.strategyFlags.name(), strategyOptionsFrom(o.strategyFlags));
  context.parameters.emplace_back("batch_pixels", std::to_string(o.batchPixels));
  context.parameters.emplace_back("batch_seconds",
                                  o.batchSeconds ? formatDouble(*o.batchSeconds) : "auto");
  context.parameters.emplace_back("speed_index", o.speedIndex);
  std::string slowdowns;
  for (double k : o.slowdowns) {
    if (!slowdowns.empty()) slowdowns += ',';
    slowdowns += parameterText(k);
  }
  if (!slowdowns.empty()) context.parameters.emplace_back("slowdown", slowdowns);
  context.parameters.emplace_back(
      "worker_timeout_s", o.workerTimeoutSeconds ? parameterText(*o.workerTimeoutSeconds) : "auto");
  context.outputs.emplace_back("image", scene.image.output);
  for (const auto& [name, path] :
       {std::pair<const char*, const std::string&>{"report", o.reportPath},
        {"html", o.htmlPath},
        {"trace", o.tracePath},
        {"ownership", o.ownershipPath}}) {
    if (!path.empty()) context.outputs.emplace_back(name, path);
  }
  const FrameSequence frames = framesOf(o);
  const uint64_t perFrame = static_cast<uint64_t>(scene.image.width) * scene.image.height;
  // A sequence's page shows who rendered its middle frame, and a sheet of its frames.
  const uint64_t shown = frames.count() / 2;
  const auto first = run.owner.begin() + static_cast<std::ptrdiff_t>(shown * perFrame);
  const std::vector<int32_t> owner(first, first + static_cast<std::ptrdiff_t>(perFrame));
  const nlohmann::json document = reportDocument(run.report, context, run.events, owner);
  PagePicture picture;
  if (!o.htmlPath.empty() && frames.count() > 1) {
    picture = framesPicture(run.image, scene.image.height, frames);
  } else if (!o.htmlPath.empty()) {
    picture = renderPicture(run.image);
  }
  writeReportAndPage(o.reportPath, o.htmlPath, document, picture);
}

}  // namespace prt::cli
