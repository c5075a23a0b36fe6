#pragma once
// Reading a saved report's JSON for the page, forgivingly: a key that is missing or of
// another type gives the fallback, so a report from an older or newer prt still draws.
// Internal to the report library. Pure; thread-safe.

#include <algorithm>
#include <cmath>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>

#include "report/html_text.h"

namespace prt::page {

using nlohmann::json;

inline std::optional<double> number(const json& j, const char* key) {
  if (!j.is_object() || !j.contains(key) || !j[key].is_number()) return std::nullopt;
  return j[key].get<double>();
}
inline double numberOr(const json& j, const char* key, double fallback) {
  return number(j, key).value_or(fallback);
}
inline std::string text(const json& j, const char* key) {
  return j.is_object() && j.contains(key) && j[key].is_string() ? j[key].get<std::string>() : "";
}
inline uint64_t count(const json& j, const char* key) {
  const auto v = number(j, key);
  return v && *v > 0 ? static_cast<uint64_t>(std::llround(*v)) : 0;
}
inline std::string humanKey(std::string key) {
  std::replace(key.begin(), key.end(), '_', ' ');
  return key;
}
// Counts of faults shown (a card, a workers' column) only when they are not zero: zero in
// nearly every run, where a card or a column of them says nothing.
inline bool hiddenWhileZero(const std::string& key, const json& value) {
  return key == "non_finite_samples" && !(value.is_number() && value.get<double>() > 0);
}
// A JSON value of a key nobody told the page about, readably.
inline std::string genericValue(const json& v) {
  if (v.is_null()) return "\u2014";  // not there (a worker that did not join: no join time)
  if (v.is_array()) return std::to_string(v.size()) + (v.empty() ? "" : ": " + shortText(v.dump()));
  if (v.is_string()) return shortText(v.get<std::string>());
  if (v.is_number_float()) return formatNumber(v.get<double>(), 4);
  return v.dump();
}

inline std::string chip(const std::string& colour) {
  return "<span class=\"chip\" style=\"background:" + colour + "\"></span>";
}

}  // namespace prt::page
