#pragma once
// Image: a width x height grid of linear RGB pixels, stored as 32-bit floats, three per
// pixel, row-major, row 0 at the top. Floats halve the memory of doubles and are the
// precision of the PFM files we write; colours enter and leave as prt::Color (doubles).
//
// Plain value type: copyable, movable, bit-exact equality. Not internally synchronised;
// different threads may set *different* pixels concurrently (no shared state besides the
// pixel buffer), but reads and writes of the same pixel must be ordered by the caller.

#include <cstddef>
#include <span>
#include <vector>

#include "core/check.h"
#include "core/vec3.h"

namespace prt {

class Image {
 public:
  // All pixels black. Both sizes must be > 0 (PRT_CHECK): an empty image is a bug upstream.
  Image(int width, int height);

  int width() const { return width_; }
  int height() const { return height_; }
  size_t pixelCount() const { return static_cast<size_t>(width_) * static_cast<size_t>(height_); }

  // pixelIndex = y * width + x, the order tiles and files use.
  size_t pixelIndex(int x, int y) const {
    PRT_CHECK(x >= 0 && x < width_ && y >= 0 && y < height_);
    return static_cast<size_t>(y) * static_cast<size_t>(width_) + static_cast<size_t>(x);
  }

  Color at(int x, int y) const { return at(pixelIndex(x, y)); }
  Color at(size_t pixelIndex) const {
    PRT_CHECK(pixelIndex < pixelCount());
    const float* p = &data_[3 * pixelIndex];
    return {p[0], p[1], p[2]};
  }

  // Stores c rounded to float precision (round to nearest).
  void set(int x, int y, const Color& c) { set(pixelIndex(x, y), c); }
  void set(size_t pixelIndex, const Color& c) {
    PRT_CHECK(pixelIndex < pixelCount());
    float* p = &data_[3 * pixelIndex];
    p[0] = static_cast<float>(c.x);
    p[1] = static_cast<float>(c.y);
    p[2] = static_cast<float>(c.z);
  }

  // The raw samples: 3 * pixelCount() floats, R G B per pixel, rows top to bottom.
  std::span<float> data() { return data_; }
  std::span<const float> data() const { return data_; }

  // Bit-exact: same size and identical float bit patterns (so NaN == NaN and 0 != -0).
  bool operator==(const Image& other) const;

 private:
  int width_;
  int height_;
  std::vector<float> data_;
};

}  // namespace prt
