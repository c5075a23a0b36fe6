#pragma once
// Numbers as text, both ways. Writing uses the shortest form that reads back to the very same
// double, so a scene written by writeScene() and parsed again is bit-identical: the master
// sends scenes to workers as text and every process must render the same picture.

#include <cstdint>
#include <string>
#include <string_view>

namespace prt {

enum class NumberStatus {
  Ok,
  Malformed,   // not a decimal number at all ("1.2.3", "0x10", "1e")
  OutOfRange,  // too large (or too tiny) for the type
  NotFinite,   // NaN or an infinity
};

template <typename T>
struct ParsedNumber {
  T value{};
  NumberStatus status = NumberStatus::Malformed;
};

// Decimal floating point: optional sign, digits with an optional '.', optional exponent.
ParsedNumber<double> parseDouble(std::string_view text);

// Decimal integer: optional sign and digits only ("3.0" and "3e2" are Malformed).
ParsedNumber<int64_t> parseInteger(std::string_view text);

// Shortest round-trip text of `value` ("0.1", "1e-300", "0.3333333333333333").
std::string formatDouble(double value);

}  // namespace prt
