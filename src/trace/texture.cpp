#include "trace/texture.h"

#include <cmath>

#include "core/portable_math.h"

namespace prt {
namespace {

struct SrgbTable {
  double linear[256];
  SrgbTable() {
    for (int i = 0; i < 256; ++i) {
      const double c = i / 255.0;
      linear[i] = c <= 0.04045 ? c / 12.92 : powNonNegative((c + 0.055) / 1.055, 2.4);
    }
  }
};
const SrgbTable& srgbTable() {
  static const SrgbTable table;
  return table;
}

struct LinearTable {
  double value[256];
  LinearTable() {
    for (int i = 0; i < 256; ++i) value[i] = i / 255.0;
  }
};
const LinearTable& linearTable() {
  static const LinearTable table;
  return table;
}

// A coordinate into [0, 1] (clamp), [0, 1) (repeat) or [0, 1] mirrored every other unit.
double wrapped(double t, TextureWrap wrap) {
  if (!std::isfinite(t)) return 0;
  switch (wrap) {
    case TextureWrap::clamp:
      return t < 0 ? 0 : (t > 1 ? 1 : t);
    case TextureWrap::mirror: {
      const double period = t - 2.0 * std::floor(0.5 * t);  // in [0, 2)
      return period > 1 ? 2 - period : period;
    }
    case TextureWrap::repeat:
    default: {
      const double f = t - std::floor(t);
      return f < 1 ? f : 0;  // t just below an integer can round up to 1
    }
  }
}

// Texel index i in [-1, size] brought into [0, size): repeating images wrap around, the others
// hold their edge.
int texelIndex(int i, int size, TextureWrap wrap) {
  if (wrap == TextureWrap::repeat) return i < 0 ? i + size : (i >= size ? i - size : i);
  return i < 0 ? 0 : (i >= size ? size - 1 : i);
}

Color texel(const TextureImage& image, int x, int y, bool data) {
  const double* linear = data ? linearTable().value : srgbTable().linear;
  const uint8_t* p = image.texels.data() +
                     (static_cast<size_t>(y) * static_cast<size_t>(image.width) +
                      static_cast<size_t>(x)) *
                         static_cast<size_t>(image.channels);
  if (image.channels >= 3) return {linear[p[0]], linear[p[1]], linear[p[2]]};
  return Color(linear[p[0]]);
}

}  // namespace

double srgbToLinear(uint8_t value) { return srgbTable().linear[value]; }

double linearFromByte(uint8_t value) { return linearTable().value[value]; }

Color sampleTexture(const Texture& texture, double u, double v) {
  const TextureImage& image = *texture.image;
  const double x = wrapped(u, texture.wrapU) * image.width;
  const double y = wrapped(v, texture.wrapV) * image.height;
  if (texture.nearest) {
    const int ix = std::min(static_cast<int>(x), image.width - 1);
    const int iy = std::min(static_cast<int>(y), image.height - 1);
    return texel(image, ix, iy, texture.linear);
  }
  // Between the centres of the four nearest texels; x - 0.5 lies in [-0.5, width - 0.5].
  const double fx = x - 0.5, fy = y - 0.5;
  const double x0 = std::floor(fx), y0 = std::floor(fy);
  const double ax = fx - x0, ay = fy - y0;
  const int ix = static_cast<int>(x0), iy = static_cast<int>(y0);
  const int xa = texelIndex(ix, image.width, texture.wrapU);
  const int xb = texelIndex(ix + 1, image.width, texture.wrapU);
  const int ya = texelIndex(iy, image.height, texture.wrapV);
  const int yb = texelIndex(iy + 1, image.height, texture.wrapV);
  const bool data = texture.linear;
  const Color a = texel(image, xa, ya, data), b = texel(image, xb, ya, data);
  const Color c = texel(image, xa, yb, data), d = texel(image, xb, yb, data);
  if (data) {  // exact where the texels agree
    const Color top = a + ax * (b - a), bottom = c + ax * (d - c);
    return top + ay * (bottom - top);
  }
  const Color top = (1 - ax) * a + ax * b;
  const Color bottom = (1 - ax) * c + ax * d;
  return (1 - ay) * top + ay * bottom;
}

}  // namespace prt
