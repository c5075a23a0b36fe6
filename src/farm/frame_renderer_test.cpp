#include "farm/frame_renderer.h"

#include <gtest/gtest.h>

#include <cmath>
#include <utility>
#include <vector>

#include "scene/scene_file.h"

namespace prt {
namespace {

TEST(FrameTasks, BatchesAreSplitAtFrameBoundaries) {
  TaskSet tasks;
  tasks.append(TaskRun{5, 4, 3});   // 5 8 11 14: frames 0, 0, 1, 1 of 10 pixels
  tasks.append(TaskRun{28, 3, 1});  // 28 29 30: frame 2, 2, 3
  std::vector<std::pair<uint64_t, std::vector<uint64_t>>> seen;
  FrameRenderer::forEachFrame(tasks, 10, [&](uint64_t frame, const TaskSet& pixels) {
    seen.emplace_back(frame, pixels.toVector());
  });
  const std::vector<std::pair<uint64_t, std::vector<uint64_t>>> expected = {
      {0, {5, 8}}, {1, {1, 4}}, {2, {8, 9}}, {3, {0}}};
  EXPECT_EQ(seen, expected);
}

// A scene that moves is rebuilt per frame with its meshes' trees kept; a still is built once.
TEST(FrameTasks, FramesAreBuiltOnDemandAndStillsOnce) {
  const Scene moving = parseScene(
      "camera { eye 0 0 -5 look_at 0 0 0 }\nimage { width 4 height 3 }\n"
      "sphere { center 0 0 0 radius 1 key 1 { center 1 0 0 } }\n", "m.scene");
  FrameSequence frames;
  frames.first = 0, frames.last = 3, frames.animated = true, frames.fps = 2;
  FrameRenderer renderer(moving, RenderSettings{1, 1}, frames);
  EXPECT_EQ(renderer.taskCount(), 48u);
  std::vector<Color> colors;
  renderer.render(TaskSet::range(0, 48), 1, colors);
  EXPECT_EQ(colors.size(), 48u);
  EXPECT_EQ(renderer.framesBuilt(), 4u);
  Scene still = moving;
  still.animation = nullptr;
  FrameRenderer once(still, RenderSettings{1, 1}, frames);
  once.render(TaskSet::range(0, 48), 1, colors);
  EXPECT_EQ(once.framesBuilt(), 1u);
}

// Frames met alternately, as a worker meets them when it checks another worker's pixels of
// the frame before its own: the two used last are kept, each built once, every colour as a
// frame rendered alone gives it.
TEST(FrameTasks, TwoFramesMetAlternatelyAreEachBuiltOnce) {
  const Scene moving = parseScene(
      "camera { eye 0 0 -5 look_at 0 0 0 }\nimage { width 4 height 3 }\n"
      "sphere { center 0 0 0 radius 1 key 1 { center 1 0 0 } }\n", "m.scene");
  FrameSequence frames;
  frames.first = 0, frames.last = 3, frames.animated = true, frames.fps = 2;
  FrameRenderer alone(moving, RenderSettings{1, 1}, frames);
  std::vector<Color> expected;
  alone.render(TaskSet::range(12, 12), 1, expected);  // frame 1
  FrameRenderer renderer(moving, RenderSettings{1, 1}, frames);
  std::vector<Color> colors;
  std::vector<Color> mixed;
  for (uint64_t p = 0; p < 12; ++p) {
    renderer.render(TaskSet::range(12 + p, 1), 1, colors);  // frame 1
    mixed.push_back(colors[0]);
    renderer.render(TaskSet::range(24 + p, 1), 1, colors);  // frame 2
  }
  EXPECT_EQ(renderer.framesBuilt(), 2u);
  EXPECT_EQ(mixed, expected);
  renderer.render(TaskSet::range(0, 1), 1, colors);  // frame 0: the one used longest ago goes
  renderer.render(TaskSet::range(24, 1), 1, colors);
  EXPECT_EQ(renderer.framesBuilt(), 3u);
  renderer.render(TaskSet::range(12, 1), 1, colors);
  EXPECT_EQ(renderer.framesBuilt(), 4u);
}

// Samples found not finite are counted over every frame, those no longer kept included.
TEST(FrameTasks, NonFiniteSamplesAreCountedOverEveryFrame) {
  Scene moving = parseScene(
      "camera { eye 0 0 -5 look_at 0 0 0 }\nimage { width 4 height 3 }\n"
      "sphere { center 0 0 0 radius 1 key 1 { center 1 0 0 } }\n", "m.scene");
  moving.environment.integrator = Integrator::path;
  moving.objects[0].material.emission = Color(0, std::nan(""), 0);  // no reader lets it in
  FrameSequence frames;
  frames.first = 0, frames.last = 3, frames.animated = true, frames.fps = 2;
  std::vector<Color> colors;
  uint64_t framesAlone = 0;
  for (uint64_t f = 0; f < 4; ++f) {
    FrameRenderer alone(moving, RenderSettings{2, 1}, frames);
    alone.render(TaskSet::range(12 * f, 12), 1, colors);
    EXPECT_GT(alone.nonFiniteSamples(), 0u) << f;
    framesAlone += alone.nonFiniteSamples();
  }
  FrameRenderer renderer(moving, RenderSettings{2, 1}, frames);
  renderer.render(TaskSet::range(0, 48), 2, colors);
  EXPECT_EQ(renderer.framesBuilt(), 4u);  // frames 0 and 1 are no longer kept
  EXPECT_EQ(renderer.nonFiniteSamples(), framesAlone);
  for (const Color& c : colors) EXPECT_TRUE(isFinite(c));
}

}  // namespace
}  // namespace prt
