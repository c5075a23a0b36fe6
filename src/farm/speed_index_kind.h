#pragma once
// Which speed index the workers measure and report: the paper's Towers of Hanoi run
// (core/speed_index.h) or a ray-tracing probe of the scene itself (farm/speed_probe.h).

#include <string>
#include <vector>

#include "core/input_error.h"
#include "scene/keywords.h"

namespace prt {

enum class SpeedIndexKind {
  Hanoi,        // the paper's: Towers of Hanoi, kSpeedIndexDiscs discs
  RenderProbe,  // render probePixels() of the scene with the run's settings
  None,         // measure nothing: every worker reports 1 at once (for strategies that
                // learn speeds as they go; MASU then comes from measured throughput)
  Slowdown,     // measure nothing: every worker reports its --slowdown factor, its true
                // emulated speed (an oracle, for the emulation's own ceiling)
};

namespace speed_index_kind_detail {
inline constexpr struct {
  const char* name;
  SpeedIndexKind kind;
} kKinds[] = {{"hanoi", SpeedIndexKind::Hanoi},
                 {"probe", SpeedIndexKind::RenderProbe},
                 {"none", SpeedIndexKind::None},
                 {"slowdown", SpeedIndexKind::Slowdown}};
}  // namespace speed_index_kind_detail

inline std::vector<std::string> speedIndexKindNames() {
  std::vector<std::string> names;
  for (const auto& k : speed_index_kind_detail::kKinds) names.emplace_back(k.name);
  return names;
}

inline std::string speedIndexKindName(SpeedIndexKind kind) {
  for (const auto& k : speed_index_kind_detail::kKinds) {
    if (k.kind == kind) return k.name;
  }
  return "?";
}

// "hanoi" or "probe"; anything else throws InputError listing the valid names.
inline SpeedIndexKind parseSpeedIndexKind(const std::string& name) {
  for (const auto& k : speed_index_kind_detail::kKinds) {
    if (name == k.name) return k.kind;
  }
  throw InputError("unknown speed index '" + name +
                   "'; valid: " + joinNames(speedIndexKindNames()));
}

}  // namespace prt
