#pragma once
// Synthetic cost maps, for simulations at any image size without recording a render.

#include "sim/cost_map.h"

namespace prt {

// Every pixel costs the same; the total is `totalSeconds` (> 0).
CostMap uniformCostMap(int width, int height, double totalSeconds);

// The uneven shape of scenes/complex.scene, fitted to a map recorded from it (see the .cpp),
// drawn at width x height (the picture is stretched to the aspect ratio) and scaled to a
// total of `totalSeconds` (> 0).
CostMap complexSceneCostMap(int width, int height, double totalSeconds);

}  // namespace prt
