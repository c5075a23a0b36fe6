#include <cstdio>

#include "cli/commands.h"
#include "scene/scene_file.h"

namespace prt::cli {

Scene loadScene(const std::string& path) {
  Scene scene = loadSceneFile(path);
  for (const std::string& w : scene.warnings) std::fprintf(stderr, "warning: %s\n", w.c_str());
  return scene;
}

}  // namespace prt::cli
