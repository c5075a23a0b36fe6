#include "image/srgb.h"

#include <array>
#include <cmath>

namespace prt {

double srgbEncode(double linear) {
  if (linear <= 0.0031308) return 12.92 * linear;
  return 1.055 * std::pow(linear, 1.0 / 2.4) - 0.055;
}

double srgbDecode(double encoded) {
  if (encoded <= 0.04045) return encoded / 12.92;
  return std::pow((encoded + 0.055) / 1.055, 2.4);
}

uint8_t linearToSrgb8(double linear) {
  if (!(linear > 0.0)) return 0;  // also catches NaN
  if (linear >= 1.0) return 255;
  return static_cast<uint8_t>(std::lround(srgbEncode(linear) * 255.0));
}

double srgb8ToLinear(uint8_t code) {
  // Decoding is on the path of every PNG/PPM pixel read; 256 pow() calls once beat
  // three per pixel. Function-local static: initialised once, thread-safely.
  static const std::array<double, 256> table = [] {
    std::array<double, 256> t{};
    for (int c = 0; c < 256; ++c) t[static_cast<size_t>(c)] = srgbDecode(c / 255.0);
    return t;
  }();
  return table[code];
}

}  // namespace prt
