#pragma once
// A box blur, for comparing renderings of distributed effects (soft shadows, gloss) whose
// noise differs by design between two renderers: averaging over a small window compares the
// expected images rather than the noise.
// Pure and thread-safe.

#include "image/image.h"

namespace prt {

// Each pixel becomes the mean of the linear colours in the (2 radius + 1)^2 window around it,
// clipped at the image border (border pixels average fewer neighbours). radius 0 returns a
// copy. radius must be >= 0.
Image boxBlur(const Image& image, int radius);

}  // namespace prt
