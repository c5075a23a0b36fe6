// glTF's data textures as Blender writes them (scenes/models/maps.glb, tests/models/
// blender-tangents.glb: scripts/make-path-scenes.py): the metallic-roughness texture and the
// normal maps are read as linear textures with their factors, tangents are the file's
// TANGENT or computed (trace/tangents.h), and all of it travels to workers in the asset pack.

#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <limits>
#include <numbers>
#include <stdexcept>

#include "scene/asset_pack.h"
#include "scene/model_file.h"
#include "scene/scene_file.h"
#include "trace/tangents.h"

#include <unistd.h>

namespace prt {
namespace {

const std::filesystem::path kMapsRoot(PRT_SOURCE_DIR);

const Object* objectWith(const ImportedModel& model, bool (*has)(const Material&)) {
  for (const Object& o : model.objects) {
    if (has(o.material)) return &o;
  }
  return nullptr;
}

const TriangleMesh& meshOfObject(const Object& o) { return *std::get<InstanceShape>(o.shape).mesh; }

TEST(GltfMaps, BlendersMetallicRoughnessTextureAndNormalMapsAreRead) {
  const ImportedModel model = readModelFile((kMapsRoot / "scenes/models/maps.glb").string());
  ASSERT_EQ(model.objects.size(), 3u);
  for (const std::string& w : model.warnings) {
    EXPECT_EQ(w.find("normal map"), std::string::npos) << w;
    EXPECT_EQ(w.find("metallic-roughness"), std::string::npos) << w;
  }
  // The banded ball: factors 1 and 1, the texture's B and G (Blender's Separate Color) carry
  // them: four bands of 64 texels, metal in the second and fourth, roughness 0.25 in the
  // first two.
  const Object* banded = objectWith(model, [](const Material& m) {
    return m.pbr.metallicRoughnessTexture.texture >= 0;
  });
  ASSERT_NE(banded, nullptr);
  EXPECT_EQ(banded->material.metallic, 1.0);
  EXPECT_EQ(banded->material.pbr.roughness, 1.0);
  EXPECT_LT(banded->material.pbr.normalTexture.texture, 0);
  const Texture& bands = model.textures[static_cast<size_t>(banded->material.pbr.metallicRoughnessTexture.texture)];
  EXPECT_TRUE(bands.linear);
  ASSERT_EQ(bands.image->width, 64);
  const double row = 0.5;
  const double us[4] = {0.1, 0.35, 0.6, 0.85};
  for (int band = 0; band < 4; ++band) {
    Texture nearest = bands;
    nearest.nearest = true;
    const Color c = sampleTexture(nearest, us[band], row);
    EXPECT_EQ(c.z, band % 2 == 1 ? 1.0 : 0.0) << band;                        // metallic
    EXPECT_EQ(c.y, (band < 2 ? 64 : 179) / 255.0) << band;                      // roughness
  }
  EXPECT_TRUE(meshOfObject(*banded).tangents.empty());  // no normal map: no tangents

  // The floor and the other ball: normal maps of scale 1 and 0.8, tangents computed (the
  // file has none), one per vertex, unit and perpendicular to the normals.
  int mapped = 0;
  for (const Object& o : model.objects) {
    const PbrSurface& p = o.material.pbr;
    if (p.normalTexture.texture < 0) continue;
    ++mapped;
    EXPECT_TRUE(model.textures[static_cast<size_t>(p.normalTexture.texture)].linear);
    EXPECT_TRUE(p.normalScale == 1.0 || p.normalScale == static_cast<double>(0.8f)) << p.normalScale;
    const TriangleMesh& mesh = meshOfObject(o);
    ASSERT_EQ(mesh.tangents.size(), mesh.vertices.size());
    for (size_t i = 0; i < mesh.tangents.size(); ++i) {
      const auto& t = mesh.tangents[i];
      const Vec3 xyz{t[0], t[1], t[2]};
      ASSERT_NEAR(length(xyz), 1, 1e-12) << i;
      ASSERT_NEAR(dot(xyz, mesh.normals[i]), 0, 1e-6) << i;
      ASSERT_TRUE(t[3] == 1 || t[3] == -1);
    }
  }
  EXPECT_EQ(mapped, 2);
  // The floor (Blender's z = 0 plane, u along +x, v up its y): in glTF's coordinates the
  // tangent is +x and the bitangent cross(+y, +x) = -z is Blender's +y: handedness +1.
  const Object* floor = objectWith(model, [](const Material& m) {
    return m.pbr.normalTexture.texture >= 0 && m.pbr.normalScale == 1;
  });
  ASSERT_NE(floor, nullptr);
  // Its map is repeated by KHR_texture_transform (Blender's Mapping node, scale 2).
  const UvTransform& uv = floor->material.pbr.normalTexture.uv;
  EXPECT_EQ(uv.m[0], 2.0);
  EXPECT_EQ(uv.m[4], 2.0);
  for (const auto& t : meshOfObject(*floor).tangents) {
    EXPECT_NEAR(t[0], 1, 1e-6);
    EXPECT_EQ(t[3], 1.0);
  }
}

// Blender's own tangents (MikkTSpace, written as TANGENT) are what the reader keeps; the
// tangents computed here for the same ball agree with them to within a hundredth of a degree.
TEST(GltfMaps, TheFilesTangentsAreUsedAndAgreeWithTheComputedOnes) {
  const ImportedModel model = readModelFile((kMapsRoot / "tests/models/blender-tangents.glb").string());
  ASSERT_EQ(model.objects.size(), 1u);
  const TriangleMesh& mesh = meshOfObject(model.objects[0]);
  ASSERT_EQ(mesh.tangents.size(), mesh.vertices.size());
  const auto computed = computeTangents(mesh);
  ASSERT_EQ(computed.size(), mesh.tangents.size());
  double worst = 0, sum = 0;
  size_t differ = 0;
  for (size_t i = 0; i < computed.size(); ++i) {
    const auto &f = mesh.tangents[i], &c = computed[i];
    if (f != c) ++differ;
    const double cosine = f[0] * c[0] + f[1] * c[1] + f[2] * c[2];
    const double degrees = std::acos(std::min(1.0, cosine)) * 180 / std::numbers::pi;
    worst = std::max(worst, degrees);
    sum += degrees;
    EXPECT_EQ(f[3], c[3]) << i;
  }
  EXPECT_GT(differ, 0u);  // the file's, not computed ones
  RecordProperty("worst_degrees", std::to_string(worst));
  RecordProperty("mean_degrees", std::to_string(sum / static_cast<double>(computed.size())));
  EXPECT_LT(worst, 0.01);  // measured 0.0001 degrees: the file's float rounding
}

// A scene of the file, written and packed as the master sends it and read back as a worker
// does: the same materials (data textures and scales), tangents and linear textures.
TEST(GltfMaps, MapsAndTangentsTravelInTheAssetPack) {
  const Scene scene = loadSceneFile((kMapsRoot / "scenes/models/maps.glb").string());
  const std::vector<uint8_t> assets = packAssets(scene);
  const Scene again = parseScene(writeScene(scene), "<from master>", unpackAssets(assets));
  ASSERT_EQ(again.objects.size(), scene.objects.size());
  for (size_t i = 0; i < scene.objects.size(); ++i) EXPECT_EQ(again.objects[i], scene.objects[i]) << i;
  EXPECT_EQ(again.textures, scene.textures);
  size_t linear = 0;
  for (const Texture& t : again.textures) linear += t.linear ? 1 : 0;
  EXPECT_EQ(linear, 3u);
  // A pack of the previous version is refused, as any other.
  std::vector<uint8_t> old = assets;
  const uint32_t five = 5;
  std::memcpy(old.data() + 4, &five, sizeof five);
  try {
    unpackAssets(old);
    ADD_FAILURE() << "a pack of version 5 was read";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find("not assets of this version"), std::string::npos) << e.what();
  }
}

// A file's TANGENT as it comes: xyz made unit (zero where not finite: no normal map there), w
// taken by its sign; one of another count than POSITION's is refused, naming it.
TEST(GltfMaps, TheFilesTangentsAreCleanedOrRefused) {
  const std::filesystem::path dir =
      std::filesystem::temp_directory_path() / ("prt-maps-" + std::to_string(::getpid()));
  std::filesystem::create_directories(dir);
  struct Cleanup {
    std::filesystem::path dir;
    ~Cleanup() { std::filesystem::remove_all(dir); }
  } cleanup{dir};
  std::string bin;
  auto put = [&bin](float f) { bin.append(reinterpret_cast<const char*>(&f), sizeof f); };
  for (const float f : {0.f, 0.f, 0.f, 1.f, 0.f, 0.f, 0.f, 1.f, 0.f}) put(f);   // positions
  for (const float f : {0.f, 1.f, 1.f, 1.f, 0.f, 0.f}) put(f);                  // uvs
  const float nan = std::numeric_limits<float>::quiet_NaN();
  for (const float f : {nan, 0.f, 0.f, 1.f, 2.f, 0.f, 0.f, 0.5f, 1.f, 0.f, 0.f, -7.f}) put(f);
  std::ofstream(dir / "t.bin", std::ios::binary) << bin;
  auto file = [&](int tangents) {
    std::ofstream(dir / "t.gltf")
        << R"({"asset":{"version":"2.0"},"scene":0,"scenes":[{"nodes":[0]}],"nodes":[{"mesh":0}],)"
           R"("meshes":[{"primitives":[{"attributes":{"POSITION":0,"TEXCOORD_0":1,"TANGENT":2},"material":0}]}],)"
           R"("materials":[{"normalTexture":{"index":0}}],)"
           R"("buffers":[{"byteLength":108,"uri":"t.bin"}],)"
           R"("bufferViews":[{"buffer":0,"byteLength":36},{"buffer":0,"byteOffset":36,"byteLength":24},)"
           R"({"buffer":0,"byteOffset":60,"byteLength":48}],)"
           R"("accessors":[{"bufferView":0,"componentType":5126,"count":3,"type":"VEC3"},)"
           R"({"bufferView":1,"componentType":5126,"count":3,"type":"VEC2"},)"
           R"({"bufferView":2,"componentType":5126,"count":)" << tangents << R"(,"type":"VEC4"}]})";
    return (dir / "t.gltf").string();
  };
  const ImportedModel model = readModelFile(file(3));
  ASSERT_EQ(model.objects.size(), 1u);
  const auto& t = meshOfObject(model.objects[0]).tangents;
  ASSERT_EQ(t.size(), 3u);
  EXPECT_EQ(t[0], (std::array<double, 4>{0, 0, 0, 1}));
  EXPECT_EQ(t[1], (std::array<double, 4>{1, 0, 0, 1}));
  EXPECT_EQ(t[2], (std::array<double, 4>{1, 0, 0, -1}));
  try {
    readModelFile(file(2));
    ADD_FAILURE() << "a TANGENT of two for three positions was read";
  } catch (const ModelFileError& e) {
    EXPECT_NE(std::string(e.what()).find("TANGENT"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace prt
