#include "image/image.h"

#include <cstring>

namespace prt {

Image::Image(int width, int height) : width_(width), height_(height) {
  PRT_CHECK(width > 0 && height > 0);
  data_.assign(3 * pixelCount(), 0.0f);
}

bool Image::operator==(const Image& other) const {
  // memcmp rather than float ==, so the comparison sees bits, not values.
  return width_ == other.width_ && height_ == other.height_ &&
         std::memcmp(data_.data(), other.data_.data(), data_.size() * sizeof(float)) == 0;
}

}  // namespace prt
