#include "report/report_document.h"

#include <ctime>
#include <fstream>
#include <sstream>

#include "core/input_error.h"
#include "report/ownership_map.h"
#include "report/timeline.h"

namespace prt {
namespace {

using nlohmann::json;

// Line and column (1-based) of a byte offset, and that line's text.
SourceLocation locate(const std::string& text, size_t offset, const std::string& path) {
  SourceLocation where{path, 1, 1, ""};
  size_t lineStart = 0;
  for (size_t i = 0; i < offset && i < text.size(); ++i) {
    if (text[i] == '\n') {
      ++where.line;
      lineStart = i + 1;
    }
  }
  where.column = static_cast<int>(std::min(offset, text.size()) - lineStart) + 1;
  const size_t lineEnd = text.find('\n', lineStart);
  where.lineText = text.substr(
      lineStart, lineEnd == std::string::npos ? std::string::npos : lineEnd - lineStart);
  return where;
}

}  // namespace

std::string utcNow() {
  const std::time_t now = std::time(nullptr);
  std::tm tm{};
  gmtime_r(&now, &tm);
  char buffer[32];
  std::strftime(buffer, sizeof buffer, "%Y-%m-%d %H:%M UTC", &tm);
  return buffer;
}

json reportDocument(const RunReport& report, const RunContext& context,
                    const std::vector<Event>& events, const std::vector<int32_t>& owner) {
  json doc = json::parse(report.toJson());
  json parameters = json::object(), outputs = json::object();
  for (const auto& [name, value] : context.parameters) parameters[name] = value;
  for (const auto& [name, value] : context.outputs) outputs[name] = value;
  doc["context"] = {{"command_line", context.commandLine},
                    {"scene", context.scene},
                    {"machine", context.machine},
                    {"date", context.dateUtc},
                    {"parameters", parameters},
                    {"outputs", outputs}};
  doc["timeline"] =
      timelineJson(events, static_cast<int>(report.workers.size()), report.elapsedSeconds);
  const size_t pixels =
      static_cast<size_t>(report.info.width) * static_cast<size_t>(report.info.height);
  if (!owner.empty() && owner.size() == pixels) {
    doc["ownership_map"] = ownershipJson(owner, report.info.width, report.info.height);
  }
  return doc;
}

std::string reportDocumentText(const json& document) {
  constexpr auto kReplace = json::error_handler_t::replace;
  json shown = document;
  std::vector<std::pair<std::string, std::string>> bulky;
  for (const char* key : {"timeline", "ownership_map"}) {
    if (!shown.contains(key)) continue;
    const std::string placeholder = std::string("@prt-compact-") + key + "@";
    bulky.emplace_back("\"" + placeholder + "\"", shown[key].dump(-1, ' ', false, kReplace));
    shown[key] = placeholder;
  }
  std::string text = shown.dump(2, ' ', false, kReplace);
  for (const auto& [placeholder, compact] : bulky) {
    const size_t at = text.find(placeholder);
    if (at != std::string::npos) text.replace(at, placeholder.size(), compact);
  }
  return text + "\n";
}

json parseReportDocument(const std::string& text, const std::string& path) {
  json doc;
  try {
    doc = json::parse(text);
  } catch (const json::parse_error& e) {
    // e.byte is 1-based, pointing just past the offending character.
    const size_t offset = e.byte > 0 ? e.byte - 1 : 0;
    std::string what = e.what();
    const size_t colon = what.rfind(": ");
    throw InputError("'" + path + "' is not a valid JSON report: " +
                         (colon == std::string::npos ? what : what.substr(colon + 2)),
                     locate(text, offset, path));
  }
  if (!doc.is_object()) throw InputError("'" + path + "' is not a run report (not an object)");
  for (const char* key : {"strategy", "elapsed_s", "workers", "width", "height"}) {
    if (!doc.contains(key)) {
      throw InputError("'" + path + "' is not a run report written by prt (no \"" +
                       std::string(key) + "\" key)");
    }
  }
  if (!doc["workers"].is_array() || !doc["elapsed_s"].is_number()) {
    throw InputError("'" + path + "': \"workers\" must be a list and \"elapsed_s\" a number");
  }
  return doc;
}

json readReportDocument(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw InputError("cannot read the report '" + path + "'");
  std::ostringstream text;
  text << in.rdbuf();
  return parseReportDocument(text.str(), path);
}

}  // namespace prt
