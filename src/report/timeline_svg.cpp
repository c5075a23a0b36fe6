#include "report/timeline_svg.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "report/html_text.h"

namespace prt {
namespace {

using nlohmann::json;

constexpr double kWidth = 1000, kLeft = 86, kRight = 14, kShareHeight = 64, kGap = 14;
constexpr double kPlot = kWidth - kLeft - kRight;

std::string num(double v) {
  char buffer[32];
  std::snprintf(buffer, sizeof buffer, "%.1f", v);
  std::string s = buffer;
  if (s.size() > 2 && s.compare(s.size() - 2, 2, ".0") == 0) s.resize(s.size() - 2);
  return s;
}

// A step of 1, 2 or 5 times a power of ten giving about `target` intervals.
double niceStep(double span, int target) {
  const double raw = span / std::max(1, target);
  const double power = std::pow(10.0, std::floor(std::log10(raw)));
  for (double m : {1.0, 2.0, 5.0}) {
    if (m * power >= raw) return m * power;
  }
  return 10 * power;
}

// Axis labels in one unit for the whole axis, with the decimals the step needs.
std::string axisLabel(double t, double step, double end) {
  const bool millis = end < 1;
  const double scale = millis ? 1e3 : 1;
  const double scaledStep = step * scale;
  const int decimals =
      scaledStep >= 1 ? 0 : static_cast<int>(std::ceil(-std::log10(scaledStep) - 1e-9));
  char buffer[48];
  std::snprintf(buffer, sizeof buffer, "%.*f %s", decimals, t * scale, millis ? "ms" : "s");
  return buffer;
}

std::string rowLabel(int first, int last) {
  return first == last ? "w " + std::to_string(first)
                       : "w " + std::to_string(first) + "–" + std::to_string(last);
}

}  // namespace

std::string timelineSvg(const json& timeline, const std::vector<std::string>& colours,
                        const json& frames) {
  if (!timeline.is_object() || !timeline.contains("rows") || timeline["rows"].empty()) return "";
  const json& rows = timeline["rows"];
  const int ticks = std::max(1, timeline.value("ticks", 1000));
  const double tickSeconds = timeline.value("tick_s", 1.0);
  const double end = tickSeconds * ticks;
  const bool aggregated = timeline.value("aggregated", false);
  const double rowHeight = std::clamp(420.0 / static_cast<double>(rows.size()), 6.0, 22.0);
  const double rowsTop = kShareHeight + kGap;
  const double rowsBottom = rowsTop + rowHeight * static_cast<double>(rows.size());
  const double height = rowsBottom + 30;
  auto x = [&](double tick) { return kLeft + kPlot * tick / ticks; };
  // Shares come in bins of their own: bin i of `count` starts at this x.
  auto xb = [&](double bin, size_t binCount) {
    return kLeft + kPlot * bin / static_cast<double>(std::max<size_t>(1, binCount));
  };
  auto xs = [&](double seconds) { return kLeft + kPlot * std::clamp(seconds / end, 0.0, 1.0); };
  auto colourOf = [&](int w) {
    return w >= 0 && static_cast<size_t>(w) < colours.size() ? colours[static_cast<size_t>(w)]
                                                             : std::string("#4e79a7");
  };

  std::string s = "<svg id=\"timeline\" viewBox=\"0 0 " + num(kWidth) + " " + num(height) +
                  "\" role=\"img\" aria-label=\"Timeline of the workers\">\n";
  s += "<defs><pattern id=\"hatch\" width=\"6\" height=\"6\" patternUnits=\"userSpaceOnUse\" "
       "patternTransform=\"rotate(45)\"><rect width=\"6\" height=\"6\" fill=\"#fbe3e3\"/>"
       "<line x1=\"0\" y1=\"0\" x2=\"0\" y2=\"6\" stroke=\"#d62728\" stroke-width=\"2.5\"/>"
       "</pattern></defs>\n";

  // The share of all workers rendering, as an area over time.
  const json& share = timeline.contains("rendering_share") ? timeline["rendering_share"] : json();
  s += "<g class=\"share\"><rect x=\"" + num(kLeft) + "\" y=\"0\" width=\"" + num(kPlot) +
       "\" height=\"" + num(kShareHeight) + "\" class=\"waiting\"/>";
  if (share.is_array() && !share.empty()) {
    std::string path = "M" + num(kLeft) + " " + num(kShareHeight);
    for (size_t t = 0; t < share.size(); ++t) {
      const double y = kShareHeight * (1 - std::clamp(share[t].get<double>(), 0.0, 1.0));
      path += "H" + num(xb(static_cast<double>(t), share.size())) + "V" + num(y) + "H" +
              num(xb(static_cast<double>(t + 1), share.size()));
    }
    path += "V" + num(kShareHeight) + "Z";
    s += "<path d=\"" + path +
         "\" class=\"share-area\"><title>share of the workers rendering"
         "</title></path>";
  }
  s += "<text x=\"" + num(kLeft - 6) + "\" y=\"11\" class=\"axis end\">100 %</text>";
  s += "<text x=\"" + num(kLeft - 6) + "\" y=\"" + num(kShareHeight) +
       "\" class=\"axis end\">0</text>";
  s += "<text x=\"" + num(kLeft - 6) + "\" y=\"" + num(kShareHeight / 2 + 4) +
       "\" class=\"axis end\">rendering</text></g>\n";

  for (size_t r = 0; r < rows.size(); ++r) {
    const json& row = rows[r];
    const int first = row.value("first", 0), last = row.value("last", 0);
    const double y = rowsTop + rowHeight * static_cast<double>(r);
    const double h = std::max(1.0, rowHeight - (rowHeight > 8 ? 2 : 1));
    const std::string colour = colourOf(first);
    s += "<g class=\"row\" data-first=\"" + std::to_string(first) + "\" data-last=\"" +
         std::to_string(last) + "\"><title>" + escapeHtml(rowLabel(first, last)) +
         (row.contains("finished_s")
              ? ", last result at " + formatSeconds(row["finished_s"].get<double>())
              : std::string()) +
         "</title>";
    s += "<rect x=\"" + num(kLeft) + "\" y=\"" + num(y) + "\" width=\"" + num(kPlot) +
         "\" height=\"" + num(h) + "\" class=\"waiting\"/>";
    if (!aggregated) {
      for (const char* kind : {"setup", "rendering"}) {
        if (!row.contains(kind)) continue;
        std::string path;
        for (const json& span : row[kind]) {
          const double a = x(span[0].get<double>()), b = x(span[1].get<double>());
          path += "M" + num(a) + " " + num(y) + "h" + num(std::max(0.6, b - a)) + "v" + num(h) +
                  "H" + num(a) + "Z";
        }
        if (path.empty()) continue;
        s += std::string("<path d=\"") + path + "\" class=\"" + kind + "\"" +
             (std::string(kind) == "rendering" ? " fill=\"" + colour + "\"" : "") + "/>";
      }
      if (row.contains("messages") && !row["messages"].empty()) {
        std::string path;
        for (const json& t : row["messages"]) {
          path += "M" + num(x(t.get<double>()) + 0.5) + " " + num(y) + "v" + num(h * 0.35);
        }
        s += "<path d=\"" + path + "\" class=\"messages\"/>";
      }
    } else {
      // Shares quantised to fifths, equal neighbours merged: a few paths per row.
      for (const char* kind : {"setup_share", "rendering_share"}) {
        if (!row.contains(kind)) continue;
        const json& values = row[kind];
        std::string paths[5];
        for (size_t t = 0; t < values.size();) {
          const int level = static_cast<int>(std::ceil(values[t].get<double>() * 5 - 1e-9));
          size_t u = t + 1;
          while (u < values.size() &&
                 static_cast<int>(std::ceil(values[u].get<double>() * 5 - 1e-9)) == level) {
            ++u;
          }
          if (level > 0) {
            const double a = xb(static_cast<double>(t), values.size());
            const double b = xb(static_cast<double>(u), values.size());
            paths[std::min(level, 5) - 1] +=
                "M" + num(a) + " " + num(y) + "h" + num(b - a) + "v" + num(h) + "H" + num(a) + "Z";
          }
          t = u;
        }
        const bool render = std::string(kind) == "rendering_share";
        for (int level = 0; level < 5; ++level) {
          if (paths[level].empty()) continue;
          s += "<path d=\"" + paths[level] + "\" class=\"" + (render ? "rendering" : "setup") +
               "\"" + (render ? " fill=\"" + colour + "\"" : "") + " fill-opacity=\"" +
               num(0.2 * (level + 1)) + "\"/>";
        }
      }
    }
    if (row.contains("marks")) {
      for (const json& mark : row["marks"]) {
        const double t = mark.value("t_s", 0.0);
        const std::string title = "<title>" + escapeHtml(mark.value("label", std::string())) +
                                  " at " + formatSeconds(t) + "</title>";
        if (mark.value("kind", std::string()) == "worker_joined") {
          // Not there yet: the row is blank until the worker joins.
          s += "<rect x=\"" + num(kLeft) + "\" y=\"" + num(y) + "\" width=\"" +
               num(std::max(0.0, xs(t) - kLeft)) + "\" height=\"" + num(h) +
               "\" class=\"absent\">" + title + "</rect>";
          continue;
        }
        if (mark.value("kind", std::string()) == "worker_lost") {
          s += "<rect x=\"" + num(xs(t)) + "\" y=\"" + num(y) + "\" width=\"" +
               num(std::max(1.0, kLeft + kPlot - xs(t))) + "\" height=\"" + num(h) +
               "\" class=\"lost\">" + title + "</rect>";
          continue;
        }
        const double cx = xs(t), cy = y + h / 2, d = std::max(3.0, h / 2);
        s += "<path d=\"M" + num(cx) + " " + num(cy - d) + "l" + num(d) + " " + num(d) + "l-" +
             num(d) + " " + num(d) + "l-" + num(d) + " -" + num(d) + "Z\" class=\"mark\">" + title +
             "</path>";
      }
    }
    if (rowHeight >= 9 || r % static_cast<size_t>(std::ceil(9 / rowHeight)) == 0) {
      s += "<text x=\"" + num(kLeft - 6) + "\" y=\"" + num(y + h / 2 + 4) +
           "\" class=\"label end\">" + escapeHtml(rowLabel(first, last)) + "</text>";
    }
    s += "</g>\n";
  }

  // Master events other than messages (a reissue decided by the master, ...).
  if (timeline.contains("master_marks")) {
    for (const json& mark : timeline["master_marks"]) {
      const double cx = xs(mark.value("t_s", 0.0));
      s += "<path d=\"M" + num(cx) + " " + num(rowsTop - 2) + "l4 -7h-8Z\" class=\"mark\"><title>" +
           escapeHtml(mark.value("label", std::string())) + " (master) at " +
           formatSeconds(mark.value("t_s", 0.0)) + "</title></path>";
    }
  }

  // Frame boundaries: where each frame of a sequence was complete. Every frame gets its line;
  // labels only where they do not crowd one another (about 40 px apart).
  if (frames.is_array() && !frames.empty()) {
    s += "<g class=\"frames\">";
    double lastLabel = -1e9;
    for (const json& f : frames) {
      if (!f.is_object() || !f.contains("completed_s") || !f["completed_s"].is_number()) continue;
      const double t = f["completed_s"].get<double>();
      const std::string name =
          f.contains("frame") && f["frame"].is_number_integer()
              ? "frame " + std::to_string(f["frame"].get<long long>())
              : std::string("a frame");
      const double px = xs(t);
      s += "<path d=\"M" + num(px) + " " + num(rowsTop - 4) + "V" + num(rowsBottom) +
           "\" class=\"frame-line\"><title>" + escapeHtml(name) + " complete at " +
           formatSeconds(t) + "</title></path>";
      if (px - lastLabel >= 40) {
        s += "<text x=\"" + num(px) + "\" y=\"" + num(rowsTop - 5) + "\" class=\"frame-label\">" +
             escapeHtml(name.substr(name.rfind(' ') + 1)) + "</text>";
        lastLabel = px;
      }
    }
    s += "</g>\n";
  }

  // Time axis.
  const double step = niceStep(end, 8);
  s += "<g class=\"axis\"><path d=\"M" + num(kLeft) + " " + num(rowsBottom) + "H" +
       num(kLeft + kPlot) + "\" class=\"axis-line\"/>";
  for (double t = 0; t <= end * (1 + 1e-9); t += step) {
    const double px = xs(t);
    s += "<path d=\"M" + num(px) + " " + num(rowsBottom) + "v5\" class=\"axis-line\"/>";
    s += "<text x=\"" + num(px) + "\" y=\"" + num(rowsBottom + 18) + "\" class=\"axis mid\">" +
         axisLabel(t, step, end) + "</text>";
  }
  s += "</g>\n</svg>\n";
  return s;
}

}  // namespace prt
