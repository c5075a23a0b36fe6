#include "report/html_text.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "report/page_assets.h"

namespace prt {

std::string escapeHtml(std::string_view text) {
  std::string out;
  out.reserve(text.size());
  for (char c : text) {
    switch (c) {
      case '&':
        out += "&amp;";
        break;
      case '<':
        out += "&lt;";
        break;
      case '>':
        out += "&gt;";
        break;
      case '"':
        out += "&quot;";
        break;
      case '\'':
        out += "&#39;";
        break;
      default:
        out += c;
    }
  }
  return out;
}

std::string base64(std::string_view bytes) {
  static constexpr char kDigits[] =
      "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
  std::string out;
  out.reserve((bytes.size() + 2) / 3 * 4);
  size_t i = 0;
  for (; i + 2 < bytes.size(); i += 3) {
    const uint32_t v = static_cast<uint32_t>(static_cast<unsigned char>(bytes[i])) << 16 |
                       static_cast<uint32_t>(static_cast<unsigned char>(bytes[i + 1])) << 8 |
                       static_cast<unsigned char>(bytes[i + 2]);
    out += kDigits[v >> 18];
    out += kDigits[(v >> 12) & 63];
    out += kDigits[(v >> 6) & 63];
    out += kDigits[v & 63];
  }
  if (i < bytes.size()) {
    uint32_t v = static_cast<uint32_t>(static_cast<unsigned char>(bytes[i])) << 16;
    if (i + 1 < bytes.size())
      v |= static_cast<uint32_t>(static_cast<unsigned char>(bytes[i + 1])) << 8;
    out += kDigits[v >> 18];
    out += kDigits[(v >> 12) & 63];
    out += i + 1 < bytes.size() ? kDigits[(v >> 6) & 63] : '=';
    out += '=';
  }
  return out;
}

std::string pngDataUri(std::string_view pngBytes) {
  return "data:image/png;base64," + base64(pngBytes);
}

std::string shortText(const std::string& text, size_t max) {
  if (text.size() <= max) return text;
  size_t cut = max;
  while (cut > 0 && (static_cast<unsigned char>(text[cut]) & 0xC0) == 0x80) --cut;  // UTF-8
  std::string out(text, 0, cut);
  out.append("\u2026");
  return out;
}

std::string attributeJson(const nlohmann::json& value, size_t max) {
  const std::string text = value.dump(-1, ' ', false, nlohmann::json::error_handler_t::replace);
  if (text.size() <= max) return text;
  std::string note = "\"(";
  note.append(formatBytes(text.size()));
  note.append(", left out)\"");
  return note;
}

nlohmann::json embeddableReport(const nlohmann::json& report, size_t maxBytes,
                                std::vector<std::string>& leftOut) {
  constexpr auto kReplace = nlohmann::json::error_handler_t::replace;
  size_t total = report.dump(-1, ' ', false, kReplace).size();
  if (total <= maxBytes || !report.is_object()) return report;
  std::vector<std::pair<size_t, std::string>> sizes;
  for (const auto& [key, value] : report.items()) {
    sizes.emplace_back(value.dump(-1, ' ', false, kReplace).size(), key);
  }
  std::sort(sizes.rbegin(), sizes.rend());
  nlohmann::json kept = report;
  for (const auto& [size, key] : sizes) {
    if (total <= maxBytes) break;
    nlohmann::json note = nlohmann::json::object();
    note["left_out_bytes"] = size;
    kept[key] = std::move(note);
    total -= size;
    leftOut.push_back(key);
  }
  return kept;
}

std::string jsonForScript(const nlohmann::json& value) {
  const std::string text = value.dump(-1, ' ', false, nlohmann::json::error_handler_t::replace);
  std::string out;
  out.reserve(text.size());
  for (char c : text) {
    if (c == '<') {
      out += "\\u003c";
    } else {
      out += c;
    }
  }
  return out;
}

std::string formatCount(uint64_t n) {
  std::string digits = std::to_string(n);
  std::string out;
  for (size_t i = 0; i < digits.size(); ++i) {
    if (i > 0 && (digits.size() - i) % 3 == 0) out += ',';
    out += digits[i];
  }
  return out;
}

std::string formatNumber(double value, int significant) {
  if (!std::isfinite(value)) return "n/a";
  char buffer[64];
  const double magnitude = std::fabs(value);
  if (magnitude >= 1e6 || (magnitude > 0 && magnitude < 1e-3)) {
    std::snprintf(buffer, sizeof buffer, "%.*g", significant, value);
    return buffer;
  }
  // Fixed notation with `significant` digits, at most six decimals, trailing zeros kept.
  const int exponent = magnitude > 0 ? static_cast<int>(std::floor(std::log10(magnitude))) : 0;
  const int decimals = std::clamp(significant - 1 - exponent, 0, 6);
  std::snprintf(buffer, sizeof buffer, "%.*f", decimals, value);
  return buffer;
}

std::string formatSeconds(double seconds) {
  if (!std::isfinite(seconds)) return "n/a";
  const double magnitude = std::fabs(seconds);
  if (magnitude >= 1 || magnitude == 0) return formatNumber(seconds) + " s";
  if (magnitude >= 1e-3) return formatNumber(seconds * 1e3) + " ms";
  return formatNumber(seconds * 1e6) + " µs";
}

std::string formatPercent(double fraction) {
  if (!std::isfinite(fraction)) return "n/a";
  char buffer[32];
  std::snprintf(buffer, sizeof buffer, "%.1f %%", 100 * fraction);
  return buffer;
}

std::string formatBytes(uint64_t bytes) {
  const double b = static_cast<double>(bytes);
  if (bytes < 1000) return std::to_string(bytes) + " B";
  if (b < 1e6) return formatNumber(b / 1e3) + " kB";
  if (b < 1e9) return formatNumber(b / 1e6) + " MB";
  return formatNumber(b / 1e9) + " GB";
}

std::string htmlDocument(const std::string& title, const std::string& body,
                         const std::string& extraHead) {
  return "<!DOCTYPE html>\n<html lang=\"en\">\n<head>\n<meta charset=\"utf-8\">\n"
         "<meta name=\"viewport\" content=\"width=device-width, initial-scale=1\">\n"
         "<title>" +
         escapeHtml(title) + "</title>\n<style>\n" + std::string(kPageStyle) + "</style>\n" +
         extraHead + "</head>\n<body>\n" + body + "</body>\n</html>\n";
}

}  // namespace prt
