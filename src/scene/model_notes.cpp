#include "scene/model_notes.h"

#include "scene/model_file.h"

namespace prt {
namespace {

std::string plural(size_t n, const char* one, const char* many) {
  return std::to_string(n) + " " + (n == 1 ? one : many);
}

}  // namespace

void ModelNotes::problem(std::vector<std::string>& warnings, const std::string& what) const {
  if (strict) throw ModelFileError("model file \"" + file + "\": " + what);
  warnings.push_back("model file \"" + file + "\": " + what + "; rendered without it");
}

void ModelNotes::warn(std::vector<std::string>& warnings) const {
  skips.warn(warnings, file);
  const std::string head = "model file \"" + file + "\": ";
  if (skinned > 0) {
    warnings.push_back(head + "skinning is not applied (" +
                       plural(skinned, "skinned mesh or node", "skinned meshes or nodes") +
                       "): the rest pose is rendered");
  }
  if (morphed > 0) warnings.push_back(head + "morph targets are not applied: the base shape is rendered");
  if (morphAnimations > 0) {
    warnings.push_back(head + "animations of morph weights are not played (" +
                       plural(morphAnimations, "animation", "animations") +
                       "): the weights the file sets are rendered in every frame");
  }
  if (morphsOverBudget > 0) {
    warnings.push_back(head + plural(morphsOverBudget, "placement", "placements") +
                       " of a mesh with morph weights of its own are rendered in the mesh's stored "
                       "shape: the morphed copies already made hold all the vertices PRT copies for "
                       "morphs of one file");
  }
  if (animations > 0) {
    warnings.push_back(head + "animations are not played (" + plural(animations, "animation", "animations") +
                       "): nodes are rendered as the file places them");
  }
  if (unusedLights > 0) {
    warnings.push_back(head + plural(unusedLights, "ambient or area light is", "ambient or area lights are") +
                       " not used");
  }
  if (hiddenNodes > 0) {
    warnings.push_back(head + plural(hiddenNodes, "node is", "nodes are") +
                       " scaled to nothing (or not finite): skipped with what they hold");
  }
  if (!outOfRange.empty()) {
    std::string list;
    for (const std::string& what : outOfRange) list += (list.empty() ? "" : "; ") + what;
    warnings.push_back(head + "material values out of range: " + list);
  }
  if (!notUsed.empty()) {
    std::string list;
    for (const std::string& what : notUsed) list += (list.empty() ? "" : "; ") + what;
    warnings.push_back(head + "not used: " + list);
  }
}

std::string noTrianglesMessage(const std::string& file, const std::string& detail,
                               const std::vector<std::string>& warnings) {
  std::string message = "model file \"" + file + "\" has no triangles to render" + detail;
  const std::string head = "model file \"" + file + "\": ";
  constexpr size_t kShown = 4;
  for (size_t i = 0; i < warnings.size() && i < kShown; ++i) {
    std::string why = warnings[i];
    if (why.compare(0, head.size(), head) == 0) why.erase(0, head.size());
    message += (i == 0 ? ": " : "; ") + why;
  }
  if (warnings.size() > kShown) {
    message += "; and " + std::to_string(warnings.size() - kShown) + " more";
  }
  return message;
}

}  // namespace prt
