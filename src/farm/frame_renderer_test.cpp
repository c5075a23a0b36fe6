#include "farm/frame_renderer.h"

#include <gtest/gtest.h>

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

}  // namespace
}  // namespace prt
