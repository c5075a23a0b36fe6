#pragma once
// Checks of flag values that CLI11's own validators word badly: a positive number whose
// message would print the largest double in 300 digits, and file names given as "".

#include <CLI/CLI.hpp>
#include <cmath>
#include <cstdlib>
#include <string>

namespace prt::cli {

namespace detail {

// The number `text` holds, if it holds one and nothing else.
inline bool parseNumber(const std::string& text, double& value) {
  char* end = nullptr;
  value = std::strtod(text.c_str(), &end);
  return !text.empty() && end != nullptr && *end == '\0';
}

}  // namespace detail

// A finite number in (0, max], for times and factors; the message names the range plainly.
inline CLI::Validator positiveUpTo(double max, const std::string& unit) {
  return CLI::Validator(
      [max, unit](std::string& text) -> std::string {
        double value = 0;
        if (detail::parseNumber(text, value) && std::isfinite(value) && value > 0 &&
            value <= max) {
          return {};
        }
        return "must be a positive number of " + unit + ", at most " + CLI::detail::to_string(max) +
               "; found '" + text + "'";
      },
      "(0, " + CLI::detail::to_string(max) + "]");
}

// A finite number in [min, max]: CLI::Range lets NaN through (every comparison with it fails).
inline CLI::Validator finiteIn(double min, double max) {
  const std::string range = "[" + CLI::detail::to_string(min) + ", " + CLI::detail::to_string(max) + "]";
  return CLI::Validator(
      [min, max, range](std::string& text) -> std::string {
        double value = 0;
        if (detail::parseNumber(text, value) && value >= min && value <= max) return {};
        return "must be a number in " + range + "; found '" + text + "'";
      },
      range);
}

// A file name: refuses "" (which would otherwise mean "not given" and be silently ignored).
inline CLI::Validator fileName() {
  return CLI::Validator(
      [](std::string& text) -> std::string {
        return text.empty() ? "needs a file name; found an empty string" : std::string();
      },
      "FILE");
}

}  // namespace prt::cli
