// Triangle meshes: the tree's build time and memory for generated meshes of 10 k, 100 k and
// 1 M triangles, and rays cast against one mesh alone (primary rays from a camera, then
// incoherent rays between random points around it), PRT's MeshBvh beside Embree 3's
// rtcIntersect1 when the benchmark was built with Embree (libembree-dev; never linked into
// prt). One thread; medians of five runs.
//
//   build/bench/prt_bench_mesh [mesh file]   (default: scenes/models/bunny.ply)

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <functional>
#include <string>
#include <vector>

#include "core/rng.h"
#include "scene/mesh_file.h"
#include "trace/isa_level.h"
#include "trace/mesh_bvh.h"
#include "trace/world.h"

#ifdef PRT_HAVE_EMBREE
#include <embree3/rtcore.h>
#endif

namespace prt {
namespace {

double seconds(const std::function<void()>& f) {
  const auto start = std::chrono::steady_clock::now();
  f();
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

double median(std::vector<double> v) {
  std::sort(v.begin(), v.end());
  return v[v.size() / 2];
}

// A bumpy sphere of about `triangles` triangles: a latitude-longitude grid, radius varying.
std::shared_ptr<TriangleMesh> generated(size_t triangles) {
  const auto rows = static_cast<int>(std::sqrt(static_cast<double>(triangles) / 4));
  const int columns = 2 * rows;
  auto mesh = std::make_shared<TriangleMesh>();
  for (int i = 0; i <= rows; ++i) {
    const double theta = M_PI * i / rows;
    for (int j = 0; j < columns; ++j) {
      const double phi = 2 * M_PI * j / columns;
      const double r = 1 + 0.05 * std::sin(7 * theta) * std::cos(5 * phi);
      mesh->vertices.push_back({r * std::sin(theta) * std::cos(phi), r * std::cos(theta),
                                r * std::sin(theta) * std::sin(phi)});
    }
  }
  auto at = [&](int i, int j) { return static_cast<uint32_t>(i * columns + (j % columns)); };
  for (int i = 0; i < rows; ++i) {
    for (int j = 0; j < columns; ++j) {
      if (i > 0) mesh->triangles.push_back({at(i, j), at(i, j + 1), at(i + 1, j)});
      if (i + 1 < rows) mesh->triangles.push_back({at(i, j + 1), at(i + 1, j + 1), at(i + 1, j)});
    }
  }
  return mesh;
}

void buildTable() {
  std::printf("%-10s %12s %12s %14s %14s\n", "triangles", "build_s", "tree_MB", "tree_B/tri",
              "with_mesh_B/tri");
  for (const size_t n : {size_t{10000}, size_t{100000}, size_t{1000000}}) {
    const auto mesh = generated(n);
    std::vector<double> times;
    size_t bytes = 0;
    for (int run = 0; run < 5; ++run) {
      times.push_back(seconds([&] {
        const MeshBvh bvh(mesh);
        bytes = bvh.bytes();
      }));
    }
    const double t = static_cast<double>(mesh->triangles.size());
    const double meshBytes =
        static_cast<double>(mesh->vertices.size() * sizeof(Vec3) + mesh->triangles.size() * 12);
    std::printf("%-10zu %12.3f %12.1f %14.1f %14.1f\n", mesh->triangles.size(), median(times),
                static_cast<double>(bytes) / 1e6, static_cast<double>(bytes) / t,
                (static_cast<double>(bytes) + meshBytes) / t);
  }
}

// The rest of a World's preparation (its BVH, shadow shafts, neighbours and tie-breaking
// ranks) sees a mesh as one item: a million triangles among a dozen spheres and three lights
// cost it no more than the spheres alone.
void worldTable() {
  Scene scene;
  scene.objects.push_back({MeshShape{generated(1000000), {}}, Material{}});
  for (int i = 0; i < 12; ++i) {
    scene.objects.push_back({SphereShape{{-3.0 + 0.5 * i, 0.2, -1.5}, 0.2}, Material{}});
  }
  scene.objects.push_back({PlaneShape{{0, -1.1, 0}, {0, 1, 0}}, Material{}});
  scene.lights.push_back({SphereLight{{-3, 5, -4}, 0.5}, {1, 1, 1}});
  scene.lights.push_back({RectLight{{2, 5, -2}, {1, 0, 0}, {0, 0, 1}}, {1, 1, 1}});
  scene.lights.push_back({PointLight{{0, 6, -6}}, {1, 1, 1}});
  std::vector<double> total, trees;
  for (int run = 0; run < 3; ++run) {
    double tree = 0;
    total.push_back(seconds([&] {
      const World world(scene);
      tree = world.meshStats().buildSeconds;
    }));
    trees.push_back(tree);
  }
  std::printf(
      "\nWorld of a 1 M-triangle mesh, 12 spheres, a plane, 3 lights: %.3f s, of which "
      "the mesh's tree %.3f s\n",
      median(total), median(trees));
}

struct RaySet {
  std::string name;
  std::vector<Ray> rays;
};

std::vector<RaySet> raySets(const Bounds& box) {
  const Vec3 centre = box.centroid();
  const double radius = 0.5 * length(box.diagonal());
  RaySet primary{"primary", {}};
  const int side = 512;
  const Vec3 eye = centre + Vec3(0.3 * radius, 0.4 * radius, -2.5 * radius);
  const Vec3 forward = normalize(centre - eye);
  const Vec3 right = normalize(cross(Vec3(0, 1, 0), forward));
  const Vec3 up = cross(forward, right);
  for (int y = 0; y < side; ++y) {
    for (int x = 0; x < side; ++x) {
      const double u = (x + 0.5) / side * 2 - 1, v = (y + 0.5) / side * 2 - 1;
      primary.rays.push_back({eye, normalize(forward + 0.45 * u * right + 0.45 * v * up)});
    }
  }
  RaySet incoherent{"incoherent", {}};
  Rng rng(7);
  auto onSphere = [&](double r) {
    const double z = 2 * rng.uniform() - 1, a = 2 * M_PI * rng.uniform();
    const double s = std::sqrt(1 - z * z);
    return centre + r * Vec3(s * std::cos(a), s * std::sin(a), z);
  };
  for (int i = 0; i < side * side; ++i) {
    const Vec3 from = onSphere(1.5 * radius), to = onSphere(0.5 * radius);
    incoherent.rays.push_back({from, normalize(to - from)});
  }
  return {primary, incoherent};
}

#ifdef PRT_HAVE_EMBREE
struct EmbreeMesh {
  RTCDevice device = rtcNewDevice("threads=1");
  RTCScene scene = rtcNewScene(device);
  explicit EmbreeMesh(const TriangleMesh& mesh) {
    RTCGeometry g = rtcNewGeometry(device, RTC_GEOMETRY_TYPE_TRIANGLE);
    auto* v = static_cast<float*>(rtcSetNewGeometryBuffer(
        g, RTC_BUFFER_TYPE_VERTEX, 0, RTC_FORMAT_FLOAT3, 3 * sizeof(float), mesh.vertices.size()));
    for (size_t i = 0; i < mesh.vertices.size(); ++i) {
      for (int k = 0; k < 3; ++k) v[3 * i + k] = static_cast<float>(mesh.vertices[i][k]);
    }
    auto* t = static_cast<unsigned*>(rtcSetNewGeometryBuffer(g, RTC_BUFFER_TYPE_INDEX, 0,
                                                             RTC_FORMAT_UINT3, 3 * sizeof(unsigned),
                                                             mesh.triangles.size()));
    for (size_t i = 0; i < mesh.triangles.size(); ++i) {
      for (int k = 0; k < 3; ++k) t[3 * i + k] = mesh.triangles[i][k];
    }
    rtcCommitGeometry(g);
    rtcAttachGeometry(scene, g);
    rtcReleaseGeometry(g);
    rtcCommitScene(scene);
  }
  ~EmbreeMesh() {
    rtcReleaseScene(scene);
    rtcReleaseDevice(device);
  }
  size_t cast(const std::vector<Ray>& rays) const {
    RTCIntersectContext context;
    rtcInitIntersectContext(&context);
    size_t hits = 0;
    for (const Ray& r : rays) {
      RTCRayHit h{};
      h.ray.org_x = static_cast<float>(r.origin.x);
      h.ray.org_y = static_cast<float>(r.origin.y);
      h.ray.org_z = static_cast<float>(r.origin.z);
      h.ray.dir_x = static_cast<float>(r.direction.x);
      h.ray.dir_y = static_cast<float>(r.direction.y);
      h.ray.dir_z = static_cast<float>(r.direction.z);
      h.ray.tnear = 0;
      h.ray.tfar = std::numeric_limits<float>::infinity();
      h.ray.mask = ~0u;
      h.hit.geomID = RTC_INVALID_GEOMETRY_ID;
      rtcIntersect1(scene, &context, &h);
      hits += h.hit.geomID != RTC_INVALID_GEOMETRY_ID;
    }
    return hits;
  }
};
#endif

void rayTable(const std::string& file) {
  MeshSource source;
  source.file = file;
  const LoadedMesh loaded = loadMeshFile(source);
  const MeshBvh bvh(loaded.mesh);
  std::printf("\n%s: %zu triangles\n%-11s %8s %14s %14s %8s\n", file.c_str(), bvh.triangleCount(),
              "rays", "hit_%", "prt_Mrays/s", "embree_Mrays/s", "ratio");
#ifdef PRT_HAVE_EMBREE
  const EmbreeMesh embree(*loaded.mesh);
#endif
  for (const RaySet& set : raySets(bvh.bounds())) {
    // The two take turns, so that both meet the same spells of a shared machine's load.
    size_t hits = 0, embreeHits = 0;
    std::vector<double> prt, other;
    for (int run = 0; run < 5; ++run) {
      prt.push_back(seconds([&] {
        hits = 0;
        for (const Ray& r : set.rays) {
          double t = std::numeric_limits<double>::infinity();
          uint32_t triangle = 0;
          hits += bvh.nearest(r, 0, t, triangle);
        }
      }));
#ifdef PRT_HAVE_EMBREE
      other.push_back(seconds([&] { embreeHits = embree.cast(set.rays); }));
#endif
    }
    const double n = static_cast<double>(set.rays.size());
    const double prtRate = n / median(prt) / 1e6;
    const double embreeRate = other.empty() ? 0.0 : n / median(other) / 1e6;
    if (!other.empty() && embreeHits != hits) {
      std::printf("  (embree hit %zu rays, prt %zu)\n", embreeHits, hits);
    }
    std::printf("%-11s %8.1f %14.2f %14.2f %8.2f\n", set.name.c_str(),
                100.0 * static_cast<double>(hits) / n, prtRate, embreeRate,
                embreeRate > 0 ? prtRate / embreeRate : 0.0);
  }
}

}  // namespace
}  // namespace prt

int main(int argc, char** argv) {
  // The figures are those of the build of the kernels the loader took (prt --version's).
  std::printf("trace kernels: %s\n\n", prt::traceIsaLevel());
  prt::buildTable();
  prt::worldTable();
  prt::rayTable(argc > 1 ? argv[1] : std::string(PRT_SOURCE_DIR) + "/scenes/models/bunny.ply");
  return 0;
}
