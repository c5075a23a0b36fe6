#pragma once
// ParallelRun: what a parallel render produces, whatever drove it, and the master-side
// bookkeeping both drivers share: assembling the image and the ownership map from result
// batches, and building the report from the event stream.

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "cluster/messages.h"
#include "drive/parallel_options.h"
#include "image/image.h"
#include "metrics/events.h"
#include "metrics/run_report.h"
#include "trace/render_settings.h"
#include "trace/scene.h"

namespace prt {

struct ParallelRun {
  Image image{1, 1};
  std::vector<int16_t> owner;  // per pixel: the worker that rendered it
  std::vector<Event> events;
  RunReport report;
};

// Assembles result batches into the image and the ownership map.
class ImageAssembler {
 public:
  ImageAssembler(int width, int height);
  void add(int worker, const TaskSet& tasks, const std::vector<float>& rgb);
  Image& image() { return image_; }
  std::vector<int16_t>& owner() { return owner_; }

 private:
  Image image_;
  std::vector<int16_t> owner_;
};

// The scene as the master sends it.
SceneMsg makeSceneMessage(const Scene& scene, const RenderSettings& settings);

// The ownership map: each pixel in its worker's colour, shaded by the image's brightness so
// the picture stays recognisable. Written like any image (extension picks the format).
Image ownershipImage(const Image& image, const std::vector<int16_t>& owner);

}  // namespace prt
