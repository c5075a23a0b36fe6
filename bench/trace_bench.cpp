// Micro-benchmarks of the tracer's hot paths: nearest-hit queries against BVHs of growing size
// (the BVH should keep cost near-logarithmic in the object count) and whole pixels of the
// benchmark scene.

#include <benchmark/benchmark.h>

#include <vector>

#include "balance/interleaved_order.h"
#include "core/rng.h"
#include "scene/scene_file.h"
#include "trace/isa_level.h"
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
  state.counters["rays/s"] =
      benchmark::Counter(static_cast<double>(rays), benchmark::Counter::kIsRate);
}
BENCHMARK(BM_ComplexScenePixels);

// Queries as the shader makes them on the benchmark scene, gathered once: for a grid of camera
// rays, the nearest-hit query of the camera ray and of its mirror bounce, and one shadow query
// from each hit towards each light's centre. Replayed in a loop, they time World's queries
// alone: shadow rays both through the BVH and as the shader asks them, from the light's
// shadow shafts.
struct RecordedQueries {
  struct Shadow {
    Ray ray;
    double distance;
    size_t light;
  };
  explicit RecordedQueries(Scene scene);
  World world;
  std::vector<Ray> nearest;
  std::vector<Shadow> shadow;
};

RecordedQueries::RecordedQueries(Scene sceneToLoad) : world(std::move(sceneToLoad)) {
  const Scene& scene = world.scene();
  const PinholeCamera camera(scene.camera, 160, 120);
  auto shadowRays = [&](const Hit& hit, const Vec3& n) {
    const Vec3 origin = hit.point + 1e-9 * n;
    for (size_t l = 0; l < scene.lights.size(); ++l) {
      const Light& light = scene.lights[l];
      Vec3 target;
      if (const auto* p = std::get_if<PointLight>(&light.shape)) target = p->position;
      if (const auto* s = std::get_if<SphereLight>(&light.shape)) target = s->center;
      if (const auto* r = std::get_if<RectLight>(&light.shape)) {
        target = r->corner + 0.5 * r->edge1 + 0.5 * r->edge2;
      }
      const Vec3 d = target - origin;
      const double distance = length(d);
      if (dot(d, n) > 0) shadow.push_back({Ray{origin, d / distance}, distance, l});
    }
  };
  for (int y = 0; y < 120; ++y) {
    for (int x = 0; x < 160; ++x) {
      Ray ray = camera.generateRay(x + 0.5, y + 0.5);
      for (int bounce = 0; bounce < 2; ++bounce) {
        nearest.push_back(ray);
        Hit hit;
        if (!world.intersect(ray, 0, std::numeric_limits<double>::infinity(), hit)) break;
        const Vec3 n = dot(ray.direction, hit.normal) < 0 ? hit.normal : -hit.normal;
        shadowRays(hit, n);
        ray = Ray{hit.point + 1e-9 * n, reflect(ray.direction, n)};
      }
    }
  }
}

// Loaded and recorded once for both benchmarks.
const RecordedQueries& complexSceneQueries() {
  static const RecordedQueries queries(loadSceneFile(PRT_SOURCE_DIR "/scenes/complex.scene"));
  return queries;
}

void BM_ComplexSceneNearest(benchmark::State& state) {
  const RecordedQueries& q = complexSceneQueries();
  size_t i = 0;
  Hit hit;
  for (auto _ : state) {
    benchmark::DoNotOptimize(q.world.intersect(q.nearest[i], 0, 1e300, hit));
    if (++i == q.nearest.size()) i = 0;
  }
  state.SetItemsProcessed(state.iterations());
}
BENCHMARK(BM_ComplexSceneNearest);

// Replays the recorded shadow queries through `query(world, shadow)`.
template <typename Query>
void replayShadows(benchmark::State& state, Query&& query) {
  const RecordedQueries& q = complexSceneQueries();
  size_t i = 0;
  for (auto _ : state) {
    benchmark::DoNotOptimize(query(q.world, q.shadow[i]));
    if (++i == q.shadow.size()) i = 0;
  }
  state.SetItemsProcessed(state.iterations());
}

void BM_ComplexSceneShadow(benchmark::State& state) {
  replayShadows(state, [](const World& world, const RecordedQueries::Shadow& s) {
    return world.transmittance(s.ray, 0, s.distance);
  });
}
BENCHMARK(BM_ComplexSceneShadow);

void BM_ComplexSceneShadowToLight(benchmark::State& state) {
  replayShadows(state, [](const World& world, const RecordedQueries::Shadow& s) {
    return world.transmittanceToLight(s.light, s.ray, s.distance);
  });
}
BENCHMARK(BM_ComplexSceneShadowToLight);

// Preparing the benchmark scene for tracing: the BVH and every light's shadow shafts, which
// each process of a parallel render does once.
void BM_ComplexSceneWorld(benchmark::State& state) {
  const Scene scene = loadSceneFile(PRT_SOURCE_DIR "/scenes/complex.scene");
  for (auto _ : state) {
    const World world(scene);
    benchmark::DoNotOptimize(&world);
  }
}
BENCHMARK(BM_ComplexSceneWorld)->Unit(benchmark::kMillisecond);

// The cost of the order pixels are traced in, on a frame of the keyframes scene at 320x240
// and 4 samples: in scan lines, and in the strategies' interleaved order (interleaved_order.h:
// cells of a few neighbouring pixels spread across the image). Same pixels, same image; only
// the time differs.
void BM_PixelOrder(benchmark::State& state) {
  Scene scene = loadSceneFile(PRT_SOURCE_DIR "/scenes/keyframes.scene");
  scene.image.width = 320;
  scene.image.height = 240;
  const World world(scene);
  const Renderer renderer(world, RenderSettings{4, 1});
  const uint64_t n = renderer.pixelCount();
  const int mode = static_cast<int>(state.range(0));
  std::vector<uint64_t> pixels = mode == 0 ? TaskSet::range(0, n).toVector()
                                           : interleavedOrder(n).toVector();
  uint64_t rays = 0;
  for (auto _ : state) {
    for (uint64_t p : pixels) benchmark::DoNotOptimize(renderer.renderPixel(p, rays));
  }
  state.SetItemsProcessed(state.iterations() * static_cast<int64_t>(n));
  state.SetLabel(mode == 0 ? "scan lines" : "interleaved");
}
BENCHMARK(BM_PixelOrder)->DenseRange(0, 1)->Unit(benchmark::kMillisecond);

}  // namespace
}  // namespace prt

// As BENCHMARK_MAIN, with the build of the trace kernels that ran (baseline or an x86-64
// level) in the report's context: the figures depend on it.
int main(int argc, char** argv) {
  benchmark::AddCustomContext("trace kernels", prt::traceIsaLevel());
  benchmark::Initialize(&argc, argv);
  if (benchmark::ReportUnrecognizedArguments(argc, argv)) return 1;
  benchmark::RunSpecifiedBenchmarks();
  benchmark::Shutdown();
  return 0;
}
