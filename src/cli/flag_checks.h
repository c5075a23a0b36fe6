#pragma once
// Checks of flag values that CLI11's own validators word badly: a positive number whose
// message would print the largest double in 300 digits, and file names given as "".

#include <CLI/CLI.hpp>
#include <cmath>
#include <cstdlib>
#include <string>

namespace prt::cli {

// A finite number in (0, max], for times and factors; the message names the range plainly.
inline CLI::Validator positiveUpTo(double max, const std::string& unit) {
  return CLI::Validator(
      [max, unit](std::string& text) -> std::string {
        char* end = nullptr;
        const double value = std::strtod(text.c_str(), &end);
        const bool whole = !text.empty() && end != nullptr && *end == '\0';
        if (whole && std::isfinite(value) && value > 0 && value <= max) return {};
        return "must be a positive number of " + unit + ", at most " + CLI::detail::to_string(max) +
               "; found '" + text + "'";
      },
      "(0, " + CLI::detail::to_string(max) + "]");
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
