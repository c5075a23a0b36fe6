#pragma once
// Text for self-contained HTML pages: escaping, base64 for data: URIs, JSON that is safe
// inside a <script> element, and numbers formatted for people. Pure functions; thread-safe.

#include <cstdint>
#include <nlohmann/json.hpp>
#include <string>
#include <string_view>
#include <vector>

namespace prt {

// &, <, >, " and ' as entities: safe in element content and in quoted attributes.
std::string escapeHtml(std::string_view text);

// RFC 4648 base64 with padding.
std::string base64(std::string_view bytes);
std::string pngDataUri(std::string_view pngBytes);  // "data:image/png;base64,..."

// `value` as compact JSON for a <script type="application/json"> element: every '<' is
// written as \u003c (it only occurs inside strings), so no "</script>" can end the element;
// invalid UTF-8 in strings is replaced rather than thrown on.
std::string jsonForScript(const nlohmann::json& value);

// A page's size is bounded whatever a report holds (a saved report may be edited, or huge):
// text shown is cut at `max` bytes with "…"; a value in a data- attribute is its JSON, or a
// JSON string saying how large it was when that is over `max`; the report embedded in a page
// keeps every top-level value while the whole fits `maxBytes`, the largest ones left out first
// (each replaced by {"left_out_bytes": N}), their keys added to `leftOut`.
std::string shortText(const std::string& text, size_t max = 200);
std::string attributeJson(const nlohmann::json& value, size_t max = 4096);
nlohmann::json embeddableReport(const nlohmann::json& report, size_t maxBytes,
                                std::vector<std::string>& leftOut);
inline constexpr size_t kMaxEmbeddedReportBytes = size_t{16} << 20;

// People's numbers: "1,234,567"; "12.3 s", "456 ms", "78 µs"; "93.4 %"; "1.2 MB"; "3.05".
std::string formatCount(uint64_t n);
std::string formatSeconds(double seconds);
std::string formatPercent(double fraction);  // 0.934 -> "93.4 %"
std::string formatBytes(uint64_t bytes);
std::string formatNumber(double value, int significant = 3);

// The page shell shared by the run page and the experiments' index: doctype, <head> with the
// title and the inline style sheet, <body> around `body`.
std::string htmlDocument(const std::string& title, const std::string& body,
                         const std::string& extraHead = "");

}  // namespace prt
