#include "image/image_compare.h"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <limits>
#include <string>

#include "core/input_error.h"
#include "image/srgb.h"

namespace prt {
namespace {

void requireSameSize(const Image& a, const Image& b) {
  if (a.width() != b.width() || a.height() != b.height()) {
    throw InputError("cannot compare images of different sizes: " + std::to_string(a.width()) +
                     "x" + std::to_string(a.height()) + " and " + std::to_string(b.width()) + "x" +
                     std::to_string(b.height()));
  }
}

int codeDifference(float a, float b) {
  return std::abs(int{linearToSrgb8(a)} - int{linearToSrgb8(b)});
}

}  // namespace

double psnr(const Image& a, const Image& b) {
  requireSameSize(a, b);
  const std::span<const float> sa = a.data();
  const std::span<const float> sb = b.data();
  // Integer sum: exact, and cannot overflow (< 2^16 per sample, < 2^30 samples).
  uint64_t sumSquares = 0;
  for (size_t i = 0; i < sa.size(); ++i) {
    const auto d = static_cast<uint64_t>(codeDifference(sa[i], sb[i]));
    sumSquares += d * d;
  }
  if (sumSquares == 0) return std::numeric_limits<double>::infinity();
  const double mse = static_cast<double>(sumSquares) / static_cast<double>(sa.size());
  return 10.0 * std::log10(255.0 * 255.0 / mse);
}

double differingPixelFraction(const Image& a, const Image& b, int tolerance) {
  requireSameSize(a, b);
  const std::span<const float> sa = a.data();
  const std::span<const float> sb = b.data();
  size_t differing = 0;
  for (size_t i = 0; i < sa.size(); i += 3) {
    const int worst = std::max({codeDifference(sa[i], sb[i]), codeDifference(sa[i + 1], sb[i + 1]),
                                codeDifference(sa[i + 2], sb[i + 2])});
    if (worst > tolerance) ++differing;
  }
  return static_cast<double>(differing) / static_cast<double>(a.pixelCount());
}

Image differenceImage(const Image& a, const Image& b, double scale) {
  requireSameSize(a, b);
  Image diff(a.width(), a.height());
  const std::span<const float> sa = a.data();
  const std::span<const float> sb = b.data();
  const std::span<float> out = diff.data();
  for (size_t i = 0; i < sa.size(); ++i) {
    // Stored decoded, so that writing the image sRGB-encodes it back to the scaled difference.
    const double shown = std::min(1.0, scale * codeDifference(sa[i], sb[i]) / 255.0);
    out[i] = static_cast<float>(srgbDecode(shown));
  }
  return diff;
}

Image sideBySide(const Image& a, const Image& b, double diffScale) {
  const Image diff = differenceImage(a, b, diffScale);  // also checks the sizes
  const int w = a.width();
  PRT_CHECK(w <= std::numeric_limits<int>::max() / 3);
  Image out(3 * w, a.height());
  const Image* parts[] = {&a, &b, &diff};
  for (int y = 0; y < a.height(); ++y) {
    for (int part = 0; part < 3; ++part) {
      for (int x = 0; x < w; ++x) out.set(part * w + x, y, parts[part]->at(x, y));
    }
  }
  return out;
}

}  // namespace prt
