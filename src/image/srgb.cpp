#include "image/srgb.h"

#include <algorithm>
#include <array>
#include <bit>
#include <cmath>
#include <cstdint>

namespace prt {

double srgbEncode(double linear) {
  if (linear <= 0.0031308) return 12.92 * linear;
  return 1.055 * std::pow(linear, 1.0 / 2.4) - 0.055;
}

double srgbDecode(double encoded) {
  if (encoded <= 0.04045) return encoded / 12.92;
  return std::pow((encoded + 0.055) / 1.055, 2.4);
}

uint8_t linearToSrgb8ByCurve(double linear) {
  if (!(linear > 0.0)) return 0;  // also catches NaN
  if (linear >= 1.0) return 255;
  return static_cast<uint8_t>(std::lround(srgbEncode(linear) * 255.0));
}

namespace {

// linearToSrgb8 without a pow() per sample (three per pixel of every PNG and JPEG written):
// the least double of each code 1..255 by the curve, found once by bisection over the bits of
// the positive doubles (ordered as their bits are), and for each of kBuckets equal slices of
// [0, 1) the code at its start, from which a sample steps up past the few thresholds inside
// its slice. The code of a sample is then the number of thresholds at or below it: the
// curve's own code, the curve being monotonic (tested against it in srgb_test.cpp).
constexpr int kBuckets = 4096;

struct EncodeTable {
  std::array<double, 255> threshold{};  // threshold[c]: the least double of code c + 1
  std::array<uint8_t, kBuckets> start{};

  EncodeTable() {
    for (int c = 0; c < 255; ++c) {
      uint64_t below = std::bit_cast<uint64_t>(0.0), above = std::bit_cast<uint64_t>(1.0);
      while (above - below > 1) {  // code(below) <= c < code(above)
        const uint64_t middle = below + (above - below) / 2;
        (linearToSrgb8ByCurve(std::bit_cast<double>(middle)) > c ? above : below) = middle;
      }
      threshold[static_cast<size_t>(c)] = std::bit_cast<double>(above);
    }
    for (int i = 0; i < kBuckets; ++i) {
      const double from = static_cast<double>(i) / kBuckets;
      start[static_cast<size_t>(i)] = static_cast<uint8_t>(
          std::upper_bound(threshold.begin(), threshold.end(), from) - threshold.begin());
    }
  }
};

}  // namespace

uint8_t linearToSrgb8(double linear) {
  if (!(linear > 0.0)) return 0;  // also catches NaN
  if (linear >= 1.0) return 255;
  static const EncodeTable table;  // initialised once, thread-safely
  unsigned code = table.start[static_cast<size_t>(linear * kBuckets)];
  while (code < 255 && linear >= table.threshold[code]) ++code;
  return static_cast<uint8_t>(code);
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
