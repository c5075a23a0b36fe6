#include "trace/renderer.h"

#include <gtest/gtest.h>

#include <algorithm>

#include "core/rng.h"

namespace prt {
namespace {

// A small scene with every feature that draws random numbers: area lights, gloss,
// translucency, glass, supersampling.
Scene featureScene() {
  Scene scene;
  scene.image.width = 24;
  scene.image.height = 18;
  scene.camera.eye = Vec3(0, 1.5, -5);
  scene.camera.lookAt = Vec3(0, 0.8, 0);
  scene.environment.maxDepth = 4;
  scene.lights.push_back({SphereLight{{3, 5, -3}, 0.7}, Color(1)});
  scene.lights.push_back({RectLight{{-3, 4, -1}, {1, 0, 0}, {0, 0, 1}}, Color(0.5)});
  Material glass;
  glass.transmissivity = 0.8;
  glass.reflectivity = 0.1;
  glass.ior = 1.5;
  glass.translucencyDegrees = 3;
  glass.diffuse = 0.1;
  Material floor;
  floor.reflectivity = 0.5;
  floor.glossDegrees = 4;
  scene.objects.push_back({SphereShape{{0, 1, 0}, 1}, glass});
  scene.objects.push_back({BoxShape{{1, 0, 1}, {2, 1, 2}}, Material{}});
  scene.objects.push_back({PlaneShape{{0, 0, 0}, {0, 1, 0}}, floor});
  return scene;
}

TEST(RendererTest, SameImageForOneAndTwoThreads) {
  const World world(featureScene());
  const Renderer renderer(world, RenderSettings{4, 2});
  RenderStats one, two;
  const Image a = renderImage(renderer, 1, &one);
  const Image b = renderImage(renderer, 2, &two);
  EXPECT_TRUE(a == b);
  EXPECT_EQ(one.rays, two.rays);
  EXPECT_GT(one.rays, renderer.pixelCount() * 4);
}

TEST(RendererTest, AnyTaskOrderGivesTheSamePixels) {
  const World world(featureScene());
  const Renderer renderer(world, RenderSettings{2, 2});
  const Image reference = renderImage(renderer, 1);
  // Render the pixels in a scrambled order, as scattered tasks, on two threads.
  std::vector<uint64_t> order(renderer.pixelCount());
  for (uint64_t i = 0; i < order.size(); ++i) order[i] = i;
  Rng rng(5);
  for (uint64_t i = order.size() - 1; i > 0; --i) {
    std::swap(order[i], order[static_cast<uint64_t>(rng.uniform() * static_cast<double>(i + 1))]);
  }
  TaskSet tasks;
  for (uint64_t p : order) tasks.append(TaskRun{p, 1, 1});
  std::vector<Color> colors;
  renderTasks(renderer, tasks, 2, colors);
  Image scrambled(renderer.width(), renderer.height());
  for (uint64_t i = 0; i < order.size(); ++i) scrambled.set(order[i], colors[i]);
  EXPECT_TRUE(scrambled == reference);
}

TEST(RendererTest, SupersamplingChangesEdgesButNotFlatRegions) {
  Scene scene = featureScene();
  scene.lights.clear();
  scene.objects.resize(1);
  scene.objects[0].material = Material{};
  const World world(scene);
  const Image one = renderImage(Renderer(world, RenderSettings{1, 1}), 1);
  const Image many = renderImage(Renderer(world, RenderSettings{9, 1}), 1);
  // Corner pixel sees only background in both.
  EXPECT_EQ(one.at(0, 0), many.at(0, 0));
  EXPECT_FALSE(one == many);  // the sphere's silhouette is anti-aliased
}

}  // namespace
}  // namespace prt
