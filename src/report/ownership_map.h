#pragma once
// The ownership map (which worker rendered each pixel) in a compact, exact form for pages
// and saved reports. Maps larger than `maxSide` pixels on their longest side are first
// sampled every f-th pixel in both directions (f the smallest integer that fits), which keeps
// the owner of each sample exact. The samples, row by row, become runs of one owner, written
// as pairs of unsigned LEB128 varints (owner + 1, so 0 is "no owner"; run length), then base64.
// A block-structured map of a 640 x 480 image takes a few hundred bytes; a pixel-interleaved
// one about twice its sample count.
//
// JSON: {"width", "height" (the samples'), "step" (f), "source_width", "source_height",
//        "encoding": "rle-leb128-base64", "data"}
// Pure; thread-safe.

#include <cstdint>
#include <nlohmann/json.hpp>
#include <vector>

namespace prt {

// `owner` has width * height entries, row-major; negative: no owner.
nlohmann::json ownershipJson(const std::vector<int32_t>& owner, int width, int height,
                             int maxSide = 800);

// The samples back, width * height of them (-1: no owner). Throws std::invalid_argument for
// a malformed map (wrong encoding, bad base64, runs that do not fill it exactly).
std::vector<int32_t> decodeOwnership(const nlohmann::json& map);

}  // namespace prt
