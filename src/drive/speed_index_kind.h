#pragma once
// Which speed index the workers measure and report: the paper's Towers of Hanoi run
// (core/speed_index.h) or a ray-tracing probe of the scene itself (drive/speed_probe.h).

#include <string>
#include <vector>

#include "core/input_error.h"

namespace prt {

enum class SpeedIndexKind {
  Hanoi,        // the paper's: Towers of Hanoi, kSpeedIndexDiscs discs
  RenderProbe,  // render probePixels() of the scene with the run's settings
};

inline std::vector<std::string> speedIndexKindNames() {
  return {"hanoi", "probe"};
}

inline std::string speedIndexKindName(SpeedIndexKind kind) {
  return kind == SpeedIndexKind::Hanoi ? "hanoi" : "probe";
}

// "hanoi" or "probe"; anything else throws InputError listing the valid names.
inline SpeedIndexKind parseSpeedIndexKind(const std::string& name) {
  if (name == "hanoi") return SpeedIndexKind::Hanoi;
  if (name == "probe") return SpeedIndexKind::RenderProbe;
  throw InputError("unknown speed index '" + name + "'; valid: hanoi, probe");
}

}  // namespace prt
