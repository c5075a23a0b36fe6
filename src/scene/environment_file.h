#pragma once
// Environment maps: HDR images of the light around a scene (trace/environment_light.h), read
// from the two formats such maps come in — Radiance RGBE (.hdr, .pic; decoded with stb_image,
// which the textures already use) and OpenEXR (.exr; the image library's reader, as for
// -o x.exr). Linear RGB floats; an image's size is checked against the budget before it is
// decoded. Thread-safe.

#include <cstddef>
#include <memory>
#include <string>

#include "image/image.h"

namespace prt {

// Maps larger than this many bytes decoded (12 per texel) are refused unless a budget says
// otherwise: 1 GiB, the textures' default budget (a 16384 x 8192 map is 1.5 GiB).
inline constexpr size_t kEnvironmentBudgetBytes = size_t{1} << 30;

// Reads the map at `path`. Throws InputError naming the file (and why) when it is missing,
// unreadable, not an image of a supported kind, empty, or larger than `budgetBytes` decoded.
std::shared_ptr<const Image> readEnvironmentMap(const std::string& path,
                                                size_t budgetBytes = kEnvironmentBudgetBytes);

// Whether `path` names a kind of file readEnvironmentMap reads (by its extension).
bool isEnvironmentMapPath(const std::string& path);

}  // namespace prt
