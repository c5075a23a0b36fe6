#include "export/box_blur.h"

#include <algorithm>
#include <vector>

namespace prt {
namespace {

// One pass along rows (horizontal) or columns, in doubles so the running sums stay exact
// enough; the window is clipped to the image.
Image blurPass(const Image& in, int radius, bool horizontal) {
  const int w = in.width(), h = in.height();
  const int length = horizontal ? w : h;
  const int lines = horizontal ? h : w;
  Image out(w, h);
  std::vector<Color> prefix(static_cast<size_t>(length) + 1);
  for (int l = 0; l < lines; ++l) {
    auto at = [&](int i) { return horizontal ? in.at(i, l) : in.at(l, i); };
    for (int i = 0; i < length; ++i) prefix[static_cast<size_t>(i) + 1] = prefix[i] + at(i);
    for (int i = 0; i < length; ++i) {
      const int lo = std::max(0, i - radius), hi = std::min(length - 1, i + radius);
      const Color mean = (prefix[static_cast<size_t>(hi) + 1] - prefix[lo]) / (hi - lo + 1);
      if (horizontal) {
        out.set(i, l, mean);
      } else {
        out.set(l, i, mean);
      }
    }
  }
  return out;
}

}  // namespace

Image boxBlur(const Image& image, int radius) {
  PRT_CHECK(radius >= 0);
  if (radius == 0) return image;
  return blurPass(blurPass(image, radius, true), radius, false);
}

}  // namespace prt
