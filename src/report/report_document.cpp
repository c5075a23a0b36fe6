#include "report/report_document.h"

#include <ctime>
#include <fstream>
#include <sstream>
#include <vector>

#include "core/input_error.h"
#include "core/input_file.h"
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

namespace {

// The types the page relies on, by path ("*": every element of a list): a saved report that
// was edited or made by another program is refused naming the first field of another type,
// rather than failing deep inside the page. Fields not listed pass through as they are.
enum class Kind { Number, NumberOrNull, String, Bool, Object, List, Span };

struct FieldRule {
  const char* path;
  Kind kind;
};

constexpr FieldRule kFieldRules[] = {
    {"strategy", Kind::String},
    {"driver", Kind::String},
    {"width", Kind::Number},
    {"height", Kind::Number},
    {"elapsed_s", Kind::Number},
    {"serial_s", Kind::NumberOrNull},
    {"samples_per_pixel", Kind::Number},
    {"drt", Kind::Number},
    {"master_speed_index_s", Kind::NumberOrNull},
    {"context", Kind::Object},
    {"context.scene", Kind::String},
    {"context.date", Kind::String},
    {"context.outputs", Kind::Object},
    {"context.outputs.*", Kind::String},
    {"context.parameters", Kind::Object},
    {"workers", Kind::List},
    {"workers.*", Kind::Object},
    {"workers.*.worker", Kind::Number},
    {"workers.*.lost", Kind::Bool},
    {"workers.*.pixels", Kind::NumberOrNull},
    {"workers.*.tasks", Kind::NumberOrNull},
    {"workers.*.busy_s", Kind::NumberOrNull},
    {"workers.*.idle_s", Kind::NumberOrNull},
    {"workers.*.speed_index_s", Kind::NumberOrNull},
    {"workers.*.slowdown", Kind::NumberOrNull},
    {"workers.*.messages", Kind::NumberOrNull},
    {"workers.*.bytes_sent", Kind::NumberOrNull},
    {"workers.*.bytes_received", Kind::NumberOrNull},
    {"joined_workers", Kind::List},
    {"joined_workers.*", Kind::Object},
    {"joined_workers.*.worker", Kind::Number},
    {"joined_workers.*.at_s", Kind::Number},
    {"frames", Kind::List},
    {"timeline", Kind::Object},
    {"timeline.ticks", Kind::Number},
    {"timeline.tick_s", Kind::Number},
    {"timeline.aggregated", Kind::Bool},
    {"timeline.workers_per_row", Kind::Number},
    {"timeline.rendering_share", Kind::List},
    {"timeline.rendering_share.*", Kind::Number},
    {"timeline.master_marks", Kind::List},
    {"timeline.master_marks.*", Kind::Object},
    {"timeline.master_marks.*.t_s", Kind::Number},
    {"timeline.master_marks.*.label", Kind::String},
    {"timeline.rows", Kind::List},
    {"timeline.rows.*", Kind::Object},
    {"timeline.rows.*.first", Kind::Number},
    {"timeline.rows.*.last", Kind::Number},
    {"timeline.rows.*.finished_s", Kind::Number},
    {"timeline.rows.*.setup", Kind::List},
    {"timeline.rows.*.setup.*", Kind::Span},
    {"timeline.rows.*.rendering", Kind::List},
    {"timeline.rows.*.rendering.*", Kind::Span},
    {"timeline.rows.*.messages", Kind::List},
    {"timeline.rows.*.messages.*", Kind::Number},
    {"timeline.rows.*.setup_share", Kind::List},
    {"timeline.rows.*.setup_share.*", Kind::Number},
    {"timeline.rows.*.rendering_share", Kind::List},
    {"timeline.rows.*.rendering_share.*", Kind::Number},
    {"timeline.rows.*.marks", Kind::List},
    {"timeline.rows.*.marks.*", Kind::Object},
    {"timeline.rows.*.marks.*.t_s", Kind::Number},
    {"timeline.rows.*.marks.*.kind", Kind::String},
    {"timeline.rows.*.marks.*.label", Kind::String},
    {"timeline.rows.*.marks.*.worker", Kind::Number},
    {"ownership_map", Kind::Object},
    {"ownership_map.encoding", Kind::String},
    {"ownership_map.data", Kind::String},
    {"ownership_map.width", Kind::Number},
    {"ownership_map.height", Kind::Number},
    {"ownership_map.step", Kind::Number},
    {"ownership_map.source_width", Kind::Number},
    {"ownership_map.source_height", Kind::Number},
};

const char* kindName(Kind kind) {
  switch (kind) {
    case Kind::Number:
      return "a number";
    case Kind::NumberOrNull:
      return "a number or null";
    case Kind::String:
      return "a string";
    case Kind::Bool:
      return "true or false";
    case Kind::Object:
      return "an object";
    case Kind::List:
      return "a list";
    case Kind::Span:
      return "a pair of numbers";
  }
  return "";
}

bool hasKind(const json& v, Kind kind) {
  switch (kind) {
    case Kind::Number:
      return v.is_number();
    case Kind::NumberOrNull:
      return v.is_number() || v.is_null();
    case Kind::String:
      return v.is_string();
    case Kind::Bool:
      return v.is_boolean();
    case Kind::Object:
      return v.is_object();
    case Kind::List:
      return v.is_array();
    case Kind::Span:
      return v.is_array() && v.size() == 2 && v[0].is_number() && v[1].is_number();
  }
  return false;
}

// Checks `rule` below `v`, `segments` from `at` on; `where` is the path so far, for messages.
void checkRule(const json& v, const std::vector<std::string>& segments, size_t at,
               const std::string& where, Kind kind, const std::string& path) {
  if (at == segments.size()) {
    if (!hasKind(v, kind)) {
      std::string found = v.type_name();
      throw InputError("'" + path + "': the field \"" + where + "\" must be " + kindName(kind) +
                       ", not " + (found == "array" ? "a list" : "a " + found) +
                       "; is it a report prt wrote?");
    }
    return;
  }
  const std::string& segment = segments[at];
  const std::string prefix = where.empty() ? "" : where + ".";
  if (segment == "*") {
    if (v.is_array()) {
      for (size_t i = 0; i < v.size(); ++i) {
        checkRule(v[i], segments, at + 1, where + "[" + std::to_string(i) + "]", kind, path);
      }
    } else if (v.is_object()) {
      for (const auto& [key, value] : v.items()) {
        checkRule(value, segments, at + 1, prefix + key, kind, path);
      }
    }
    return;
  }
  if (v.is_object() && v.contains(segment)) {
    checkRule(v[segment], segments, at + 1, prefix + segment, kind, path);
  }
}

void checkFieldTypes(const json& doc, const std::string& path) {
  for (const FieldRule& rule : kFieldRules) {
    std::vector<std::string> segments;
    std::string text = rule.path;
    for (size_t start = 0;;) {
      const size_t dot = text.find('.', start);
      segments.push_back(text.substr(start, dot - start));
      if (dot == std::string::npos) break;
      start = dot + 1;
    }
    checkRule(doc, segments, 0, "", rule.kind, path);
  }
}

}  // namespace

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
  checkFieldTypes(doc, path);
  return doc;
}

json readReportDocument(const std::string& path) {
  return parseReportDocument(readInputFile(path, "report"), path);
}

}  // namespace prt
