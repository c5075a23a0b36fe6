#include "farm/parallel_run.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstring>

#include "core/check.h"
#include "core/input_error.h"
#include "core/number_format.h"
#include "scene/scene_file.h"

namespace prt {
namespace {

constexpr double kMaxSlowdown = 1000;

}  // namespace

void validateParallelOptions(const ParallelOptions& o, uint64_t pixelCount) {
  if (o.workers < 1) throw InputError("--workers must be at least 1");
  if (static_cast<uint64_t>(o.workers) > pixelCount) {
    throw InputError("more workers (" + std::to_string(o.workers) + ") than pixels (" +
                     std::to_string(pixelCount) + ")");
  }
  validateJoinWaves(o.joins, "--join-at");
  const int total = o.totalWorkers();
  if (!o.slowdowns.empty()) {
    if (o.slowdowns.size() != static_cast<size_t>(total)) {
      throw InputError("--slowdown lists " + std::to_string(o.slowdowns.size()) +
                       " values for " + std::to_string(total) +
                       (o.joins.empty() ? " workers" : " workers (with those that join)") +
                       "; give one per worker");
    }
    for (double k : o.slowdowns) {
      // Beyond a thousand an emulated worker would take hours for a render of seconds, and
      // huge factors overflow the pacing's clock arithmetic.
      if (!(k >= 1.0 && k <= kMaxSlowdown)) {
        throw InputError("--slowdown values must be in [1, " + formatNumber(kMaxSlowdown) + "] (got " + formatNumber(k) + ")");
      }
    }
  }
  for (const SpeedChange& c : o.slowdownChanges) {
    if (c.worker < 0 || c.worker >= total || !(c.value >= 1.0) || !(c.atSeconds >= 0)) {
      throw InputError("--slowdown-at: worker " + std::to_string(c.worker) + " at " +
                       std::to_string(c.atSeconds) + " s, factor " + std::to_string(c.value) +
                       ": workers are 0 to " + std::to_string(total - 1) +
                       ", times >= 0 and factors >= 1");
    }
  }
  if (!(o.verifyPercent >= 0 && o.verifyPercent <= 100)) {
    throw InputError("--verify must be a percentage from 0 (no spot checks) to 100 (got " +
                     formatNumber(o.verifyPercent) + ")");
  }
  if (!(o.batchSeconds >= 0 && o.batchSeconds <= 60)) {
    throw InputError("--batch-seconds must be in [0, 60] (0: batches of --batch pixels)");
  }
  if (!(o.checkpointEverySeconds >= 0.01) || !(o.checkpointEverySeconds <= 86400)) {
    throw InputError("--checkpoint-every must be between 0.01 and 86400 seconds (got " +
                     formatNumber(o.checkpointEverySeconds) + ")");
  }
  validateRunPlan(o, total);
}

ImageAssembler::ImageAssembler(int width, int height, int frameHeight)
    : image_(width, height),
      owner_(static_cast<size_t>(width) * height, -1),
      pixelsPerFrame_(static_cast<uint64_t>(width) * (frameHeight > 0 ? frameHeight : height)),
      frameCounts_(image_.pixelCount() / pixelsPerFrame_, 0) {
  PRT_CHECK(image_.pixelCount() % pixelsPerFrame_ == 0);
}

void ImageAssembler::add(int worker, const TaskSet& tasks, const std::vector<float>& rgb,
                         const std::function<void(uint64_t)>& completed) {
  PRT_CHECK(rgb.size() == 3 * tasks.size());
  size_t i = 0;
  tasks.forEach([&](uint64_t pixel) {
    image_.set(pixel, Color(rgb[i], rgb[i + 1], rgb[i + 2]));
    owner_[pixel] = static_cast<int16_t>(worker);
    i += 3;
    const uint64_t frame = pixel / pixelsPerFrame_;
    if (++frameCounts_[frame] == pixelsPerFrame_ && completed) completed(frame);
  });
}

void ImageAssembler::takeBack(const TaskSet& tasks) {
  tasks.forEach([&](uint64_t pixel) {
    if (owner_[pixel] < 0) return;
    image_.set(pixel, Color(0, 0, 0));
    owner_[pixel] = -1;
    --frameCounts_[pixel / pixelsPerFrame_];
  });
}

Image frameOfSequence(const Image& stacked, int frameHeight, uint64_t ordinal) {
  Image out(stacked.width(), frameHeight);
  const uint64_t perFrame = out.pixelCount(), offset = ordinal * perFrame;
  for (uint64_t p = 0; p < perFrame; ++p) out.set(p, stacked.at(offset + p));
  return out;
}

Image ImageAssembler::frame(uint64_t ordinal) const {
  const auto height = static_cast<int>(pixelsPerFrame_ / static_cast<uint64_t>(image_.width()));
  return frameOfSequence(image_, height, ordinal);
}

void ImageAssembler::restore(const Checkpoint& checkpoint) {
  PRT_CHECK(checkpoint.image.width() == image_.width() &&
            checkpoint.image.height() == image_.height());
  image_ = checkpoint.image;
  owner_ = checkpoint.owner;
  owner_.resize(image_.pixelCount(), -1);
  std::fill(frameCounts_.begin(), frameCounts_.end(), 0);
  checkpoint.done.forEach([&](uint64_t pixel) { ++frameCounts_[pixel / pixelsPerFrame_]; });
}

SceneMsg makeSceneMessage(const Scene& scene, const RenderSettings& settings,
                          const FrameSequence& frames) {
  return SceneMsg{writeScene(scene), settings.samplesPerPixel, settings.drtRate,
                  packAssets(scene), frames};
}

Image ownershipImage(const Image& image, const std::vector<int16_t>& owner) {
  // A qualitative palette (Tableau 10), repeated for more workers.
  static const Color kPalette[] = {{0.12, 0.47, 0.71}, {1.0, 0.50, 0.05}, {0.17, 0.63, 0.17},
                                   {0.84, 0.15, 0.16}, {0.58, 0.40, 0.74}, {0.55, 0.34, 0.29},
                                   {0.89, 0.47, 0.76}, {0.50, 0.50, 0.50}, {0.74, 0.74, 0.13},
                                   {0.09, 0.75, 0.81}};
  Image out(image.width(), image.height());
  for (size_t p = 0; p < owner.size(); ++p) {
    const Color c = image.at(p);
    const double bright = std::clamp(luminance(c), 0.0, 1.0);
    const Color base = owner[p] < 0 ? Color(0) : kPalette[owner[p] % 10];
    out.set(p, base * (0.45 + 0.55 * std::sqrt(bright)));
  }
  return out;
}

}  // namespace prt
