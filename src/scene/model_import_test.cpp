// Model files that Blender wrote (tests/models, scenes/models: scripts/make-models.py made the
// geometry and Blender's own exporters the files): what the readers make of their meshes,
// instances, materials, textures, cameras and lights; the `import` block and `camera { from }`
// of the scene format; and a scene of imports written and sent as a worker receives it.

#include <assimp/Importer.hpp>
#include <assimp/scene.h>
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>
#include <unistd.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <numbers>
#include <set>
#include <tuple>

#include "scene/asset_pack.h"
#include "scene/model_file.h"
#include "scene/scene_file.h"
#include "trace/shapes.h"

namespace prt {
namespace {

namespace fs = std::filesystem;

const fs::path kImportSource(PRT_SOURCE_DIR);
const fs::path kModels = kImportSource / "tests" / "models";
constexpr double kDegrees = 180 / std::numbers::pi;

size_t distinctMeshes(const std::vector<Object>& objects) {
  std::set<const TriangleMesh*> meshes;
  for (const Object& o : objects) meshes.insert(std::get<InstanceShape>(o.shape).mesh.get());
  return meshes.size();
}

bool anyWarning(const std::vector<std::string>& warnings, const std::string& fragment) {
  for (const std::string& w : warnings) {
    if (w.find(fragment) != std::string::npos) return true;
  }
  return false;
}

TEST(ModelFile, GltfInstancesShareTheirMeshes) {
  const ImportedModel pawns = readModelFile((kImportSource / "scenes/models/pawns.gltf").string());
  // The board (2 primitives) and 16 pawns of 2 primitives each, from 3 meshes of 6 primitives.
  EXPECT_EQ(pawns.objects.size(), 2u + 16u * 2u);
  EXPECT_EQ(distinctMeshes(pawns.objects), 6u);
  EXPECT_EQ(pawns.format, "glTF 2.0");
  // The board's checker and the marble, one of them named with a space ("pawn marble.png").
  EXPECT_EQ(pawns.textures.size(), 2u);
  for (const Texture& t : pawns.textures) EXPECT_GE(t.image->width, 64);
  // The glass pawns' body: KHR_materials_transmission and KHR_materials_ior.
  bool glass = false;
  for (const Object& o : pawns.objects) glass = glass || o.material.transmissivity > 0.5;
  EXPECT_TRUE(glass);
  // The node tree composes: the pawns stand on the board, rotated with it, above y = 0.12.
  for (const Object& o : pawns.objects) EXPECT_GE(boundsOf(o.shape).lo.y, 0.12 - 0.13);
}

TEST(ModelFile, GltfCamerasAndLightsAsBlenderExportsThem) {
  const ImportedModel pawns = readModelFile((kImportSource / "scenes/models/pawns.gltf").string());
  ASSERT_EQ(pawns.cameras.size(), 1u);
  EXPECT_EQ(pawns.cameras[0].name, "Camera");
  EXPECT_NEAR(pawns.cameras[0].camera.fovDegrees, 0.6509916954952726 * kDegrees, 1e-9);
  EXPECT_NEAR(pawns.cameras[0].aspectRatio, 4.0 / 3, 1e-12);
  ASSERT_EQ(pawns.lights.size(), 2u);
  const auto* spot = std::get_if<SpotLight>(&pawns.lights[0].shape);
  ASSERT_NE(spot, nullptr);
  // Blender's 50-degree cone with blend 0.3: outer 25 degrees, inner 17.5.
  EXPECT_NEAR(spot->outerDegrees, 25, 1e-5);
  EXPECT_NEAR(spot->innerDegrees, 17.5, 1e-5);
  EXPECT_EQ(pawns.lights[0].falloff, Falloff::inverseSquare);
  // 900 W in Blender, 900 * 683 / (4 pi) cd in the file: 900 / (4 pi^2) in PRT's terms.
  EXPECT_NEAR(pawns.lights[0].color.x, 900 / (4 * std::numbers::pi * std::numbers::pi), 1e-3);
  const ImportedModel lights = readModelFile((kModels / "blender-lights.glb").string());
  std::set<size_t> kinds;
  for (const Light& l : lights.lights) kinds.insert(l.shape.index());
  EXPECT_EQ(kinds.size(), 3u);  // point, spot and sun
  for (const Light& l : lights.lights) {
    if (const auto* sun = std::get_if<DirectionalLight>(&l.shape)) {
      EXPECT_NEAR(length(sun->direction), 1, 1e-12);
      EXPECT_EQ(l.falloff, Falloff::none);
    }
  }
}

TEST(ModelFile, MirroredAndScaledInstancesKeepTheirTransforms) {
  const ImportedModel model = readModelFile((kModels / "blender-instances.glb").string());
  EXPECT_EQ(model.objects.size(), 10u);  // 5 nodes of a 2-primitive mesh
  EXPECT_EQ(distinctMeshes(model.objects), 2u);
  int mirrored = 0;
  for (const Object& o : model.objects) {
    mirrored += std::get<InstanceShape>(o.shape).worldFromMesh.determinant() < 0 ? 1 : 0;
  }
  EXPECT_EQ(mirrored, 2);  // both primitives of the mirrored node
}

TEST(ModelFile, OrthographicCameraKeepsItsHeight) {
  const ImportedModel model = readModelFile((kModels / "blender-ortho.glb").string());
  ASSERT_EQ(model.cameras.size(), 1u);
  EXPECT_NEAR(model.cameras[0].camera.orthoHeight, 2 * 1.875, 1e-6);
  EXPECT_NEAR(model.cameras[0].aspectRatio, 2.5 / 1.875, 1e-9);
}

TEST(ModelFile, EmbeddedAndSeparateGltfGiveTheSameScene) {
  const ImportedModel glb = readModelFile((kModels / "blender-cube.glb").string());
  const ImportedModel embedded = readModelFile((kModels / "blender-cube.gltf").string());
  ASSERT_EQ(glb.objects.size(), 1u);
  ASSERT_EQ(embedded.objects.size(), 1u);
  EXPECT_EQ(glb.objects[0], embedded.objects[0]);
  ASSERT_EQ(glb.textures.size(), 1u);
  EXPECT_EQ(glb.textures[0].image->texels, embedded.textures[0].image->texels);
  EXPECT_EQ(glb.textures[0].image->width, embedded.textures[0].image->width);
  EXPECT_FALSE(std::get<InstanceShape>(glb.objects[0].shape).mesh->uvs.empty());
}

// Blender's shape key "Bulge" at 0.5 (the mesh's weights): the column's middle ring, of radius
// 0.2, moved out by half of the key's 0.16; skinning is not applied (the rest pose).
TEST(ModelFile, MorphTargetsAreAppliedAndSkinningWarnsAndGivesTheRestPose) {
  const ImportedModel model = readModelFile((kModels / "blender-skinned.glb").string());
  ASSERT_EQ(model.objects.size(), 1u);
  EXPECT_TRUE(anyWarning(model.warnings, "skinning is not applied"));
  EXPECT_FALSE(anyWarning(model.warnings, "morph"));
  EXPECT_TRUE(anyWarning(model.warnings, "animations are not played"));
  const Bounds box = boundsOf(model.objects[0].shape);
  const double radius = static_cast<double>(0.2f) + 0.5 * static_cast<double>(0.16f);
  EXPECT_NEAR(box.hi.x, radius, 1e-6);
  EXPECT_NEAR(box.lo.z, -radius, 1e-6);
  EXPECT_NEAR(box.hi.y, 2.0, 1e-6);  // the ends stay
  // Smooth normals stay unit after their displacements are added.
  const TriangleMesh& mesh = *std::get<InstanceShape>(model.objects[0].shape).mesh;
  ASSERT_EQ(mesh.normals.size(), mesh.vertices.size());
  for (const Vec3& n : mesh.normals) EXPECT_NEAR(length(n), 1.0, 1e-12);
}

TEST(ModelFile, ObjTexturesAreFoundAsWindowsToolsWriteTheirPaths) {
  for (const char* name : {"blender-cube.obj", "blender-cube-winpath.obj"}) {
    const ImportedModel model = readModelFile((kModels / name).string());
    ASSERT_EQ(model.objects.size(), 1u) << name;
    EXPECT_EQ(model.textures.size(), 1u) << name;  // textures\cube tex.png found as well
    EXPECT_TRUE(model.warnings.empty()) << name << ": " << model.warnings.front();
    EXPECT_EQ(model.objects[0].material.colorTexture.texture, 0) << name;
  }
}

TEST(ModelFile, FbxAndColladaOfOneSceneAgree) {
  const ImportedModel fbx = readModelFile((kModels / "blender-scene.fbx").string());
  const ImportedModel dae = readModelFile((kModels / "blender-scene.dae").string());
  ASSERT_EQ(fbx.objects.size(), 2u);
  ASSERT_EQ(dae.objects.size(), 2u);
  ASSERT_EQ(fbx.cameras.size(), 1u);
  ASSERT_EQ(dae.cameras.size(), 1u);
  // A 35 mm lens on a 36 mm film at 4:3: a vertical field of view of 42.2 degrees in both
  // (the FBX in centimetres, the COLLADA file in metres).
  EXPECT_NEAR(fbx.cameras[0].camera.fovDegrees, 2 * std::atan(18.0 / 35 * 0.75) * kDegrees, 0.01);
  EXPECT_NEAR(dae.cameras[0].camera.fovDegrees, fbx.cameras[0].camera.fovDegrees, 0.01);
  ASSERT_EQ(fbx.lights.size(), 1u);
  ASSERT_EQ(dae.lights.size(), 1u);
  // The same 1000 W point light, once the FBX's centimetres are counted.
  const Vec3 p = std::get<PointLight>(fbx.lights[0].shape).position;
  const Vec3 q = std::get<PointLight>(dae.lights[0].shape).position;
  const double scale = length(p) / length(q);
  EXPECT_NEAR(scale, 100, 1e-3);
  EXPECT_NEAR(fbx.lights[0].color.x / (scale * scale), dae.lights[0].color.x, 1e-3);
  EXPECT_NEAR(dae.lights[0].color.x, 1000 / (4 * std::numbers::pi * std::numbers::pi), 1e-3);
  EXPECT_EQ(fbx.textures.size(), 1u);
  EXPECT_EQ(dae.textures.size(), 1u);
}

// FBX transparency is TransparentColor x TransparencyFactor: a Maya file (assimp-testmodels)
// writes a factor of 1 with a black colour and Opacity 1 for its opaque box.
TEST(ModelFile, FbxOpaqueWithFactorOneAndBlackTransparentColourStaysOpaque) {
  const fs::path file = "/usr/share/assimp/models/FBX/box_orphant_embedded_texture.fbx";
  if (!fs::exists(file)) GTEST_SKIP() << "assimp-testmodels is not installed";
  const ImportedModel box = readModelFile(file.string());
  ASSERT_FALSE(box.objects.empty());
  for (const Object& o : box.objects) EXPECT_EQ(o.material.transmissivity, 0.0);
}

// Blender's cube with its material's values edited out of their ranges: each is clamped, and
// the file, the material and the value taken are named in one warning. As Blender wrote it,
// no such warning.
TEST(ModelFile, MaterialValuesOutOfRangeAreClampedAndNamed) {
  const ImportedModel asWritten = readModelFile((kModels / "blender-cube.gltf").string());
  EXPECT_FALSE(anyWarning(asWritten.warnings, "out of range"));
  nlohmann::json doc;
  std::ifstream((kModels / "blender-cube.gltf")) >> doc;
  nlohmann::json& material = doc["materials"][0];
  material["pbrMetallicRoughness"]["roughnessFactor"] = 7;
  material["pbrMetallicRoughness"]["metallicFactor"] = -1;
  material["extensions"]["KHR_materials_ior"]["ior"] = 0.5;
  doc["extensionsUsed"].push_back("KHR_materials_ior");
  const fs::path file = fs::temp_directory_path() /
                        ("prt-out-of-range-" + std::to_string(::getpid()) + ".gltf");
  std::ofstream(file) << doc.dump();
  const ImportedModel model = readModelFile(file.string());
  fs::remove(file);
  std::string line;
  for (const std::string& w : model.warnings) {
    if (w.find("out of range") != std::string::npos) line = w;
  }
  EXPECT_NE(line.find(file.string()), std::string::npos) << line;
  EXPECT_NE(line.find("'CubeGrid': roughness 7 (taken as 1)"), std::string::npos) << line;
  EXPECT_NE(line.find("'CubeGrid': metallic -1 (taken as 0)"), std::string::npos) << line;
  EXPECT_NE(line.find("'CubeGrid': ior 0.5 (taken as 1)"), std::string::npos) << line;
  ASSERT_FALSE(model.objects.empty());
  EXPECT_EQ(model.objects[0].material.pbr.roughness, 1.0);
  EXPECT_EQ(model.objects[0].material.metallic, 0.0);
}

// Khronos's AnimatedMorphCube (assimp-testmodels), its mesh weights set to one target at a
// time in a copy: the morphed vertices are those assimp makes of the same file (its
// aiAnimMesh holds each target's shape, base plus displacement, in floats; PRT's sum of the
// two floats, exact in doubles, rounds to the same float). As given, the weights are 0 and
// their animation is not played: the stored shape, with that warning.
TEST(ModelFile, MorphTargetsAgreeWithAssimpOnAKhronosSample) {
  const fs::path dir = "/usr/share/assimp/models/glTF2/glTF-Sample-Models/AnimatedMorphCube-glTF";
  const fs::path file = dir / "AnimatedMorphCube.gltf";
  if (!fs::exists(file)) GTEST_SKIP() << "assimp-testmodels is not installed";
  const ImportedModel still = readModelFile(file.string());
  ASSERT_EQ(still.objects.size(), 1u);
  EXPECT_TRUE(anyWarning(still.warnings, "animations of morph weights are not played"));

  Assimp::Importer importer;
  const aiScene* scene = importer.ReadFile(file.string(), 0);
  ASSERT_NE(scene, nullptr) << importer.GetErrorString();
  ASSERT_EQ(scene->mNumMeshes, 1u);
  const aiMesh& mesh = *scene->mMeshes[0];
  ASSERT_EQ(mesh.mNumAnimMeshes, 2u);
  auto sorted = [](std::vector<std::array<float, 3>> v) {
    std::sort(v.begin(), v.end());
    return v;
  };
  auto floats = [&](const TriangleMesh& m) {
    std::vector<std::array<float, 3>> v;
    for (const Vec3& p : m.vertices) {
      v.push_back({static_cast<float>(p.x), static_cast<float>(p.y), static_cast<float>(p.z)});
    }
    return sorted(v);
  };
  const fs::path scratch = fs::temp_directory_path() / ("prt-morph-" + std::to_string(getpid()));
  fs::create_directories(scratch);
  fs::copy_file(dir / "AnimatedMorphCube.bin", scratch / "AnimatedMorphCube.bin",
                fs::copy_options::overwrite_existing);
  nlohmann::json json;
  std::ifstream(file) >> json;
  for (unsigned k = 0; k < 2; ++k) {
    json["meshes"][0]["weights"] = k == 0 ? nlohmann::json{1.0, 0.0} : nlohmann::json{0.0, 1.0};
    const fs::path copy = scratch / ("target" + std::to_string(k) + ".gltf");
    std::ofstream(copy) << json.dump();
    const ImportedModel morphed = readModelFile(copy.string());
    ASSERT_EQ(morphed.objects.size(), 1u);
    std::vector<std::array<float, 3>> expected;
    const aiAnimMesh& target = *mesh.mAnimMeshes[k];
    ASSERT_EQ(target.mNumVertices, mesh.mNumVertices);
    for (unsigned i = 0; i < target.mNumVertices; ++i) {
      expected.push_back({target.mVertices[i].x, target.mVertices[i].y, target.mVertices[i].z});
    }
    const auto got = floats(*std::get<InstanceShape>(morphed.objects[0].shape).mesh);
    EXPECT_EQ(got, sorted(expected)) << "target " << k;
    EXPECT_NE(got, floats(*std::get<InstanceShape>(still.objects[0].shape).mesh)) << "target " << k;
  }
  fs::remove_all(scratch);
}

// A Draco-compressed glTF (assimp-testmodels) fails in tinygltf before its extensions are
// seen: the refusal still names the extension it needs.
TEST(ModelFile, DracoCompressedGltfIsRefusedByItsExtensionsName) {
  const fs::path file = "/usr/share/assimp/models/glTF2/draco/2CylinderEngine.gltf";
  if (!fs::exists(file)) GTEST_SKIP() << "assimp-testmodels is not installed";
  try {
    readModelFile(file.string());
    ADD_FAILURE() << "read";
  } catch (const ModelFileError& e) {
    EXPECT_NE(std::string(e.what()).find("requires the glTF extension KHR_draco_mesh_compression"),
              std::string::npos)
        << e.what();
  }
}

// The Khronos sample of a sparse accessor (tests/models/README.md): three of the strip's
// vertices are replaced, lifting them from y = 1 to y = 2, 3 and 4.
TEST(ModelFile, SparseAccessorsReplaceTheElementsTheyName) {
  const ImportedModel strip =
      readModelFile((kModels / "khronos-simple-sparse-accessor.gltf").string());
  ASSERT_EQ(strip.objects.size(), 1u);
  const auto& mesh = *std::get<InstanceShape>(strip.objects[0].shape).mesh;
  EXPECT_EQ(mesh.triangles.size(), 12u);
  std::set<std::tuple<double, double, double>> used;
  for (const auto& t : mesh.triangles) {
    for (const uint32_t v : t) used.insert({mesh.vertices[v].x, mesh.vertices[v].y, mesh.vertices[v].z});
  }
  for (const auto& lifted : {std::tuple{1.0, 2.0, 0.0}, {3.0, 3.0, 0.0}, {5.0, 4.0, 0.0}}) {
    EXPECT_EQ(used.count(lifted), 1u) << std::get<0>(lifted) << ", " << std::get<1>(lifted);
  }
  for (const double x : {1.0, 3.0, 5.0}) EXPECT_EQ(used.count({x, 1.0, 0.0}), 0u) << x;
  EXPECT_EQ(used.count({0.0, 1.0, 0.0}), 1u);  // the others stay
  EXPECT_EQ(boundsOf(strip.objects[0].shape).hi.y, 4.0);
}

class ImportScene : public ::testing::Test {
 protected:
  void SetUp() override {
    const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
    dir_ = fs::temp_directory_path() / ("prt-import-" + std::to_string(::getpid()) + "-" + info->name());
    fs::remove_all(dir_);
    fs::create_directories(dir_);
    for (const char* f : {"blender-cube.glb", "blender-lights.glb", "blender-cube.obj",
                          "blender-cube.mtl", "blender-cube.png"}) {
      fs::copy_file(kModels / f, dir_ / f);
    }
  }
  void TearDown() override { fs::remove_all(dir_); }
  Scene load(const std::string& text, const SceneReadOptions& options = {}) const {
    std::ofstream(dir_ / "s.scene") << text;
    return loadSceneFile((dir_ / "s.scene").string(), options);
  }
  std::string errorOf(const std::string& text, const SceneReadOptions& options = {}) const {
    try {
      load(text, options);
    } catch (const InputError& e) {
      return e.format();
    }
    ADD_FAILURE() << "no error for:\n" << text;
    return {};
  }
  fs::path dir_;
};

const char* kImage = "image { width 8 height 6 }\n";

TEST_F(ImportScene, ImportBringsMeshesLightsAndTheCamera) {
  const Scene scene = load(std::string(kImage) + "import { file \"blender-lights.glb\" }\n" +
                           "sphere { center 0 5 0 radius 1 }\n");
  ASSERT_EQ(scene.imports.size(), 1u);
  const ImportSource& import = scene.imports[0];
  EXPECT_EQ(import.objectCount, 2u);
  EXPECT_EQ(import.lightCount, 3u);
  EXPECT_EQ(scene.objects.size(), 3u);
  EXPECT_EQ(scene.lights.size(), 3u);
  // No camera block: the file's.
  const ImportedModel model = readModelFile((dir_ / "blender-lights.glb").string());
  EXPECT_EQ(scene.camera.fovDegrees, model.cameras[0].camera.fovDegrees);
  // Right-handed files become left-handed: z is turned over.
  EXPECT_EQ(scene.camera.eye.z, -model.cameras[0].camera.eye.z);
}

TEST_F(ImportScene, PlacementScaleRotationAndTranslationApplyOnTop) {
  const Scene plain = load(std::string(kImage) + "import { file \"blender-cube.glb\" }\n");
  const Scene placed = load(std::string(kImage) +
                            "import { file \"blender-cube.glb\" scale 2 rotate 0 90 0 translate 10 0 0 "
                            "no_lights }\n");
  const Bounds a = boundsOf(plain.objects[0].shape), b = boundsOf(placed.objects[0].shape);
  EXPECT_NEAR(b.diagonal().y, 2 * a.diagonal().y, 1e-9);
  EXPECT_NEAR(b.centroid().x, 10 + 2 * a.centroid().z, 1e-6);  // +z turned to +x
  EXPECT_TRUE(placed.lights.size() == 1);  // no light of the file: the headlight
  EXPECT_EQ(std::get<PointLight>(placed.lights[0].shape).position, placed.camera.eye);
}

TEST_F(ImportScene, AnEmissiveSurfaceIsTheLightNotTheHeadlight) {
  const Scene lit = load(std::string(kImage) +
                         "import { file \"blender-cube.glb\" no_lights }\n"
                         "triangle { vertices 0 5 0 1 5 0 0 5 1 surface { emission 10 10 10 } }\n");
  EXPECT_TRUE(lit.lights.empty());
}

TEST_F(ImportScene, CameraFromPicksAFilesCameraByNameOrIndex) {
  const std::string base = std::string(kImage) + "import { file \"blender-cube.glb\" }\n";
  const Scene byName = load(base + "camera { from \"blender-cube.glb\" name \"Camera\" }\n");
  const Scene byIndex = load(base + "camera { from \"blender-cube.glb\" index 0 }\n");
  EXPECT_EQ(byName.camera, byIndex.camera);
  EXPECT_NE(errorOf(base + "camera { from \"blender-cube.glb\" name \"Nope\" }\n")
                .find("has no camera 'Nope'; its cameras: 0 'Camera'"),
            std::string::npos);
  EXPECT_NE(errorOf(base + "camera { from \"other.glb\" }\n").find("which the scene does not import"),
            std::string::npos);
  EXPECT_NE(errorOf(base + "camera { from \"blender-cube.glb\" eye 0 0 0 }\n").find("has no 'eye'"),
            std::string::npos);
  SceneReadOptions options;
  options.camera = "2";
  EXPECT_NE(errorOf(base, options).find("--camera 2: no imported camera"), std::string::npos);
  options.camera = "Camera";
  EXPECT_EQ(load(base + "camera { eye 0 0 -9 look_at 0 0 0 }\n", options).camera, byName.camera);
}

TEST_F(ImportScene, AModelWithoutCameraOrLightIsFramedAndLit) {
  const Scene scene = load(std::string(kImage) + "import { file \"blender-cube.obj\" }\n");
  const Bounds box = boundsOf(scene.objects[0].shape);
  EXPECT_LT(length(scene.camera.lookAt - box.centroid()), 1e-9);
  EXPECT_LT(scene.camera.eye.z, box.lo.z);  // in front: on the side imported models face
  ASSERT_EQ(scene.lights.size(), 1u);
}

TEST_F(ImportScene, BadImportsAreLocated) {
  EXPECT_NE(errorOf(std::string(kImage) + "import { file \"missing.glb\" }\n").find("s.scene:2:"),
            std::string::npos);
  EXPECT_NE(errorOf(std::string(kImage) + "import { file \"missing.glb\" }\n").find("does not exist"),
            std::string::npos);
  EXPECT_NE(errorOf(std::string(kImage) + "import { file \"blender-cube.glb\" scale 0 }\n")
                .find("must not be zero"),
            std::string::npos);
  EXPECT_NE(errorOf(std::string(kImage) + "import { scale 2 }\n").find("file"), std::string::npos);
  // A scene file that is a model file by its content but named .scene is read as text.
  fs::copy_file(dir_ / "blender-cube.glb", dir_ / "cube.scene");
  EXPECT_THROW(loadSceneFile((dir_ / "cube.scene").string()), InputError);
}

// An OBJ naming its MTL by an absolute path (assimp asks for it joined onto the OBJ's folder).
TEST_F(ImportScene, ObjMaterialLibrariesByAbsolutePathAreFound) {
  fs::create_directories(dir_ / "a");
  fs::create_directories(dir_ / "b");
  std::ofstream(dir_ / "b" / "red.mtl") << "newmtl red\nKd 1 0 0\n";
  std::ofstream(dir_ / "a" / "tri.obj") << "mtllib " << (dir_ / "b" / "red.mtl").string()
                                        << "\nv -1 -1 0\nv 1 -1 0\nv 0 1 0\nusemtl red\nf 1 2 3\n";
  const ImportedModel model = readModelFile((dir_ / "a" / "tri.obj").string());
  ASSERT_EQ(model.objects.size(), 1u);
  EXPECT_EQ(model.objects[0].material.color, Color(1, 0, 0));
  EXPECT_FALSE(anyWarning(model.warnings, ".mtl")) << model.warnings.front();
}

// An OBJ or PLY model that assimp cannot read is checked as a mesh block's file is: a bad
// index is named by its line and column (assimp says only "vertex index out of range"), a
// binary PLY's by its record; a file assimp reads is read as before.
TEST_F(ImportScene, ObjAndPlyModelsAreCheckedLineByLine) {
  std::ofstream(dir_ / "far.obj") << "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\nf 1 2 9\n";
  try {
    readModelFile((dir_ / "far.obj").string());
    ADD_FAILURE() << "an index out of range was read";
  } catch (const ModelFileError& e) {
    EXPECT_NE(std::string(e.what()).find("far.obj:5:7: a vertex index '9' is out of range"),
              std::string::npos)
        << e.what();
  }
  std::string ply =
      "ply\nformat binary_little_endian 1.0\nelement vertex 3\nproperty float x\n"
      "property float y\nproperty float z\nelement face 1\n"
      "property list uchar int vertex_indices\nend_header\n";
  const float corners[9] = {0, 0, 0, 1, 0, 0, 0, 1, 0};
  ply.append(reinterpret_cast<const char*>(corners), sizeof corners);
  const unsigned char count = 3;
  const int32_t face[3] = {0, 1, 7};
  ply.append(reinterpret_cast<const char*>(&count), 1);
  ply.append(reinterpret_cast<const char*>(face), sizeof face);
  std::ofstream(dir_ / "far.ply", std::ios::binary) << ply;
  try {
    readModelFile((dir_ / "far.ply").string());
    ADD_FAILURE() << "an index out of range was read";
  } catch (const ModelFileError& e) {
    EXPECT_NE(std::string(e.what()).find("face 1 of 1"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("vertex index 7 is out of range"), std::string::npos)
        << e.what();
  }
  // A good OBJ is read as before.
  std::ofstream(dir_ / "good.obj") << "v 0 0 0\nv 1 0 0 # a comment\nv 0 1 0\nvt 0 0\nvn 0 0 1\n"
                                      "o tri\ns off\nf 1/1/1 2//1 -1/1\n";
  EXPECT_EQ(readModelFile((dir_ / "good.obj").string()).objects.size(), 1u);
}

// A model rendered directly is placed by a scene text made for it: an error about the
// placement names the model file, with no line and column of that text (the user never wrote
// it, and the model file has no such line).
TEST_F(ImportScene, ErrorsAboutAModelRenderedDirectlyNameItWithoutALocation) {
  // One triangle 1e38 wide: beyond the coordinates a scene allows once placed.
  const float corners[9] = {-1e38f, -1e38f, 0, 1e38f, -1e38f, 0, 0, 1e38f, 0};
  std::ofstream(dir_ / "huge.bin", std::ios::binary)
      .write(reinterpret_cast<const char*>(corners), sizeof corners);
  std::ofstream(dir_ / "huge.gltf")
      << R"({"asset":{"version":"2.0"},"scenes":[{"nodes":[0]}],"nodes":[{"mesh":0}],)"
         R"("meshes":[{"primitives":[{"attributes":{"POSITION":0}}]}],)"
         R"("buffers":[{"byteLength":36,"uri":"huge.bin"}],"bufferViews":[{"buffer":0,"byteLength":36}],)"
         R"("accessors":[{"bufferView":0,"componentType":5126,"count":3,"type":"VEC3"}]})";
  const std::string error = errorOf(std::string(kImage) + "import { file \"huge.gltf\" }\n");
  EXPECT_NE(error.find("s.scene:2:"), std::string::npos) << error;  // a scene the user wrote
  try {
    loadSceneFile((dir_ / "huge.gltf").string());
    ADD_FAILURE() << "a triangle 1e38 wide was read";
  } catch (const InputError& e) {
    EXPECT_FALSE(e.hasLocation()) << e.format();
    EXPECT_NE(std::string(e.what()).find("huge.gltf"), std::string::npos) << e.format();
  }
}

TEST_F(ImportScene, ModelFilesRenderDirectly) {
  const Scene scene = loadSceneFile((dir_ / "blender-cube.glb").string());
  EXPECT_EQ(scene.image.width, 640);
  EXPECT_EQ(scene.image.height, 480);  // the camera's 4:3
  EXPECT_EQ(scene.image.output, "blender-cube.png");
  EXPECT_EQ(scene.imports.size(), 1u);
  EXPECT_EQ(scene.lights.size(), 1u);  // the file's point light
  std::ofstream(dir_ / "empty.glb");
  EXPECT_THROW(loadSceneFile((dir_ / "empty.glb").string()), InputError);
  EXPECT_THROW(loadSceneFile((dir_ / "none.obj").string()), InputError);
}

// The master writes the scene as text and packs its assets; the worker parses the text with
// them, no file at hand: the same objects, lights, camera and textures, bit for bit.
TEST_F(ImportScene, AScenesImportsTravelWithItToWorkers) {
  const Scene scene = load(std::string(kImage) +
                           "import { file \"blender-lights.glb\" rotate 0 30 0 }\n"
                           "sphere { center 0 5 0 radius 1 }\n"
                           "import { file \"blender-cube.glb\" translate 3 0 0 }\n"
                           "import { file \"blender-cube.glb\" translate -3 0 0 light_scale 2 }\n"
                           "light spot { position 0 9 0 direction 0 -1 0 inner 10 outer 20 falloff inverse_square }\n"
                           "light directional { direction 0 -1 1 color 0.5 0.5 0.5 }\n");
  const std::string text = writeScene(scene);
  const std::vector<uint8_t> assets = packAssets(scene);
  fs::remove_all(dir_);
  const Scene again = parseScene(text, "<from master>", unpackAssets(assets));
  ASSERT_EQ(again.objects.size(), scene.objects.size());
  for (size_t i = 0; i < scene.objects.size(); ++i) EXPECT_EQ(again.objects[i], scene.objects[i]) << i;
  EXPECT_EQ(again.lights, scene.lights);
  EXPECT_EQ(again.camera, scene.camera);
  EXPECT_EQ(again.textures, scene.textures);
  // The cube's mesh and texture travel once for its two imports.
  const ShippedAssets shipped = unpackAssets(assets);
  EXPECT_EQ(std::get<InstanceShape>(shipped.imports[1].objects[0].shape).mesh,
            std::get<InstanceShape>(shipped.imports[2].objects[0].shape).mesh);
  EXPECT_EQ(shipped.imports[1].textures[0].image, shipped.imports[2].textures[0].image);
  // The text is stable: written again from the worker's scene, it is the same.
  EXPECT_EQ(writeScene(again), text);
}

}  // namespace
}  // namespace prt
