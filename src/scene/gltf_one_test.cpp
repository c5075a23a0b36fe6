// glTF 1.0, which tinygltf does not read, read with assimp: the Khronos samples of Debian's
// assimp-testmodels (scripts/install-deps.sh installs it) with their textures and their
// "common" materials (KHR_materials_common, and 1.0's technique values) mapped as the common
// model; binary glTF 1.0; and files that claim 1.0 and are malformed, refused naming the
// file (assimp's crashes contained), never a crash of PRT.

#include <set>

#include "scene/hostile_model_files.h"

namespace prt {
namespace {

const fs::path kGltfOne = "/usr/share/assimp/models/glTF";

using HostileGltfOne = HostileModel;

// A glTF 1.0 file of one triangle: its collections are objects keyed by id. `patch` replaces
// the first occurrence of its first string by its second.
std::string gltfOne(const std::pair<std::string, std::string>& patch = {}) {
  std::string json =
      R"({"asset":{"version":"1.0"},"scene":"s","scenes":{"s":{"nodes":["n"]}},)"
      R"("nodes":{"n":{"meshes":["m"]}},)"
      R"("meshes":{"m":{"primitives":[{"attributes":{"POSITION":"p"},"indices":"i","mode":4}]}},)"
      R"("accessors":{"p":{"bufferView":"v","byteOffset":0,"componentType":5126,"count":3,"type":"VEC3"},)"
      R"("i":{"bufferView":"w","byteOffset":0,"componentType":5123,"count":3,"type":"SCALAR"}},)"
      R"("bufferViews":{"v":{"buffer":"b","byteOffset":0,"byteLength":36},)"
      R"("w":{"buffer":"b","byteOffset":36,"byteLength":6}},)"
      R"("buffers":{"b":{"byteLength":44,"uri":")" + dataUri(triangleBytes()) + R"("}}})";
  if (!patch.first.empty()) {
    const size_t at = json.find(patch.first);
    EXPECT_NE(at, std::string::npos) << patch.first;
    if (at != std::string::npos) json.replace(at, patch.first.size(), patch.second);
  }
  return json;
}

// A binary glTF 1.0 (KHR_binary_glTF): the 20-byte header (magic, version 1, length, content
// length, content format 0: JSON), the JSON padded with spaces to a multiple of 4, the body.
std::string glbOne(std::string json, const std::string& body = "") {
  while (json.size() % 4) json += ' ';
  std::string out = "glTF";
  append(out, uint32_t{1});
  append(out, static_cast<uint32_t>(20 + json.size() + body.size()));
  append(out, static_cast<uint32_t>(json.size()));
  append(out, uint32_t{0});
  return out + json + body;
}

const Material* texturedMaterial(const ImportedModel& model) {
  for (const Object& o : model.objects) {
    if (o.material.colorTexture.texture >= 0) return &o.material;
  }
  return nullptr;
}

TEST(GltfOne, KhronosSamplesAreReadWithTheirTextures) {
  if (!fs::exists(kGltfOne)) GTEST_SKIP() << "assimp-testmodels is not installed";
  struct Sample {
    const char* file;
    size_t objects;
    int textureWidth;  // 0: none
  };
  for (const Sample& s : {Sample{"CesiumMilkTruck/CesiumMilkTruck.gltf", 5, 2048},
                          Sample{"BoxTextured-glTF/BoxTextured.gltf", 1, 211},
                          Sample{"BoxTextured-glTF-Embedded/BoxTextured.gltf", 1, 211},
                          Sample{"BoxTextured-glTF-MaterialsCommon/BoxTextured.gltf", 1, 211},
                          Sample{"TwoBoxes/TwoBoxes.gltf", 2, 0}}) {
    SCOPED_TRACE(s.file);
    const ImportedModel model = readModelFile((kGltfOne / s.file).string());
    EXPECT_EQ(model.format, "glTF 1.0 (assimp)");
    EXPECT_EQ(model.objects.size(), s.objects);
    if (s.textureWidth == 0) {
      EXPECT_TRUE(model.textures.empty());
      continue;
    }
    ASSERT_FALSE(model.textures.empty());  // one for each material using the image
    for (const Texture& t : model.textures) EXPECT_EQ(t.image->width, s.textureWidth);
    ASSERT_NE(texturedMaterial(model), nullptr);
    for (const Object& o : model.objects) {
      const auto& mesh = *std::get<InstanceShape>(o.shape).mesh;
      if (o.material.colorTexture.texture >= 0) {
        EXPECT_EQ(mesh.uvs.size(), mesh.vertices.size());
      }
    }
  }
}

// KHR_materials_common's PHONG (BoxTextured) and the truck's technique values: the diffuse
// texture alone is the colour (a 1.0 material gives a colour or a texture), the specular
// colour's largest component the highlight, shininess its exponent (docs/model-files.md,
// "Common materials").
TEST(GltfOne, CommonMaterialsAreMappedAsTheCommonModel) {
  if (!fs::exists(kGltfOne)) GTEST_SKIP() << "assimp-testmodels is not installed";
  const ImportedModel box =
      readModelFile((kGltfOne / "BoxTextured-glTF-MaterialsCommon/BoxTextured.gltf").string());
  ASSERT_EQ(box.objects.size(), 1u);
  const Material& logo = box.objects[0].material;
  EXPECT_GE(logo.colorTexture.texture, 0);
  EXPECT_EQ(logo.color, Color(1, 1, 1));
  EXPECT_EQ(logo.diffuse, 1.0);
  EXPECT_NEAR(logo.specular, 0.2, 1e-6);
  EXPECT_EQ(logo.phongExponent, 256.0);
  EXPECT_EQ(logo.reflectivity, 0.0);
  EXPECT_EQ(logo.transmissivity, 0.0);
  EXPECT_EQ(logo.emission, Color(0, 0, 0));

  const ImportedModel truck = readModelFile((kGltfOne / "CesiumMilkTruck/CesiumMilkTruck.gltf").string());
  bool glass = false;
  for (const Object& o : truck.objects) {
    if (o.material.colorTexture.texture >= 0) {
      EXPECT_EQ(o.material.color, Color(1, 1, 1));
      EXPECT_NEAR(o.material.specular, 0.04, 1e-6);
      continue;
    }
    if (std::abs(o.material.specular - 0.65) > 1e-6) continue;
    glass = true;  // "glass": diffuse (0, 0.0405063, 0.0212407), specular 0.65, shininess 256
    EXPECT_NEAR(o.material.color.y, 0.0405063, 1e-6);
    EXPECT_NEAR(o.material.color.z, 0.0212407, 1e-6);
    EXPECT_EQ(o.material.phongExponent, 256.0);
  }
  EXPECT_TRUE(glass);
}

TEST_F(HostileGltfOne, GltfOneFilesOfEveryKindAreRead) {
  Batch batch;
  auto objects = [](size_t n) {
    return [n](const Outcome& o) {
      EXPECT_EQ(o.kind, Kind::returned) << o;
      EXPECT_EQ(o.message, "objects " + std::to_string(n) + ", lights 0, cameras 0, textures 0") << o;
    };
  };
  batch.read(write("one.gltf", gltfOne()), objects(1));
  // The version as a number (as the truck's exporter wrote it), or not given at all with
  // 1.0's collections, keyed objects.
  batch.read(write("number.gltf", gltfOne({R"("version":"1.0")", R"("version":1)"})), objects(1));
  batch.read(write("unversioned.gltf", gltfOne({R"("asset":{"version":"1.0"},)", ""})), objects(1));
  batch.read(write("one.glb", glbOne(gltfOne())), objects(1));
  // A 2.0 file (arrays) that says 1.0 is read as what it is, by the glTF 2.0 reader.
  std::string mislabelled = Gltf().json();
  mislabelled.replace(mislabelled.find(R"("version":"2.0")"), 15, R"("version":"1.0")");
  batch.read(write("mislabelled.gltf", mislabelled), [](const Outcome& o) {
    EXPECT_EQ(o.kind, Kind::returned) << o;
    EXPECT_EQ(o.message, "objects 1, lights 0, cameras 0, textures 0 (glTF 2.0)") << o;
  }, {}, [](const ImportedModel& m) { return counts(m) + " (" + m.format + ")"; });
  // Without an extension, known by its magic: assimp tells a binary glTF 1.0 by its name
  // alone, so this one is refused, naming the file and what it is.
  const std::string unnamed = write("binary-one", glbOne(gltfOne()));
  batch.read(unnamed, [unnamed](const Outcome& o) {
    EXPECT_REFUSED(o, unnamed);
    EXPECT_TRUE(contains(o.message, "(glTF 1.0, read with assimp)")) << o;
  });
  batch.run();
  // A real 1.0 file, its texture embedded as a data: URI, in a binary glTF 1.0.
  if (fs::exists(kGltfOne)) {
    const std::string embedded = readAll(kGltfOne / "BoxTextured-glTF-Embedded/BoxTextured.gltf");
    const std::string path = write("box.glb", glbOne(embedded));
    const ImportedModel box = readModelFile(path);
    EXPECT_EQ(box.format, "glTF 1.0 (assimp)");
    EXPECT_EQ(box.objects.size(), 1u);
    ASSERT_EQ(box.textures.size(), 1u);
    EXPECT_EQ(box.textures[0].image->width, 211);
  }
}

// Files that say they are glTF 1.0 and are not well formed: each is refused with a
// ModelFileError naming the file and saying it was read as glTF 1.0, whatever assimp does
// with it (it aborts on an accessor past its buffer and overflows its stack on a node cycle:
// contained).
TEST_F(HostileGltfOne, MalformedGltfOneFilesAreRefusedNamingTheFile) {
  const std::vector<std::pair<std::string, std::string>> texts = {
      {"empty-one.gltf", R"({"asset":{"version":"1.0"}})"},
      {"nothing-but-number.gltf", R"({"asset":{"version":1}})"},
      {"dangling-accessor.gltf", gltfOne({R"("POSITION":"p")", R"("POSITION":"nope")"})},
      {"accessor-past-buffer.gltf", gltfOne({R"("count":3,"type":"VEC3")", R"("count":1000000,"type":"VEC3")"})},
      {"indices-past-buffer.gltf", gltfOne({R"("count":3,"type":"SCALAR")", R"("count":3000000000,"type":"SCALAR")"})},
      {"missing-buffer.gltf", gltfOne({R"("uri":"data:)", R"("uri":"missing.bin","x":"data:)"})},
      {"node-cycle.gltf", gltfOne({R"("n":{"meshes":["m"]})", R"("n":{"meshes":["m"],"children":["n"]})"})},
      {"wrong-types.gltf", R"({"asset":{"version":"1.0"},"accessors":{"a":7},"meshes":7})"},
      {"unversioned-broken.gltf", R"({"meshes":{"m":{"primitives":[{"attributes":{"POSITION":"p"}}]}}})"},
  };
  Batch batch;
  for (const auto& [name, text] : texts) {
    const std::string path = write(name, text);
    batch.read(path, [path](const Outcome& o) {
      EXPECT_REFUSED(o, path);
      EXPECT_TRUE(contains(o.message, "(glTF 1.0, read with assimp)")) << o;
    });
  }
  // Cut short, the JSON says nothing of its version; with 2.0's arrays it is 2.0 whatever its
  // version says: both refused as glTF 2.0 files.
  for (const auto& [name, text] :
       {std::pair<std::string, std::string>{"cut.gltf", gltfOne().substr(0, 300)},
        {"arrays.gltf", R"({"asset":{"version":"1.0"},"accessors":[1,2,3],"meshes":7})"}}) {
    const std::string path = write(name, text);
    batch.read(path, [path](const Outcome& o) {
      EXPECT_REFUSED(o, path);
      EXPECT_TRUE(contains(o.message, "could not be read as glTF")) << o;
    });
  }
  batch.run(60);
}

// Binary glTF 1.0 whose header lies is refused before assimp sees it (assimp says only that no
// reader suits the file). Debian's own BoxTextured.glb is such a file: its header says 33
// bytes more than the file holds.
TEST_F(HostileGltfOne, BinaryGltfOneHeadersThatLieAreRefused) {
  const std::string good = glbOne(gltfOne());
  auto patched = [&](size_t at, uint32_t v) {
    std::string s = good;
    putU32(s, at, v);
    return s;
  };
  // JSON of a length that is no multiple of 4, not padded, and no body.
  std::string unpadded = glbOne(gltfOne() + " ");
  while ((unpadded.size() - 20) % 4 != 3) unpadded.pop_back();
  putU32(unpadded, 8, static_cast<uint32_t>(unpadded.size()));
  putU32(unpadded, 12, static_cast<uint32_t>(unpadded.size() - 20));
  std::vector<std::pair<std::string, std::string>> cases = {
      {"short.glb", good.substr(0, 12)},
      {"length-long.glb", patched(8, static_cast<uint32_t>(good.size() + 33))},
      {"length-short.glb", patched(8, 20)},
      {"content-past-end.glb", patched(12, 0xFFFFFFF0u)},
      {"content-unpadded.glb", unpadded},
      {"content-not-json.glb", patched(16, 1)},
      {"json-garbage.glb", glbOne("{\"asset\":{\"version\":\"1.0\"},\"nodes\":{\"n\":[[[[")},
  };
  const fs::path debian = kGltfOne / "BoxTextured-glTF-Binary/BoxTextured.glb";
  if (fs::exists(debian)) cases.emplace_back("debian-box.glb", readAll(debian));
  Batch batch;
  for (const auto& [name, bytes] : cases) {
    const std::string path = write(name, bytes);
    const bool header = name != "json-garbage.glb";
    batch.read(path, [path, header](const Outcome& o) {
      EXPECT_REFUSED(o, path);
      EXPECT_TRUE(contains(o.message, header ? "is not a binary glTF 1.0 file" : "glTF 1.0")) << o;
    });
  }
  batch.run(60);
}

}  // namespace
}  // namespace prt
