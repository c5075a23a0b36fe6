#pragma once
// Comparing two renderings of the same image, e.g. ours against another renderer's.
// Differences are measured on 8-bit sRGB codes (linearToSrgb8), the values a viewer of the
// PNG sees, so small differences in dark regions count as much as they are visible and
// differences above white or below black, which no one can see, do not count at all.
//
// All functions are pure and thread-safe. The two images must have the same size; a
// mismatch is reported as InputError (the images usually come from user-supplied files).

#include "image/image.h"

namespace prt {

// Peak signal-to-noise ratio in dB over all R, G, B samples:
// 10 log10(255^2 / MSE) with MSE the mean squared difference of the 8-bit codes.
// +infinity when the 8-bit encodings are identical.
double psnr(const Image& a, const Image& b);

// Share of pixels, in [0, 1], for which some channel's 8-bit codes differ by more than
// `tolerance` (so tolerance 0 counts every pixel whose encoding differs at all).
double differingPixelFraction(const Image& a, const Image& b, int tolerance);

// Per-channel |code(a) - code(b)| * scale, as an image whose PNG/PPM encoding shows that
// value (clamped to 255): black where the images agree, scale 10 makes a difference of
// 1 code show as 10. Its linear values are chosen for that encoding, not for arithmetic.
Image differenceImage(const Image& a, const Image& b, double scale = 1.0);

// a | b | differenceImage(a, b, diffScale), side by side, three times as wide as a.
Image sideBySide(const Image& a, const Image& b, double diffScale = 1.0);

}  // namespace prt
