#include "scene/number_text.h"

#include <charconv>
#include <cmath>
#include <system_error>

namespace prt {
namespace {

// std::from_chars accepts '-' but not '+'; allow one '+' before the digits.
std::string_view stripPlus(std::string_view text) {
  if (text.size() > 1 && text[0] == '+' && text[1] != '-' && text[1] != '+') {
    text.remove_prefix(1);
  }
  return text;
}

template <typename T>
ParsedNumber<T> parseWith(std::string_view text, auto&&... format) {
  text = stripPlus(text);
  ParsedNumber<T> parsed;
  const char* const end = text.data() + text.size();
  const auto [ptr, ec] = std::from_chars(text.data(), end, parsed.value, format...);
  if (ptr != end || ec == std::errc::invalid_argument) {
    parsed.status = NumberStatus::Malformed;
  } else if (ec == std::errc::result_out_of_range) {
    parsed.status = NumberStatus::OutOfRange;
  } else {
    parsed.status = NumberStatus::Ok;
  }
  return parsed;
}

}  // namespace

ParsedNumber<double> parseDouble(std::string_view text) {
  ParsedNumber<double> parsed = parseWith<double>(text, std::chars_format::general);
  if (parsed.status == NumberStatus::Ok && !std::isfinite(parsed.value)) {
    parsed.status = NumberStatus::NotFinite;  // from_chars reads "inf" and "nan"
  }
  return parsed;
}

ParsedNumber<int64_t> parseInteger(std::string_view text) {
  return parseWith<int64_t>(text);
}

std::string formatDouble(double value) {
  char buffer[32];  // the longest shortest form of a double is 24 characters
  const auto [ptr, ec] = std::to_chars(buffer, buffer + sizeof buffer, value);
  (void)ec;  // cannot fail: the buffer is large enough for any double
  return std::string(buffer, ptr);
}

}  // namespace prt
