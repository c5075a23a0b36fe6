// Micro-benchmarks of the tracer's hot paths: nearest-hit queries against BVHs of growing size
// (the BVH should keep cost near-logarithmic in the object count) and whole pixels of the
// benchmark scene.

#include <benchmark/benchmark.h>

#include "core/rng.h"
#include "scene/scene_file.h"
#include "trace/renderer.h"

namespace prt {
namespace {

Scene sphereField(int count) {
  Scene scene;
  Rng rng(1);
  for (int i = 0; i < count; ++i) {
    const Vec3 c(rng.uniform() * 40 - 20, rng.uniform() * 40 - 20, rng.uniform() * 40 + 5);
    scene.objects.push_back({SphereShape{c, 0.2 + 0.3 * rng.uniform()}, Material{}});
  }
  return scene;
}

void BM_NearestHit(benchmark::State& state) {
  const World world(sphereField(static_cast<int>(state.range(0))));
  Rng rng(2);
  Hit hit;
  for (auto _ : state) {
    const Ray ray{{0, 0, 0}, normalize(Vec3(rng.uniform() - 0.5, rng.uniform() - 0.5, 1))};
    benchmark::DoNotOptimize(world.intersect(ray, 0, 1e30, hit));
  }
  state.SetItemsProcessed(state.iterations());
}
BENCHMARK(BM_NearestHit)->RangeMultiplier(10)->Range(10, 100000);

void BM_ComplexScenePixels(benchmark::State& state) {
  Scene scene = loadSceneFile(PRT_SOURCE_DIR "/scenes/complex.scene");
  const World world(scene);
  const Renderer renderer(world, RenderSettings{1, 1});
  uint64_t pixel = 0, rays = 0;
  for (auto _ : state) {
    benchmark::DoNotOptimize(renderer.renderPixel(pixel, rays));
    pixel = (pixel + 7919) % renderer.pixelCount();
  }
  state.counters["rays/s"] = benchmark::Counter(static_cast<double>(rays), benchmark::Counter::kIsRate);
}
BENCHMARK(BM_ComplexScenePixels);

}  // namespace
}  // namespace prt

BENCHMARK_MAIN();
