// libFuzzer target: the glTF reader on arbitrary bytes, written to a file (input.glb when the
// first byte is odd, input.gltf otherwise) in a scratch folder that also holds the files the
// seeds name beside them (pawns.bin and the PNG textures), so that mutated inputs reach
// buffers and images. A file that cannot be read must end in a ModelFileError naming it (never
// a crash, an out-of-bounds read, a hang, a huge allocation, a leak or another exception); a
// file that is read must give what the rest of PRT relies on: meshes with indices in range and
// finite vertices, usable transforms, texture references in range, finite lights and cameras,
// and warnings that name the file. An input that declares glTF 1.0 is read by assimp in a
// contained child (readAssimpFileContained), whose failures end in that ModelFileError too.

#include <unistd.h>

#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>
#include <variant>

#include "scene/model_file.h"

namespace {

namespace fs = std::filesystem;

fs::path scratch;

void check(bool ok) {
  if (!ok) std::abort();
}
bool finite(const prt::Vec3& v) { return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z); }

void checkModel(const prt::ImportedModel& model, const std::string& path) {
  check(!model.objects.empty());
  for (const std::string& w : model.warnings) check(w.find(path) != std::string::npos);
  for (const prt::Texture& t : model.textures) {
    check(t.image != nullptr && t.image->width > 0 && t.image->height > 0);
    check(t.image->texels.size() == static_cast<size_t>(t.image->width) * static_cast<size_t>(t.image->height) *
                                        static_cast<size_t>(t.image->channels));
  }
  for (const prt::Object& o : model.objects) {
    const auto* instance = std::get_if<prt::InstanceShape>(&o.shape);
    check(instance != nullptr && instance->mesh != nullptr && instance->worldFromMesh.isUsable());
    const prt::TriangleMesh& m = *instance->mesh;
    const size_t n = m.vertices.size();
    check(!m.triangles.empty());
    for (const auto& t : m.triangles) check(t[0] < n && t[1] < n && t[2] < n);
    for (const prt::Vec3& v : m.vertices) check(finite(v));
    for (const prt::Vec3& v : m.normals) check(finite(v));
    check(m.normals.empty() || m.normals.size() == n);
    check(m.uvs.empty() || m.uvs.size() == n);
    check(m.colors.empty() || m.colors.size() == n);
    for (const prt::TextureRef* ref : {&o.material.colorTexture, &o.material.emissionTexture}) {
      check(ref->texture >= -1 && ref->texture < static_cast<int32_t>(model.textures.size()));
      for (const double v : ref->uv.m) check(std::isfinite(v));
    }
  }
  for (const prt::Light& l : model.lights) {
    check(std::isfinite(l.color.x) && std::isfinite(l.color.y) && std::isfinite(l.color.z));
    if (const auto* spot = std::get_if<prt::SpotLight>(&l.shape)) {
      check(finite(spot->position) && spot->innerDegrees >= 0 && spot->innerDegrees <= spot->outerDegrees &&
            spot->outerDegrees <= 90);
    }
    if (const auto* point = std::get_if<prt::PointLight>(&l.shape)) check(finite(point->position));
  }
  for (const prt::ModelCamera& c : model.cameras) {
    const prt::Camera& v = c.camera;
    check(finite(v.eye) && finite(v.lookAt) && finite(v.up));
    check(v.fovDegrees > 0 && v.fovDegrees < 180);
    check(std::isfinite(v.orthoHeight) && v.orthoHeight >= 0);
    check(std::isfinite(c.aspectRatio) && c.aspectRatio >= 0);
  }
  // The rig: empty, or one binding per object, light and camera, its curves well formed (and
  // finite wherever they are evaluated) and its indices in range.
  const prt::ModelRig& rig = model.rig;
  if (rig.empty()) {
    check(rig.nodes.empty() && rig.objectNodes.empty() && rig.lightNodes.empty() && rig.cameraNodes.empty());
    return;
  }
  check(rig.objectNodes.size() == model.objects.size() && rig.objectLocal.size() == model.objects.size());
  check(rig.lightNodes.size() == model.lights.size() && rig.lightLocal.size() == model.lights.size());
  check(rig.cameraNodes.size() == model.cameras.size() && rig.cameraLocal.size() == model.cameras.size());
  prt::SceneAnimation a;
  a.curves = rig.curves;
  a.nodes = rig.nodes;
  a.duration = rig.duration;
  check(prt::rigProblem(a).empty());
  for (const auto* bound : {&rig.objectNodes, &rig.lightNodes, &rig.cameraNodes}) {
    for (const int32_t n : *bound) check(n >= -1 && n < static_cast<int32_t>(rig.nodes.size()));
  }
  for (const prt::Curve& c : rig.curves) {
    double v[4];
    for (const double t : {c.times.front() - 1, 0.5 * (c.times.front() + c.times.back()), c.times.back() + 1}) {
      c.evaluate(t, v);
      for (int i = 0; i < c.width; ++i) check(std::isfinite(v[i]));
    }
  }
}

}  // namespace

extern "C" int LLVMFuzzerInitialize(int*, char***) {
  scratch = fs::temp_directory_path() / ("prt-fuzz-model-" + std::to_string(::getpid()));
  fs::create_directories(scratch);
  const fs::path source(PRT_SOURCE_DIR);
  std::error_code error;
  for (const char* file : {"scenes/models/pawns.bin", "scenes/models/pawn marble.png",
                           "scenes/models/board-checker.png", "tests/models/blender-cube.png"}) {
    fs::copy_file(source / file, scratch / fs::path(file).filename(), fs::copy_options::overwrite_existing, error);
  }
  std::atexit([] {
    std::error_code ignored;
    fs::remove_all(scratch, ignored);
  });
  return 0;
}

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  const std::string path = (scratch / (size > 0 && (data[0] & 1) != 0 ? "input.glb" : "input.gltf")).string();
  {
    std::ofstream out(path, std::ios::binary | std::ios::trunc);
    out.write(reinterpret_cast<const char*>(data), static_cast<std::streamsize>(size));
  }
  prt::ModelReadOptions options;
  options.textureBudgetBytes = size_t{256} << 20;  // the malloc limit checks that it holds
  prt::ImportedModel model;
  try {
    model = prt::readModelFile(path, options);
  } catch (const prt::ModelFileError& error) {
    check(std::string(error.what()).find(path) != std::string::npos);
    return 0;
  }
  checkModel(model, path);
  return 0;
}
