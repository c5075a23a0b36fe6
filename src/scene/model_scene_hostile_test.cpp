// The hostile-input tests of the model readers beyond glTF (see model_file_hostile_test.cpp):
// OBJ files through assimp, scenes importing hostile files and the prt command rendering them,
// and the asset pack the master sends its workers, truncated, flipped and spoilt.

#include "scene/hostile_model_files.h"

#include <algorithm>
#include <cstdint>

#include "core/memory_budget.h"
#include "scene/contained_readers.h"

namespace prt {
namespace {

// --- OBJ through assimp ----------------------------------------------------------------------

const char* const kObj =
    "mtllib cube.mtl\n"
    "v 0 0 0\nv 1 0 0\nv 0 1 0\n"
    "vt 0 0\nvt 1 0\nvt 0 1\n"
    "usemtl Painted\n"
    "f 1/1 2/2 3/3\n";

TEST_F(HostileObj, AMissingTextureWarnsOrWithStrictIsAnError) {
  const std::string obj = write("cube.obj", kObj);
  write("cube.mtl", "newmtl Painted\nKd 0.8 0.2 0.2\nmap_Kd missing.png\n");
  EXPECT_READ_WITH_WARNING(readIsolated(obj), obj, "missing.png");
  ModelReadOptions strict;
  strict.strict = true;
  const Outcome o = readIsolated(obj, strict);
  EXPECT_REFUSED(o, obj);
  EXPECT_TRUE(contains(o.message, "missing.png")) << o;
  // Through a scene as well.
  const Outcome scene = loadIsolated(sceneImporting(obj));
  EXPECT_EQ(scene.kind, Kind::returned) << scene;
  EXPECT_TRUE(anyContains(scene.warnings, "missing.png")) << scene;
}

TEST_F(HostileObj, TexturesThatAreNotPlainImagesWarn) {
  fifo("pipe.png");
  fs::create_directories(dir_ / "folder.png");
  fs::create_symlink("/dev/zero", dir_ / "zero.png");
  write("huge.png", png(100000, 100000, 0));
  write("text.png", "not a png");
  Batch batch;
  int k = 0;
  for (const std::string texture : {"pipe.png", "folder.png", "zero.png", "huge.png", "text.png",
                                    "/dev/zero", "C:\\no\\such\\drive.png",
                                    // a parent folder's file, escaped: no such file there
                                    "%2e%2e%2fprt-hostile-no-such-texture.png"}) {
    const std::string name = "cube" + std::to_string(k++);
    const std::string obj = write(name + ".obj", std::string(kObj).replace(7, 4, name));
    write(name + ".mtl", "newmtl Painted\nKd 0.8 0.2 0.2\nmap_Kd " + texture + "\n");
    batch.read(obj, [obj, texture](const Outcome& o) {
      EXPECT_EQ(o.kind, Kind::returned) << texture << ": " << o;
      EXPECT_TRUE(anyContains(o.warnings, obj)) << texture << ": " << o;
      EXPECT_EQ(o.message, "objects 1, lights 0, cameras 0, textures 0") << texture;
      EXPECT_LT(o.seconds, 3) << o;
    });
  }
  batch.run(10);
}

// Without its MTL, an OBJ's materials are lost: that must be said, as a missing texture is.
TEST_F(HostileObj, AMissingMtlWarns) {
  const std::string obj = write("cube.obj", kObj);
  const Outcome o = readIsolated(obj);
  EXPECT_READ_WITH_WARNING(o, obj, "cube.mtl");
}

// assimp opens the files an OBJ names itself: an MTL that is a FIFO (or a device) must be
// refused, not waited on for ever.
TEST_F(HostileObj, AnMtlThatIsAFifoIsNotWaitedOn) {
  fifo("pipe.mtl");
  fs::create_symlink("/dev/zero", dir_ / "zero.mtl");
  Batch batch;
  for (const std::string mtl : {"pipe.mtl", "zero.mtl"}) {
    const std::string obj = write(mtl + ".obj", std::string(kObj).replace(7, 8, mtl));
    batch.read(obj, [](const Outcome& o) {
      EXPECT_NE(o.kind, Kind::timedOut) << o;
      EXPECT_TRUE(o.kind == Kind::returned || o.kind == Kind::modelError) << o;
      EXPECT_LT(o.seconds, 3) << o;
    });
  }
  batch.run(5);
}

TEST_F(HostileObj, NonFiniteVerticesSkipTheirTriangles) {
  const std::string obj = write("nan.obj",
                                "v 0 0 0\nv 1 0 0\nv 0 1 0\nv nan 0 0\nv inf 1 1\nv 1e400 0 0\n"
                                "f 1 2 3\nf 1 2 4\nf 1 5 2\nf 6 2 3\n");
  const Outcome o = readIsolated(obj);
  EXPECT_READ_WITH_WARNING(o, obj, "not finite");
  EXPECT_EQ(o.message, "objects 1, lights 0, cameras 0, textures 0");
}

TEST_F(HostileObj, IndicesOutOfRangeAndGarbageAreRefused) {
  Batch batch;
  int k = 0;
  for (const std::string text : {"v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 99999\n",
                                 "v 0 0 0\nv 1 0 0\nv 0 1 0\nf -7 2 3\n",
                                 "f 1 2 3\n", "v 0 0 0\n", "\x01\x02\x03 garbage\n",
                                 "v 1 2\nf 1\n"}) {
    const std::string obj = write("bad" + std::to_string(k++) + ".obj", text);
    batch.read(obj, [obj, text](const Outcome& o) {
      if (o.kind == Kind::returned) {
        EXPECT_TRUE(anyContains(o.warnings, obj)) << text << ": " << o;
      } else {
        EXPECT_REFUSED(o, obj) << text;
      }
    });
  }
  batch.run(10);
}

// --- scenes and the prt command --------------------------------------------------------------

TEST_F(HostileScene, ImportsOfHostileFilesAreInputErrorsNamingTheFile) {
  Gltf cycle;
  cycle.nodes = R"({"mesh":0,"children":[0]})";
  Gltf draco;
  draco.more = R"(,"extensionsRequired":["KHR_draco_mesh_compression"])";
  std::string truncated = glb(glbJson(), triangleBytes());
  truncated.resize(truncated.size() - 10);
  const std::vector<std::string> models = {
      write("not-json.gltf", "{ not json"), write("cycle.gltf", cycle.json()),
      write("draco.gltf", draco.json()), write("truncated.glb", truncated),
      write("empty.obj", ""), write("empty.fbx", ""),
  };
  fs::create_directories(dir_ / "folder.glb");
  for (const std::string& model : models) {
    const std::string scene = sceneImporting(model);
    const Outcome o = loadIsolated(scene);
    EXPECT_EQ(o.kind, Kind::inputError) << model << ": " << o;
    EXPECT_TRUE(contains(o.message, model)) << o;
    EXPECT_TRUE(contains(o.message, "@ " + scene)) << "not located in the scene: " << o;
    // The model given directly to loadSceneFile (prt render FILE).
    const Outcome direct = loadIsolated(model);
    EXPECT_EQ(direct.kind, Kind::inputError) << model << ": " << direct;
    EXPECT_TRUE(contains(direct.message, model)) << direct;
  }
  const std::string folder = (dir_ / "folder.glb").string();
  const Outcome o = loadIsolated(sceneImporting(folder));
  EXPECT_EQ(o.kind, Kind::inputError) << o;
  EXPECT_TRUE(contains(o.message, folder)) << o;
}

// What the master accepted from a model file must reach its workers: the scene text it writes
// must parse again with the assets it packs. Lights and cameras of a file are placed as the
// file says, but a light block and a camera block take coordinates within 1e9 only.
TEST_F(HostileScene, WhatTheMasterAcceptsFromAFileItsWorkersAccept) {
  const std::vector<std::pair<std::string, std::string>> cases = {
      {"far-light", R"({"mesh":0},{"translation":[1e12,0,0],"extensions":{"KHR_lights_punctual":{"light":0}}})"},
      {"far-camera", R"({"mesh":0},{"translation":[0,0,1e12],"camera":0})"},
      {"huge-ortho", R"({"mesh":0},{"translation":[0,0,5],"camera":1})"},
      {"skewed-camera", R"({"mesh":0},{"camera":0,"matrix":[1,0,0,0, 0,1,0,0, 0,-1,-1e-9,0, 0,0,5,1]})"},
  };
  for (const auto& [name, nodes] : cases) {
    Gltf g;
    g.nodes = nodes;
    g.scenes = R"("scene":0,"scenes":[{"nodes":[0,1]}])";
    g.more = R"(,"cameras":[{"type":"perspective","perspective":{"yfov":0.7,"znear":0.1}},)"
             R"({"type":"orthographic","orthographic":{"xmag":1e300,"ymag":1e300,"znear":0,"zfar":1}}])"
             R"(,"extensionsUsed":["KHR_lights_punctual"],"extensions":{"KHR_lights_punctual":{"lights":[{"type":"point"}]}})";
    const std::string model = write(name + ".gltf", g.json());
    const Outcome o = isolated([&]() -> Report {
      Scene scene;
      try {
        scene = loadSceneFile(model);
      } catch (const InputError& e) {
        return {Kind::inputError, std::string("the master refused it: ") + e.what(), {}};
      }
      const std::string text = writeScene(scene);
      try {
        const Scene again = parseScene(text, "<from master>", unpackAssets(packAssets(scene)));
        if (writeScene(again) != text) return {Kind::otherError, "the worker's scene differs", {}};
      } catch (const std::exception& e) {
        return {Kind::otherError, std::string("the master accepted it, the worker refused: ") + e.what(), {}};
      }
      return {Kind::returned, "", {}};
    });
    EXPECT_TRUE(o.kind == Kind::returned || o.kind == Kind::inputError) << name << ": " << o;
  }
}

std::string prtBinary() {
  const char* env = std::getenv("PRT_BINARY");
  return env != nullptr ? env : "";
}

struct CommandResult {
  int exitCode = -1;
  std::string output;
};

CommandResult runPrt(const std::string& args) {
  CommandResult r;
  FILE* pipe = popen(("timeout 60 " + prtBinary() + " " + args + " 2>&1").c_str(), "r");
  if (pipe == nullptr) return r;
  char buffer[4096];
  for (size_t n; (n = fread(buffer, 1, sizeof buffer, pipe)) > 0;) r.output.append(buffer, n);
  const int status = pclose(pipe);
  r.exitCode = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  return r;
}

TEST_F(HostileScene, ThePrtCommandRefusesHostileModelsByName) {
  if (prtBinary().empty()) GTEST_SKIP() << "PRT_BINARY is not set (ctest sets it)";
  Gltf cycle;
  cycle.nodes = R"({"mesh":0,"children":[0]})";
  std::string truncated = glb(glbJson(), triangleBytes());
  truncated.resize(30);
  fs::create_directories(dir_ / "folder.glb");
  const std::string pipe = fifo("pipe.glb");
  for (const std::string& model : {write("cycle.gltf", cycle.json()), write("truncated.glb", truncated),
                                  (dir_ / "folder.glb").string(), pipe, write("empty.obj", "")}) {
    const CommandResult r = runPrt("render \"" + model + "\" --width 8 --height 6 -q -o \"" +
                                   (dir_ / "out.png").string() + "\"");
    EXPECT_EQ(r.exitCode, 2) << model << "\n" << r.output;
    EXPECT_TRUE(contains(r.output, model)) << r.output;
    EXPECT_FALSE(fs::exists(dir_ / "out.png"));
  }
  // A file the master accepts renders under the thread driver as it does serially.
  Gltf far;
  far.nodes = R"({"mesh":0,"translation":[0,0,3]},{"translation":[1e12,0,0],"extensions":{"KHR_lights_punctual":{"light":0}}})";
  far.scenes = R"("scene":0,"scenes":[{"nodes":[0,1]}])";
  far.more = R"(,"extensionsUsed":["KHR_lights_punctual"],"extensions":{"KHR_lights_punctual":{"lights":[{"type":"point"}]}})";
  const std::string model = write("far-light.gltf", far.json());
  const std::string size = " --width 8 --height 6 --spp 1 -q -o ";
  const CommandResult serial = runPrt("render \"" + model + "\"" + size + "\"" + (dir_ / "serial.pfm").string() + "\"");
  EXPECT_EQ(serial.exitCode, 0) << serial.output;
  const CommandResult workers = runPrt("render \"" + model + "\" --workers 2" + size + "\"" +
                                       (dir_ / "workers.pfm").string() + "\"");
  EXPECT_EQ(workers.exitCode, 0) << workers.output;
}

// Files of a few bytes declaring a billion vertices: assimp allocates what a header declares,
// and before the reader's memory was tied to the file's size (foreignReaderMemoryBytes) these
// grew to 12 GB or, reading past the end of an ASCII file, ran until stopped from outside.
TEST_F(HostileScene, FilesDeclaringABillionVerticesAreRefusedWithoutGrowing) {
  if (prtBinary().empty()) GTEST_SKIP() << "PRT_BINARY is not set (ctest sets it)";
  const std::string plyHeader =
      "ply\nformat %s 1.0\nelement vertex 1000000000\nproperty float x\nproperty float y\n"
      "property float z\nelement face 1000000000\nproperty list uchar int vertex_indices\n"
      "end_header\n";
  auto ply = [&](const std::string& format) {
    std::string header = plyHeader;
    header.replace(header.find("%s"), 2, format);
    return header;
  };
  const std::vector<std::pair<std::string, std::string>> files = {
      {"ascii.ply", ply("ascii") + "0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n"},
      {"binary.ply", ply("binary_little_endian")},
      {"count.off", "OFF\n1000000000 1000000000 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n"},
      {"count.ase",
       "*3DSMAX_ASCIIEXPORT 200\n*GEOMOBJECT {\n *MESH {\n  *MESH_NUMVERTEX 1000000000\n"
       "  *MESH_NUMFACES 1000000000\n  *MESH_VERTEX_LIST {\n   *MESH_VERTEX 0 0 0 0\n  }\n }\n}\n"},
      {"count.x", "xof 0303txt 0032\nMesh m {\n 1000000000;\n 0.0;0.0;0.0;,\n 1.0;0.0;0.0;;\n 1;\n 3;0,1,2;;\n}\n"},
  };
  const std::string out = (dir_ / "out.png").string();
  for (const auto& [name, text] : files) {
    const std::string model = write(name, text);
    const CommandResult asModel =
        runPrt("render \"" + model + "\" --width 8 --height 6 -q -o \"" + out + "\"");
    EXPECT_EQ(asModel.exitCode, 2) << name << "\n" << asModel.output;
    if (name.ends_with(".ply")) {
      // Checked against the file once assimp has failed, as a mesh block's file is.
      const char* where = name == "ascii.ply" ? "ascii.ply:13:7: " : "vertex 1 of 1000000000";
      EXPECT_TRUE(contains(asModel.output, where)) << asModel.output;
    } else {
      EXPECT_TRUE(contains(asModel.output, "could not be read: it needs more than")) << asModel.output;
      EXPECT_TRUE(contains(asModel.output, "64 times its size")) << asModel.output;
    }
    const std::string scene = write(name + ".scene", "mesh { file \"" + name + "\" }\n");
    const CommandResult asMesh =
        runPrt("render \"" + scene + "\" --width 8 --height 6 -q -o \"" + out + "\"");
    EXPECT_EQ(asMesh.exitCode, 2) << name << "\n" << asMesh.output;
    EXPECT_TRUE(contains(asMesh.output, ".scene:1:13: error: ")) << asMesh.output;
    // A PLY's counts are checked against the file.
    if (!name.ends_with(".ply")) {
      EXPECT_TRUE(contains(asMesh.output, "it needs more than 512 MiB")) << asMesh.output;
    }
    EXPECT_FALSE(fs::exists(out));
  }
}

TEST(ForeignReaderMemory, GrowsWithTheFileAndStaysWithinTheBudget) {
  const uint64_t budget = memoryBudgetBytes();
  EXPECT_EQ(foreignReaderMemoryBytes(0, 0), std::min(kForeignReaderBaseBytes, budget));
  EXPECT_EQ(foreignReaderMemoryBytes(1 << 20, 1 << 30),
            std::min(kForeignReaderBaseBytes + 64 * (uint64_t{1} << 20) + (uint64_t{1} << 30), budget));
  EXPECT_EQ(foreignReaderMemoryBytes(UINT64_MAX, UINT64_MAX), budget);
  EXPECT_EQ(foreignReaderMemoryBytes(UINT64_MAX / 64 + 1, 0), budget);
}

// --- the asset pack --------------------------------------------------------------------------

// Unpacks `bytes`; if they unpack, checks what came out and hands it to the worker's parse of
// `text`. Returns "" or what went wrong.
std::string unpackAndUse(const std::vector<uint8_t>& bytes, const std::string& text) {
  ShippedAssets assets;
  try {
    assets = unpackAssets(bytes);
  } catch (const std::runtime_error&) {
    return "";
  }
  auto meshOk = [](const TriangleMesh& m) {
    for (const auto& t : m.triangles) {
      for (const uint32_t v : t) {
        if (v >= m.vertices.size()) return false;
      }
    }
    return !m.triangles.empty();
  };
  for (const auto& m : assets.meshBlocks) {
    if (m == nullptr || !meshOk(*m)) return "a bad mesh block was unpacked";
  }
  for (const ShippedImport& import : assets.imports) {
    for (const Texture& t : import.textures) {
      if (t.image == nullptr || t.image->texels.size() != static_cast<size_t>(t.image->width) *
                                                              static_cast<size_t>(t.image->height) *
                                                              static_cast<size_t>(t.image->channels)) {
        return "a bad image was unpacked";
      }
    }
    for (const Object& o : import.objects) {
      const auto& instance = std::get<InstanceShape>(o.shape);
      if (instance.mesh == nullptr || !meshOk(*instance.mesh) || !instance.worldFromMesh.isUsable()) {
        return "a bad object was unpacked";
      }
      for (const TextureRef* ref : {&o.material.colorTexture, &o.material.emissionTexture}) {
        if (ref->texture >= static_cast<int32_t>(import.textures.size())) return "a texture index out of range";
      }
    }
  }
  try {
    (void)parseScene(text, "<from master>", assets);
  } catch (const std::runtime_error&) {  // InputError: a pack that does not fit the text
  }
  return "";
}

struct Packed {
  std::vector<uint8_t> bytes;
  std::string text;
};

Packed packOf(const std::string& scenePath) {
  const Scene scene = loadSceneFile(scenePath);
  return {packAssets(scene), writeScene(scene)};
}

TEST_F(HostileScene, EveryTruncationOfAPackIsRefused) {
  const Outcome o = isolated([&]() -> Report {
    const Packed chess = packOf((kSource / "scenes/chess.scene").string());
    if (chess.bytes.size() < 1000) return {Kind::otherError, "the chess pack is too small", {}};
    if (!unpackAndUse(chess.bytes, chess.text).empty()) return {Kind::otherError, "the whole pack fails", {}};
    const size_t n = chess.bytes.size();
    std::vector<size_t> sizes;
    for (size_t s = 1; s < std::min<size_t>(n, 2048); ++s) sizes.push_back(s);
    for (size_t s = 2048; s < n; s += std::max<size_t>(1, n / 700)) sizes.push_back(s);
    for (size_t s = n - std::min<size_t>(n, 64); s < n; ++s) sizes.push_back(s);
    for (const size_t s : sizes) {
      const std::vector<uint8_t> cut(chess.bytes.begin(), chess.bytes.begin() + static_cast<std::ptrdiff_t>(s));
      try {
        (void)unpackAssets(cut);
        return {Kind::otherError, "a pack cut to " + std::to_string(s) + " of " + std::to_string(n) + " bytes unpacked", {}};
      } catch (const std::runtime_error&) {
      }
    }
    return {Kind::returned, std::to_string(sizes.size()) + " truncations refused", {}};
  });
  EXPECT_EQ(o.kind, Kind::returned) << o;
}

TEST_F(HostileScene, FlippedBytesAndGarbageInAPackNeverCrash) {
  const Outcome o = isolated([&]() -> Report {
    const Packed chess = packOf((kSource / "scenes/chess.scene").string());
    std::mt19937 random(7);
    // Flips, mostly in the counts and indices before the texels.
    for (int round = 0; round < 500; ++round) {
      std::vector<uint8_t> bytes = chess.bytes;
      const size_t span = round % 2 == 0 ? std::min<size_t>(bytes.size(), 4096) : bytes.size();
      const int flips = 1 + static_cast<int>(random() % 4);
      for (int f = 0; f < flips; ++f) bytes[random() % span] ^= static_cast<uint8_t>(1 + random() % 255);
      const std::string why = unpackAndUse(bytes, chess.text);
      if (!why.empty()) return {Kind::otherError, "flip round " + std::to_string(round) + ": " + why, {}};
    }
    // Garbage after a correct tag and version.
    for (int round = 0; round < 200; ++round) {
      std::vector<uint8_t> bytes(chess.bytes.begin(), chess.bytes.begin() + 8);
      const size_t extra = random() % 600;
      for (size_t i = 0; i < extra; ++i) {
        bytes.push_back(static_cast<uint8_t>(random() % 4 == 0 ? random() : random() % 3));
      }
      const std::string why = unpackAndUse(bytes, chess.text);
      if (!why.empty()) return {Kind::otherError, "garbage round " + std::to_string(round) + ": " + why, {}};
    }
    return {Kind::returned, "", {}};
  });
  EXPECT_EQ(o.kind, Kind::returned) << o;
  EXPECT_LT(o.peakGrowthKb, 512 * 1024) << o;
}

// A small pack (a textured triangle imported twice), every truncation and every byte flipped.
TEST_F(HostileScene, EveryByteOfASmallPackFlippedNeverCrashes) {
  write("tiny.png", png(2, 2, 2));
  write("tri.gltf", texturedGltf(R"({"source":0,"sampler":0})", R"({"uri":"tiny.png"})", R"({"wrapS":33071})"));
  const std::string scene = write("small.scene", "image { width 8 height 6 output \"x.png\" }\n"
                                                 "camera { eye 0 0 -5 look_at 0 0 0 }\n"
                                                 "import { file \"tri.gltf\" }\n"
                                                 "import { file \"tri.gltf\" translate 2 0 0 }\n");
  const Outcome o = isolated([&]() -> Report {
    const Packed small = packOf(scene);
    if (!unpackAndUse(small.bytes, small.text).empty()) return {Kind::otherError, "the whole pack fails", {}};
    for (size_t s = 1; s < small.bytes.size(); ++s) {
      try {
        (void)unpackAssets({small.bytes.begin(), small.bytes.begin() + static_cast<std::ptrdiff_t>(s)});
        return {Kind::otherError, "a cut to " + std::to_string(s) + " bytes unpacked", {}};
      } catch (const std::runtime_error&) {
      }
    }
    for (size_t i = 0; i < small.bytes.size(); ++i) {
      for (const uint8_t mask : std::initializer_list<uint8_t>{0x01, 0x80, 0xFF}) {
        std::vector<uint8_t> bytes = small.bytes;
        bytes[i] ^= mask;
        const std::string why = unpackAndUse(bytes, small.text);
        if (!why.empty()) return {Kind::otherError, "byte " + std::to_string(i) + ": " + why, {}};
      }
    }
    return {Kind::returned, std::to_string(small.bytes.size()) + " bytes", {}};
  });
  EXPECT_EQ(o.kind, Kind::returned) << o;
}

// What the loaders guarantee of every mesh (trace/triangle_mesh.h: finite vertices and
// normals, indices in range, no triangle of zero area) a pack must not bring in otherwise.
TEST_F(HostileScene, PacksOfValuesNoLoaderGivesAreRefused) {
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const std::vector<std::pair<std::string, std::function<void(TriangleMesh&)>>> cases = {
      {"a normal that is not finite", [&](TriangleMesh& m) { m.normals.assign(3, Vec3(0, 0, 1)); m.normals[1] = Vec3(nan, 0, 0); }},
      {"a texture coordinate that is not finite", [&](TriangleMesh& m) { m.uvs.assign(3, {0.f, 0.f}); m.uvs[2][0] = std::numeric_limits<float>::infinity(); }},
      {"a colour that is not finite", [&](TriangleMesh& m) { m.colors.assign(3, {1.f, 1.f, 1.f}); m.colors[0][1] = std::numeric_limits<float>::quiet_NaN(); }},
      {"a triangle of zero area", [&](TriangleMesh& m) { m.triangles.push_back({0, 0, 1}); }},
  };
  for (const auto& [what, spoil] : cases) {
    auto mesh = std::make_shared<TriangleMesh>();
    mesh->vertices = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
    mesh->triangles = {{0, 1, 2}};
    spoil(*mesh);
    Scene scene;
    MeshSource source;
    source.file = "/packed/mesh.ply";
    scene.objects.push_back({MeshShape{mesh, source}, {}});
    const std::vector<uint8_t> bytes = packAssets(scene);
    ASSERT_FALSE(bytes.empty());
    EXPECT_THROW((void)unpackAssets(bytes), std::runtime_error) << what;
  }
}

}  // namespace
}  // namespace prt
