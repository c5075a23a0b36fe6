#pragma once
// What a model file's reader could not use, gathered while it reads and given to the user at
// the end as one warning line per kind (model_file.h: never a silent grey), and the one rule
// for a texture that cannot be had: an error with --strict, else a warning. Shared by the glTF
// and the assimp readers. Not thread-safe; one per reading.

#include <cstddef>
#include <set>
#include <string>
#include <vector>

#include "scene/model_mesh.h"

namespace prt {

struct ModelNotes {
  std::string file;  // the model file, as the messages name it
  bool strict = false;

  MeshSkips skips;              // triangles and faces left out
  size_t skinned = 0;           // meshes or nodes with skins
  size_t morphed = 0;           // meshes with morph targets not applied (assimp's)
  size_t morphAnimations = 0;   // animations of morph weights (glTF), not played
  size_t morphsOverBudget = 0;  // morphed copies not made: over the budget of vertices
  size_t animations = 0;        // animations in the file
  size_t hiddenNodes = 0;       // nodes scaled to nothing
  size_t unusedLights = 0;      // lights of a kind PRT does not have
  std::set<std::string> notUsed;  // material features and extensions, with where
  std::set<std::string> outOfRange;  // material values not taken as given, with where

  // A texture (or its image) that cannot be had: throws ModelFileError with --strict, else
  // adds "...; rendered without it" to `warnings`.
  void problem(std::vector<std::string>& warnings, const std::string& what) const;
  // Appends the lines for everything counted above.
  void warn(std::vector<std::string>& warnings) const;
};

// The error for a model file that leaves nothing to render: "has no triangles to render",
// `detail`, then why, from the warnings gathered while reading (what was skipped and for what
// reason; the first few, and how many more), since they are not shown once the file is refused.
std::string noTrianglesMessage(const std::string& file, const std::string& detail,
                               const std::vector<std::string>& warnings);

}  // namespace prt
