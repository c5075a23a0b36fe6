#include "drive/worker_engine.h"

#include "core/check.h"
#include "core/speed_index.h"
#include "scene/scene_file.h"

namespace prt {

void WorkerEngine::load(const SceneMsg& scene) {
  world_ = std::make_unique<World>(parseScene(scene.sceneText, "<scene from master>"));
  renderer_ = std::make_unique<Renderer>(*world_,
                                         RenderSettings{scene.samplesPerPixel, scene.drtRate});
}

double WorkerEngine::measureSpeedIndex() const {
  const int discs = speedIndexDiscs_;
  return throttle_.run([discs] { measureSpeedIndexSeconds(discs, 1); });
}

std::vector<float> WorkerEngine::render(const TaskSet& batch, double& seconds,
                                        uint64_t& rays) const {
  PRT_CHECK(renderer_ != nullptr);
  std::vector<Color> colors;
  seconds = throttle_.run([&] { rays += renderTasks(*renderer_, batch, 1, colors); });
  std::vector<float> rgb(3 * colors.size());
  for (size_t i = 0; i < colors.size(); ++i) {
    rgb[3 * i] = static_cast<float>(colors[i].x);
    rgb[3 * i + 1] = static_cast<float>(colors[i].y);
    rgb[3 * i + 2] = static_cast<float>(colors[i].z);
  }
  return rgb;
}

}  // namespace prt
