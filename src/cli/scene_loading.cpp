#include <algorithm>
#include <cmath>
#include <cstdio>

#include "cli/commands.h"
#include "scene/scene_file.h"

namespace prt::cli {

void addSceneSource(CLI::App& cmd, SceneSource& source) {
  cmd.add_option("scene", source.path,
                 "A .scene file, or a model file to render as it is: glTF (.gltf, .glb), OBJ, "
                 "FBX, COLLADA (.dae), PLY, STL or any format assimp reads")
      ->required();
  cmd.add_option("--camera", source.camera,
                 "Render through a camera of the imported model files, by name or by index "
                 "(from 0, over every import's cameras in order)");
  cmd.add_flag("--strict", source.strict,
               "A model file's missing or unreadable texture is an error, not a warning");
}

Scene loadScene(const SceneSource& source) {
  SceneReadOptions options;
  options.camera = source.camera;
  options.strict = source.strict;
  Scene scene = loadSceneFile(source.path, options);
  for (const std::string& w : scene.warnings) std::fprintf(stderr, "warning: %s\n", w.c_str());
  return scene;
}

void applyImageSize(Scene& scene, std::optional<int> width, std::optional<int> height) {
  const double aspect =
      static_cast<double>(scene.image.width) / static_cast<double>(scene.image.height);
  const auto scaled = [](double value) {
    return static_cast<int>(std::clamp(std::lround(value), 1L, 32768L));
  };
  if (width && !height) height = scaled(*width / aspect);
  if (height && !width) width = scaled(*height * aspect);
  if (width) scene.image.width = *width;
  if (height) scene.image.height = *height;
}

}  // namespace prt::cli
