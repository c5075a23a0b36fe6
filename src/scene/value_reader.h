#pragma once
// Reading a parameter's value: numbers (checked against the range the parameter allows),
// whole numbers, 3-vectors, colours and quoted strings. Every problem is an InputError at the
// offending token saying what was found and what is allowed.

#include <limits>
#include <string>
#include <string_view>

#include "core/vec3.h"
#include "scene/token_stream.h"

namespace prt {

// An interval of allowed values; either end may be open (excluded) or unbounded.
struct Range {
  double min = -std::numeric_limits<double>::infinity();
  double max = std::numeric_limits<double>::infinity();
  bool minOpen = false;
  bool maxOpen = false;

  static Range any() { return {}; }
  static Range atLeast(double lo) { return {lo, Range{}.max, false, false}; }
  static Range above(double lo) { return {lo, Range{}.max, true, false}; }
  static Range closed(double lo, double hi) { return {lo, hi, false, false}; }
  static Range open(double lo, double hi) { return {lo, hi, true, true}; }
  static Range closedOpen(double lo, double hi) { return {lo, hi, false, true}; }

  bool contains(double value) const;
  // "in [0, 1]", "> 0", ">= 1", "in (0, 180)"; empty for any().
  std::string describe() const;
};

// Positions and sizes beyond this are surely mistakes, and squaring them must not overflow.
inline constexpr double kMaxCoordinate = 1e9;
inline const Range kCoordinate = Range::closed(-kMaxCoordinate, kMaxCoordinate);

// Each reader consumes the value tokens after the parameter name `param`.
double readNumber(TokenStream& in, std::string_view param, Range range);
int readInteger(TokenStream& in, std::string_view param, int min, int max);
Vec3 readVector(TokenStream& in, std::string_view param, Range componentRange = Range::any());
// The largest component of any colour (a surface's, a light's intensity, the background, the
// ambient light). Far beyond any real scene, and low enough that no sum or product of colours
// a render forms can overflow a float: an image never holds an infinity.
inline constexpr double kMaxColorComponent = 1e6;
Color readColor(TokenStream& in, std::string_view param);  // components in [0, 1e6]
std::string readString(TokenStream& in, std::string_view param);

}  // namespace prt
