#pragma once
// The cost-map file: what `prt render SCENE --cost-map FILE` writes and `prt simulate
// --cost-map FILE` reads. A small binary format in the spirit of PFM:
//
//   offset  size        contents
//   0       8           magic "PRTCOST1" (ASCII, no terminator)
//   8       4           width in pixels, uint32 little-endian, >= 1
//   12      4           height in pixels, uint32 little-endian, >= 1
//   16      4 * w * h   float32 little-endian: seconds to render each pixel at full speed,
//                       scan-line order (index y * width + x, top row first)
//
// Nothing follows the costs. Every cost is finite and >= 0, and the total is positive.
// Width * height is at most 2^28 pixels, as for renders.

#include <string>

#include "sim/cost_map.h"

namespace prt {

// Throws InputError naming the file for a missing or unreadable file, a wrong magic, a size
// that does not match the header (truncated or trailing bytes), or invalid costs.
CostMap readCostMapFile(const std::string& path);

// Writes atomically (see image/atomic_file.h); throws InputError when the file cannot be
// written.
void writeCostMapFile(const std::string& path, const CostMap& map);

}  // namespace prt
