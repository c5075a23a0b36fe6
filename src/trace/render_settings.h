#pragma once
// RenderSettings: how many rays to spend. The paper's test cases (Table III) are presets.

#include <optional>
#include <string>

namespace prt {

struct RenderSettings {
  int samplesPerPixel = 1;  // SS: stratified, jittered primary rays per pixel, >= 1
  int drtRate = 1;          // DRT: rays per glossy reflection, blurry transmission and
                            // area-light at every hit; compounds with depth, >= 1
};

// Table III: A = (DRT 1, SS 8), B = (DRT 1, SS 16), C = (DRT 2, SS 8), D = (DRT 2, SS 16).
// Returns nothing for any other name.
inline std::optional<RenderSettings> paperTestCase(const std::string& name) {
  if (name == "A") return RenderSettings{8, 1};
  if (name == "B") return RenderSettings{16, 1};
  if (name == "C") return RenderSettings{8, 2};
  if (name == "D") return RenderSettings{16, 2};
  return std::nullopt;
}

}  // namespace prt
