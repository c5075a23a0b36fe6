#pragma once
// A number as a user would write it in a message ("1e+300", "-1", "0.5"), not
// std::to_string's 300 digits: six significant digits.

#include <cstdio>
#include <string>

namespace prt {

inline std::string formatNumber(double value) {
  char text[32];
  std::snprintf(text, sizeof text, "%.6g", value);
  return text;
}

}  // namespace prt
