#pragma once
// The sRGB transfer curve (IEC 61966-2-1), exact piecewise form, used wherever linear
// radiance meets 8-bit files: PNG and PPM writing and reading, and image comparison, which
// measures differences in the 8-bit sRGB space people look at.
// All functions are pure and thread-safe.

#include <cstdint>

namespace prt {

// Linear [0, 1] -> sRGB-encoded [0, 1]. Values outside [0, 1] pass through the same formula
// (the caller clamps when it needs to).
double srgbEncode(double linear);

// sRGB-encoded [0, 1] -> linear [0, 1]; the inverse of srgbEncode on [0, 1].
double srgbDecode(double encoded);

// Linear -> 8-bit sRGB code: encode, clamp to [0, 1], round to nearest. NaN maps to 0 so a
// bad sample shows as black instead of being undefined behaviour in the conversion.
uint8_t linearToSrgb8(double linear);
// The same code computed from the curve (a pow per call): linearToSrgb8's definition, which it
// reaches through a table.
uint8_t linearToSrgb8ByCurve(double linear);

// 8-bit sRGB code -> linear (table lookup). For every code c,
// linearToSrgb8(srgb8ToLinear(c)) == c, also after rounding the result to float.
double srgb8ToLinear(uint8_t code);

}  // namespace prt
