// glTF files made to break the readers (the others are in model_scene_hostile_test.cpp):
// malformed glTF JSON and binary glTF, byte ranges
// reaching past their buffers, indices out of range, node cycles and shared subtrees, files
// that are FIFOs or devices, absurd counts, sizes and numbers, deeply nested JSON; OBJ files
// whose MTL or textures are missing or are FIFOs; scenes importing such files, and the prt
// command rendering them; and the asset pack the master sends its workers, truncated, flipped
// and replaced by garbage. Every one must end in a ModelFileError or InputError that names the
// file (or a model with warnings naming it), quickly and in bounded memory, never in a crash.
//
// Hostile reads run in a child process (isolatedAll, in hostile_model_files.h; a test's
// variants share one) with an alarm and their memory measured, so that a crash, a hang or a runaway allocation fails
// its test instead of taking the whole test binary down. Files are tiny and written to a
// scratch folder per test. The prt command is run from $PRT_BINARY, which CTest sets.

#include <set>

#include "scene/hostile_model_files.h"
#include "trace/shapes.h"

namespace prt {
namespace {

// --- glTF: the file as a whole ---------------------------------------------------------------

TEST_F(HostileGltf, TextThatIsNotGltfJsonIsRefused) {
  const std::vector<std::string> texts = {
      "", " ", "{", "this is not json", "[]", "null", "42", "{}", R"({"asset":{}})",
      R"({"asset":{"version":"2.0"}})",  // valid, but nothing to render
      R"({"asset":{"version":"2.0"},"nodes":[{"matrix":[NaN,0,0,0, 0,1,0,0, 0,0,1,0, 0,0,0,1]}]})",
      R"({"asset":{"version":"2.0"},"buffers":[{"byteLength":1e400}]})",
      "{\"asset\":{\"version\":\"2.0\"},\"nodes\":[{\"name\":\"\xff\xfe\"}]}",
      std::string("{\"asset\":\0{}}", 13), Gltf().json().substr(0, 200)};
  Batch batch;
  for (size_t i = 0; i < texts.size(); ++i) {
    const std::string path = write("text" + std::to_string(i) + ".gltf", texts[i]);
    batch.read(path, [path](const Outcome& o) { expectRefused(o, path); });
  }
  batch.run();
}

TEST_F(HostileGltf, EmptyFilesOfEveryModelExtensionAreRefused) {
  Batch batch;
  for (const char* name : {"empty.gltf", "empty.glb", "empty.obj", "empty.fbx", "empty.dae",
                           "empty.ply", "empty.stl"}) {
    const std::string path = write(name, "");
    batch.read(path, [path](const Outcome& o) { expectRefused(o, path); });
  }
  batch.run();
}

TEST_F(HostileGltf, ADirectoryNamedLikeAModelIsRefused) {
  const std::string path = (dir_ / "x.glb").string();
  fs::create_directories(path);
  const Outcome read = readIsolated(path);
  EXPECT_REFUSED(read, path);
  EXPECT_TRUE(contains(read.message, "not a regular file")) << read;
  const Outcome o = loadIsolated(sceneImporting(path));
  EXPECT_EQ(o.kind, Kind::inputError) << o;
  EXPECT_TRUE(contains(o.message, path)) << o;
  const Outcome direct = loadIsolated(path);
  EXPECT_EQ(direct.kind, Kind::inputError) << direct;
  EXPECT_TRUE(contains(direct.message, path)) << direct;
}

TEST_F(HostileGltf, TheMinimalFileIsRead) {
  // The base every hostile variant below starts from must itself be good.
  Batch batch;
  const std::string path = write("good.gltf", Gltf().json());
  const std::string binary = write("good.glb", glb(glbJson(), triangleBytes()));
  for (const std::string& p : {path, binary}) {
    batch.read(p, [](const Outcome& o) {
      EXPECT_EQ(o.kind, Kind::returned) << o;
      EXPECT_EQ(o.message, "objects 1, lights 0, cameras 0, textures 0");
    });
  }
  batch.run();
}

// --- binary glTF -----------------------------------------------------------------------------

TEST_F(HostileGltf, GlbHeadersThatLieAboutTheirLengthsAreRefused) {
  const std::string good = glb(glbJson(), triangleBytes());
  const auto jsonLength = static_cast<uint32_t>(good.size() - 20 - 8 - 44);
  std::vector<std::pair<std::string, std::string>> cases;
  cases.emplace_back("magic-only.glb", "glTF");
  cases.emplace_back("header-only.glb", good.substr(0, 12));
  cases.emplace_back("no-json.glb", good.substr(0, 20));
  auto patched = [&](size_t at, uint32_t v) {
    std::string s = good;
    putU32(s, at, v);
    return s;
  };
  cases.emplace_back("length-too-long.glb", patched(8, static_cast<uint32_t>(good.size() + 4)));
  cases.emplace_back("length-huge.glb", patched(8, 0xFFFFFFFFu));
  cases.emplace_back("length-short.glb", patched(8, 20));
  cases.emplace_back("json-too-long.glb", patched(12, static_cast<uint32_t>(good.size())));
  cases.emplace_back("json-wraps.glb", patched(12, 0xFFFFFFF0u));  // 20 + length wraps in 32 bits
  cases.emplace_back("json-zero.glb", patched(12, 0));
  cases.emplace_back("json-not-json.glb", patched(16, 0x4E4F534B));
  const size_t bin = 20 + jsonLength;  // the BIN chunk's header
  cases.emplace_back("bin-huge.glb", patched(bin, 0xFFFFFFF0u));
  cases.emplace_back("bin-zero.glb", patched(bin, 0));
  cases.emplace_back("bin-odd.glb", patched(bin, 43));
  cases.emplace_back("bin-type.glb", patched(bin + 4, 0x12345678));
  // The file cut by 4 bytes and its header's length with it: the BIN chunk claims 4 more.
  cases.emplace_back("bin-cut.glb", patched(8, static_cast<uint32_t>(good.size() - 4)).substr(0, good.size() - 4));
  Batch batch;
  for (const auto& [name, bytes] : cases) {
    const std::string path = write(name, bytes);
    batch.read(path, [path](const Outcome& o) { expectRefused(o, path); });
  }
  batch.run();
}

// The BIN chunk's length counts from the end of the JSON chunk instead of from its own data,
// so that it claims the 8 bytes after the file: the buffer that takes the whole chunk must not
// be copied from beyond the file.
TEST_F(HostileGltf, GlbBinChunkReachingEightBytesPastTheFileIsRefused) {
  std::string bytes = glb(R"({"asset":{"version":"2.0"},"buffers":[{"byteLength":52}]})", triangleBytes());
  const size_t bin = 20 + (bytes.size() - 20 - 8 - 44);
  putU32(bytes, bin, 44 + 8);
  const std::string path = write("bin-past-end.glb", bytes);
  const Outcome o = readIsolated(path);
  EXPECT_NE(o.kind, Kind::crashed) << o;
  EXPECT_REFUSED(o, path);
}

// Prefixes of a real file: every size up to 256 bytes (the header and the JSON's start), then
// every 7th, then the last 64.
TEST_F(HostileGltf, PrefixesOfARealGlbAreRefused) {
  const std::string real = readAll(kSource / "tests/models/blender-cube.glb");
  ASSERT_GT(real.size(), 1000u);
  const std::string path = (dir_ / "prefix.glb").string();
  const Outcome o = isolated([&]() -> Report {
    std::vector<size_t> sizes;
    for (size_t n = 0; n < real.size(); n += n < 256 ? 1 : 7) sizes.push_back(n);
    for (size_t n = real.size() - 64; n < real.size(); ++n) sizes.push_back(n);
    for (const size_t n : sizes) {
      std::ofstream(path, std::ios::binary | std::ios::trunc).write(real.data(), static_cast<std::streamsize>(n));
      const Report r = readReport(path, {}, nullptr);
      if (r.kind != Kind::modelError || !contains(r.message, path)) {
        return {Kind::otherError, "prefix of " + std::to_string(n) + " bytes: " + kindName(r.kind) + ": " + r.message, {}};
      }
    }
    return {Kind::modelError, std::to_string(sizes.size()) + " prefixes refused", {}};
  });
  EXPECT_EQ(o.kind, Kind::modelError) << o;
}

TEST_F(HostileGltf, ByteFlipsOfARealGlbNeverCrash) {
  const std::string real = readAll(kSource / "tests/models/blender-cube.glb");
  const std::string path = (dir_ / "flipped.glb").string();
  const Outcome o = isolated([&]() -> Report {
    std::mt19937 random(20240611);
    for (int round = 0; round < 300; ++round) {
      std::string bytes = real;
      const int flips = 1 + static_cast<int>(random() % 3);
      for (int f = 0; f < flips; ++f) {
        bytes[random() % bytes.size()] ^= static_cast<char>(1 + random() % 255);
      }
      std::ofstream(path, std::ios::binary | std::ios::trunc).write(bytes.data(), static_cast<std::streamsize>(bytes.size()));
      const Report r = readReport(path, {}, nullptr);
      const bool named = r.kind == Kind::modelError ? contains(r.message, path) : true;
      if ((r.kind != Kind::modelError && r.kind != Kind::returned) || !named) {
        return {Kind::otherError, "round " + std::to_string(round) + ": " + kindName(r.kind) + ": " + r.message, {}};
      }
      for (const std::string& w : r.warnings) {
        if (!contains(w, path)) return {Kind::otherError, "a warning not naming the file: " + w, {}};
      }
    }
    return {Kind::returned, "", {}};
  });
  EXPECT_EQ(o.kind, Kind::returned) << o;
}

// blender-cube.glb with its image's buffer view moved from byte 840 to 868 of its 2636-byte
// buffer (what the model fuzzer found): the image's last 27 bytes lie beyond the buffer.
TEST_F(HostileGltf, ARealGlbWhoseImageReachesPastItsBufferIsRefused) {
  std::string bytes = readAll(kSource / "tests/models/blender-cube.glb");
  const std::string from = R"({"buffer":0,"byteLength":1795,"byteOffset":840})";
  const size_t at = bytes.find(from);
  ASSERT_NE(at, std::string::npos);
  bytes.replace(at, from.size(), R"({"buffer":0,"byteLength":1795,"byteOffset":868})");
  const std::string path = write("image-past-buffer.glb", bytes);
  const Outcome o = readIsolated(path);
  EXPECT_NE(o.kind, Kind::crashed) << o;
  if (o.kind == Kind::modelError) {
    EXPECT_REFUSED(o, path);
  } else {
    EXPECT_READ_WITH_WARNING(o, path, "image");
  }
}

// --- accessors, buffer views, buffers --------------------------------------------------------

TEST_F(HostileGltf, AccessorsReachingPastTheirBufferViewSkipTheirPrimitive) {
  const std::vector<std::pair<std::string, std::string>> accessors = {
      {"offset", R"({"bufferView":0,"byteOffset":28,"componentType":5126,"count":3,"type":"VEC3"})"},
      {"offset-huge", R"({"bufferView":0,"byteOffset":18446744073709551615,"componentType":5126,"count":3,"type":"VEC3"})"},
      {"count", R"({"bufferView":0,"componentType":5126,"count":4,"type":"VEC3"})"},
      {"count-wraps", R"({"bufferView":0,"componentType":5126,"count":1537228672809129302,"type":"VEC3"})"},
      {"stride", R"({"bufferView":2,"componentType":5126,"count":3,"type":"VEC3"})"},
      {"type", R"({"bufferView":0,"componentType":5126,"count":3,"type":"MAT4"})"},
  };
  Batch batch;
  for (const auto& [name, accessor] : accessors) {
    Gltf g;
    g.accessors += "," + accessor;
    g.bufferViews += R"(,{"buffer":0,"byteOffset":0,"byteLength":36,"byteStride":16})";
    g.withSecondMesh(R"({"attributes":{"POSITION":2},"indices":1})");
    const std::string path = write(name + ".gltf", g.json());
    batch.read(path, [path](const Outcome& o) {
      EXPECT_EQ(o.kind, Kind::returned) << o;
      EXPECT_EQ(o.message, "objects 1, lights 0, cameras 0, textures 0");
      EXPECT_TRUE(anyContains(o.warnings, path)) << o;
    });
    // Alone in its file, the bad primitive leaves nothing to render.
    Gltf alone;
    alone.accessors = R"({"bufferView":0,"componentType":5126,"count":3,"type":"VEC3"},)"
                      R"({"bufferView":1,"componentType":5123,"count":3,"type":"SCALAR"},)" + accessor;
    alone.bufferViews = g.bufferViews;
    alone.meshes = R"({"primitives":[{"attributes":{"POSITION":2},"indices":1}]})";
    const std::string lonely = write(name + "-alone.gltf", alone.json());
    batch.read(lonely, [lonely](const Outcome& o) { expectRefused(o, lonely); });
  }
  Gltf g;
  g.accessors += R"(,{"bufferView":0,"byteOffset":28,"componentType":5126,"count":3,"type":"VEC3"})";
  g.withSecondMesh(R"({"attributes":{"POSITION":2},"indices":1})");
  const std::string path = write("offset-warning.gltf", g.json());
  batch.read(path, [path](const Outcome& o) { EXPECT_READ_WITH_WARNING(o, path, "reaches past its buffer view"); });
  batch.run();
}

TEST_F(HostileGltf, BufferViewsReachingPastTheirBufferSkipTheirPrimitive) {
  Batch batch;
  int k = 0;
  for (const std::string view : {R"({"buffer":0,"byteOffset":40,"byteLength":36})",
                                 R"({"buffer":0,"byteOffset":0,"byteLength":45})",
                                 R"({"buffer":0,"byteOffset":18446744073709551600,"byteLength":36})",
                                 R"({"buffer":0,"byteOffset":8,"byteLength":18446744073709551612})",
                                 R"({"buffer":7,"byteOffset":0,"byteLength":36})"}) {
    Gltf g;
    g.bufferViews += "," + view;
    g.accessors += R"(,{"bufferView":2,"componentType":5126,"count":3,"type":"VEC3"})";
    g.withSecondMesh(R"({"attributes":{"POSITION":2},"indices":1})");
    const std::string path = write("view" + std::to_string(k++) + ".gltf", g.json());
    batch.read(path, [path, view](const Outcome& o) {
      // tinygltf may refuse the view itself; PRT's own check skips the primitive.
      if (o.kind == Kind::modelError) {
        EXPECT_REFUSED(o, path) << view;
      } else {
        EXPECT_EQ(o.kind, Kind::returned) << view << ": " << o;
        EXPECT_EQ(o.message, "objects 1, lights 0, cameras 0, textures 0") << view;
        EXPECT_TRUE(anyContains(o.warnings, "buffer")) << view << ": " << o;
      }
    });
  }
  batch.run();
}

TEST_F(HostileGltf, IndicesOutOfRangeSkipTheirTriangles) {
  std::string bytes = triangleBytes();
  bytes.resize(36);
  for (const uint16_t i : std::initializer_list<uint16_t>{0, 1, 2, 0, 1, 3, 65535, 0, 1}) append(bytes, i);  // 3 triangles, 2 bad
  bytes.resize(56, '\0');
  Gltf g;
  g.buffers = R"({"byteLength":56,"uri":")" + dataUri(bytes) + R"("})";
  g.bufferViews = R"({"buffer":0,"byteOffset":0,"byteLength":36},{"buffer":0,"byteOffset":36,"byteLength":18})";
  g.accessors = R"({"bufferView":0,"componentType":5126,"count":3,"type":"VEC3"},)"
                R"({"bufferView":1,"componentType":5123,"count":9,"type":"SCALAR"})";
  const std::string path = write("indices.gltf", g.json());
  const Outcome o = readIsolated(path, {}, [](const ImportedModel& m) {
    return "triangles " + std::to_string(std::get<InstanceShape>(m.objects.at(0).shape).mesh->triangles.size());
  });
  EXPECT_READ_WITH_WARNING(o, path, "skipped 2 triangles with a vertex index out of range");
  EXPECT_EQ(o.message, "triangles 1");
}

TEST_F(HostileGltf, IndexAccessorsThatAreNotUnsignedIntegersSkipTheirPrimitive) {
  Batch batch;
  int k = 0;
  for (const std::string type : {R"("componentType":5126,"count":1,"type":"SCALAR")",   // FLOAT
                                 R"("componentType":5122,"count":3,"type":"SCALAR")",   // SHORT
                                 R"("componentType":5123,"count":1,"type":"VEC3")"}) {  // not scalar
    Gltf g;
    g.accessors += R"(,{"bufferView":2,)" + type + "}";
    g.bufferViews += R"(,{"buffer":0,"byteOffset":32,"byteLength":12})";
    g.withSecondMesh(R"({"attributes":{"POSITION":0},"indices":2})");
    const std::string path = write("indices" + std::to_string(k++) + ".gltf", g.json());
    batch.read(path, [path](const Outcome& o) { EXPECT_READ_WITH_WARNING(o, path, "indices"); });
  }
  batch.run();
}

TEST_F(HostileGltf, HugeDeclaredCountsAreRefusedWithoutAllocating) {
  Batch batch;
  int k = 0;
  for (const std::string count : {"1099511627776", "4294967296", "18446744073709551615"}) {
    for (const std::string view : {R"("bufferView":0,)", ""}) {
      Gltf g;
      g.accessors += R"(,{)" + view + R"("componentType":5126,"count":)" + count + R"(,"type":"VEC3"})";
      g.withSecondMesh(R"({"attributes":{"POSITION":2}})");
      const std::string path = write("count" + std::to_string(k++) + ".gltf", g.json());
      batch.read(path, [path](const Outcome& o) {
        EXPECT_LT(o.peakGrowthKb, 256 * 1024) << o;
        if (o.kind == Kind::modelError) {
          EXPECT_TRUE(contains(o.message, path)) << o;
        } else {
          EXPECT_EQ(o.kind, Kind::returned) << o;
        }
      });
    }
  }
  batch.run();
}

// An accessor without a buffer view is all zeros (glTF 2.0, 3.6.2.3): 2^31 of them pass the
// reader's limit on elements, and must not be expanded into 48 GiB of vertices, nor 2^24 into
// 0.6 GiB, for a file of 300 bytes.
TEST_F(HostileGltf, AccessorsWithoutBufferViewDoNotExpandIntoGigabytes) {
  Batch batch;
  for (const std::string count : {"2147483648", "16777216"}) {
    Gltf g;
    g.accessors += R"(,{"componentType":5126,"count":)" + count + R"(,"type":"VEC3"})";
    g.withSecondMesh(R"({"attributes":{"POSITION":2}})");
    const std::string path = write("zeros" + count + ".gltf", g.json());
    batch.read(path, [](const Outcome& o) {
      EXPECT_TRUE(o.kind == Kind::returned || o.kind == Kind::modelError) << o;
      EXPECT_LT(o.peakGrowthKb, 256 * 1024) << o;
      EXPECT_LT(o.seconds, 5) << o;
    });
  }
  batch.run(30);
}

// Sparse accessors (glTF 2.0, 3.6.2.3) whose indices or values lie: each skips its primitive
// with a warning saying what is wrong. The buffer: the triangle's 36 bytes of floats, then the
// indices 0, 1, 2, 0 as 16-bit numbers; view 2 reads 1, 2, 0 (not rising).
TEST_F(HostileGltf, SparseAccessorsThatLieSkipTheirPrimitive) {
  // The triangle's three vertices, a sparse part of `count` elements over them.
  auto sparse = [](const std::string& count, const std::string& indices, const std::string& values) {
    std::string a = R"("bufferView":0,"componentType":5126,"count":3,"type":"VEC3","sparse":{"count":)";
    a += count;
    a += R"(,"indices":{)";
    a += indices;
    a += R"(},"values":{)";
    a += values;
    a += "}}";
    return a;
  };
  const std::string ushorts = R"("bufferView":1,"componentType":5123)";
  const std::string floats = R"("bufferView":0)";
  const std::vector<std::tuple<std::string, std::string, std::string>> cases = {
      {"not-rising", sparse("3", R"("bufferView":2,"componentType":5123)", floats),
       "indices do not rise"},
      {"count-zero", sparse("0", ushorts, floats),
       "count 0 is not between 1 and the accessor's count, 3"},
      {"count-over", sparse("4", ushorts, floats),
       "count 4 is not between 1 and the accessor's count, 3"},
      {"index-type", sparse("1", R"("bufferView":1,"componentType":5126)", floats),
       "indices are not unsigned integers"},
      {"indices-past", sparse("2", R"("bufferView":1,"byteOffset":4,"componentType":5123)", floats),
       "sparse indices reaches past its buffer view"},
      {"values-past", sparse("1", ushorts, R"("bufferView":1)"),
       "sparse values reaches past its buffer view"},
      {"negative", sparse("1", R"("bufferView":1,"byteOffset":-2,"componentType":5123)", floats),
       "negative byte offset"},
      {"no-view", sparse("1", R"("bufferView":9,"componentType":5123)", floats),
       "names buffer view 9, which does not exist"},
      {"zeros-huge", R"("componentType":5126,"count":2147483648,"type":"VEC3","sparse":)"
                     R"({"count":1,"indices":{"bufferView":1,"componentType":5123},"values":{"bufferView":0}})",
       "has no buffer view and 2147483648 elements"},
  };
  Batch batch;
  for (const auto& [name, accessor, why] : cases) {
    Gltf g;
    g.accessors += ",{" + accessor + "}";
    g.bufferViews += R"(,{"buffer":0,"byteOffset":38,"byteLength":6})";
    g.withSecondMesh(R"({"attributes":{"POSITION":2},"indices":1})");
    const std::string path = write("sparse-" + name + ".gltf", g.json());
    batch.read(path, [path, why](const Outcome& o) {
      EXPECT_READ_WITH_WARNING(o, path, why);
      EXPECT_EQ(o.message, "objects 1, lights 0, cameras 0, textures 0");
    });
  }
  // Zeros (no buffer view) with every vertex replaced: a triangle like the first; and as many
  // zeros as PRT fills, one of them replaced, in bounded time and memory.
  for (const std::string count : {"3", "1048576"}) {
    Gltf g;
    g.accessors += R"(,{"componentType":5126,"count":)" + count + R"(,"type":"VEC3","sparse":)"
                   R"({"count":3,"indices":{"bufferView":1,"componentType":5123},"values":{"bufferView":0}}})";
    g.withSecondMesh(R"({"attributes":{"POSITION":2},"indices":1})");
    const std::string path = write("sparse-zeros-" + count + ".gltf", g.json());
    batch.read(path, [](const Outcome& o) {
      EXPECT_EQ(o.kind, Kind::returned) << o;
      EXPECT_EQ(o.message, "objects 2, lights 0, cameras 0, textures 0");
      EXPECT_LT(o.peakGrowthKb, 256 * 1024) << o;
      EXPECT_LT(o.seconds, 5) << o;
    });
  }
  batch.run(30);
}

// Morph targets (glTF 2.0, 3.7.2.2). The target moves vertex 0 by (1, 0, 0): sparse over zeros,
// its one value the triangle's second vertex. Node weights override the mesh's; each distinct
// set of weights is a mesh of its own, and equal ones share one.
namespace morph {
const std::string kTarget = R"({"componentType":5126,"count":3,"type":"VEC3","sparse":{"count":1,)"
                            R"("indices":{"bufferView":1,"componentType":5123},"values":{"bufferView":0,"byteOffset":12}}})";
std::string facts(const ImportedModel& m) {
  std::string out;
  std::set<const TriangleMesh*> meshes;
  for (const Object& o : m.objects) {
    const Bounds box = boundsOf(o.shape);
    char range[64];
    std::snprintf(range, sizeof range, "[%f %f]", box.lo.x, box.hi.x);
    out += range;
    meshes.insert(std::get<InstanceShape>(o.shape).mesh.get());
  }
  return out + " meshes " + std::to_string(meshes.size());
}
}  // namespace morph

TEST_F(HostileGltf, MorphTargetsMoveTheVerticesByTheirWeights) {
  Gltf g;
  g.accessors += "," + morph::kTarget;
  g.meshes = R"({"primitives":[{"attributes":{"POSITION":0},"indices":1,"targets":[{"POSITION":2}]}],"weights":[-1]})";
  g.scenes = R"("scene":0,"scenes":[{"nodes":[0,1,2,3,4]}])";
  // The mesh's weight; 2; 2 again; 0 (the stored shape); more weights than targets.
  g.nodes = R"({"mesh":0},{"mesh":0,"weights":[2]},{"mesh":0,"weights":[2]},{"mesh":0,"weights":[0]},)"
            R"({"mesh":0,"weights":[-1,5]})";
  const std::string path = write("morph.gltf", g.json());
  const Outcome o = readIsolated(path, {}, morph::facts);
  EXPECT_EQ(o.kind, Kind::returned) << o;
  EXPECT_TRUE(o.warnings.empty()) << o;
  EXPECT_EQ(o.message,
            "[-1.000000 1.000000][0.000000 2.000000][0.000000 2.000000][0.000000 1.000000]"
            "[-1.000000 1.000000] meshes 3");
}

TEST_F(HostileGltf, MorphTargetsThatCannotBeReadLeaveTheStoredShape) {
  Batch batch;
  const std::vector<std::pair<std::string, std::string>> targets = {
      {R"({"componentType":5126,"count":4,"type":"VEC3"})", "has a count unlike POSITION's"},
      {R"({"bufferView":0,"componentType":5126,"count":3,"type":"VEC2"})", "is not 3-vectors"},
      {R"({"bufferView":0,"byteOffset":24,"componentType":5126,"count":3,"type":"VEC3"})",
       "reaches past its buffer view"},
  };
  int k = 0;
  for (const auto& [target, why] : targets) {
    Gltf g;
    g.accessors += "," + target;
    g.withSecondMesh(R"({"attributes":{"POSITION":0},"indices":1,"targets":[{"POSITION":2}]})");
    g.meshes = R"({"primitives":[{"attributes":{"POSITION":0},"indices":1}]},)"
               R"({"primitives":[{"attributes":{"POSITION":0},"indices":1,"targets":[{"POSITION":2}]}],"weights":[1]})";
    const std::string path = write("morph-bad" + std::to_string(k++) + ".gltf", g.json());
    batch.read(path, [path, why](const Outcome& o) {
      EXPECT_READ_WITH_WARNING(o, path, "morph target 0 POSITION");
      EXPECT_READ_WITH_WARNING(o, path, why);
      EXPECT_READ_WITH_WARNING(o, path, "rendered in its stored shape");
      EXPECT_EQ(o.message, "[0.000000 1.000000][0.000000 1.000000] meshes 2");
    }, {}, morph::facts);
  }
  // A NORMAL target on a primitive without normals is not read: its faults do not matter.
  Gltf normal;
  normal.accessors += R"(,{"bufferView":0,"componentType":5126,"count":3,"type":"VEC2"})";
  normal.meshes = R"({"primitives":[{"attributes":{"POSITION":0},"indices":1,"targets":[{"NORMAL":2}]}],"weights":[1]})";
  const std::string normalPath = write("morph-normal.gltf", normal.json());
  batch.read(normalPath, [](const Outcome& o) {
    EXPECT_EQ(o.kind, Kind::returned) << o;
    EXPECT_TRUE(o.warnings.empty()) << o;
  });
  // A target of zeros moves nothing, whatever its weight.
  Gltf zeros;
  zeros.accessors += R"(,{"componentType":5126,"count":3,"type":"VEC3"})";
  zeros.meshes = R"({"primitives":[{"attributes":{"POSITION":0},"indices":1,"targets":[{"POSITION":2}]}],"weights":[7]})";
  const std::string zerosPath = write("morph-zeros.gltf", zeros.json());
  batch.read(zerosPath, [](const Outcome& o) {
    EXPECT_EQ(o.kind, Kind::returned) << o;
    EXPECT_EQ(o.message, "[0.000000 1.000000] meshes 1");
  }, {}, morph::facts);
  batch.run();
}

// One dense target of 65,536 vertices named 1,100 times: 72 million moves from a file of one
// megabyte; PRT stops at 2^26 and renders the stored shape, with a warning.
TEST_F(HostileGltf, MorphTargetsMovingTooManyVerticesLeaveTheStoredShape) {
  constexpr int kVertices = 65536;
  std::string bytes;
  for (int i = 0; i < kVertices; ++i) {
    const float x = i == 1 ? 1.f : 0.f, y = i == 2 ? 1.f : 0.f;
    for (const float f : {x, y, 0.f}) append(bytes, f);
  }
  for (const uint16_t i : std::initializer_list<uint16_t>{0, 1, 2, 0}) append(bytes, i);
  Gltf g;
  g.buffers = R"({"byteLength":)" + std::to_string(bytes.size()) + R"(,"uri":")" + dataUri(bytes) + R"("})";
  g.bufferViews = R"({"buffer":0,"byteOffset":0,"byteLength":786432},)"
                  R"({"buffer":0,"byteOffset":786432,"byteLength":6})";
  g.accessors = R"({"bufferView":0,"componentType":5126,"count":65536,"type":"VEC3"},)"
                R"({"bufferView":1,"componentType":5123,"count":3,"type":"SCALAR"})";
  std::string targets, weights;
  for (int k = 0; k < 1100; ++k) {
    targets += std::string(k ? "," : "") + R"({"POSITION":0})";
    weights += std::string(k ? "," : "") + "0.0001";
  }
  g.meshes = R"({"primitives":[{"attributes":{"POSITION":0},"indices":1,"targets":[)" + targets +
             R"(]}],"weights":[)" + weights + "]}";
  const std::string path = write("morph-moves.gltf", g.json());
  const Outcome o = readIsolated(path, {}, morph::facts);
  EXPECT_READ_WITH_WARNING(o, path, "past the 67108864 PRT moves for one file");
  EXPECT_READ_WITH_WARNING(o, path, "rendered in its stored shape");
  EXPECT_EQ(o.message, "[0.000000 1.000000] meshes 1");
  EXPECT_LT(o.seconds, 10) << o;
}

// Each distinct set of weights copies the mesh: 2^20 vertices (zeros, three of them replaced)
// and three indices placed with nine different weights pass the budget of 2^23 copied
// elements seven times; the last two are the stored shape, with a warning.
TEST_F(HostileGltf, MorphedCopiesStopAtABudgetOfVertices) {
  Gltf g;
  g.accessors = R"({"componentType":5126,"count":1048576,"type":"VEC3","sparse":{"count":3,)"
                R"("indices":{"bufferView":1,"componentType":5123},"values":{"bufferView":0}}},)"
                R"({"bufferView":1,"componentType":5123,"count":3,"type":"SCALAR"},)"
                R"({"componentType":5126,"count":1048576,"type":"VEC3","sparse":{"count":1,)"
                R"("indices":{"bufferView":1,"componentType":5123},"values":{"bufferView":0,"byteOffset":12}}})";
  g.meshes = R"({"primitives":[{"attributes":{"POSITION":0},"indices":1,"targets":[{"POSITION":2}]}]})";
  g.scenes = R"("scene":0,"scenes":[{"nodes":[0,1,2,3,4,5,6,7,8]}])";
  g.nodes.clear();
  std::string expected;
  for (int w = 2; w <= 10; ++w) {
    g.nodes += std::string(w > 2 ? "," : "") + R"({"mesh":0,"weights":[)" + std::to_string(w) + "]}";
    char range[64];
    std::snprintf(range, sizeof range, "[%f %f]", 0.0, w <= 8 ? static_cast<double>(w) : 1.0);
    expected += range;
  }
  const std::string path = write("morph-budget.gltf", g.json());
  const Outcome o = readIsolated(path, {}, morph::facts);
  EXPECT_READ_WITH_WARNING(o, path, "2 placements of a mesh with morph weights of its own");
  EXPECT_EQ(o.message, expected + " meshes 8");
  EXPECT_LT(o.seconds, 10) << o;
}

// --- the node tree ---------------------------------------------------------------------------

TEST_F(HostileGltf, NodeCyclesAreRefused) {
  const std::vector<std::pair<std::string, std::string>> cases = {
      {"two", R"({"mesh":0,"children":[1]},{"children":[0]})"},
      {"self", R"({"mesh":0,"children":[0]})"},
      {"deep", R"({"mesh":0,"children":[1]},{"children":[2]},{"children":[3]},{"children":[1]})"}};
  Batch batch;
  for (const auto& [name, nodes] : cases) {
    Gltf g;
    g.nodes = nodes;
    const std::string path = write(name + ".gltf", g.json());
    batch.read(path, [path](const Outcome& o) {
      EXPECT_REFUSED(o, path);
      // Found as a cycle, or as a node with two parents.
      EXPECT_TRUE(contains(o.message, "cycle") || contains(o.message, "parent")) << o;
    });
    // Without a scene, the roots are the nodes that are nobody's child: none here.
    g.scenes = R"("extensionsUsed":[])";
    const std::string sceneless = write(name + "-sceneless.gltf", g.json());
    batch.read(sceneless, [sceneless](const Outcome& o) { expectRefused(o, sceneless); });
  }
  batch.run(10);
}

// glTF's nodes form a forest: no node has two parents. A file where each of 40 nodes lists the
// next twice is no cycle, but its paths from the root number 2^40.
TEST_F(HostileGltf, NodesSharedByManyParentsDoNotMultiplyTheWork) {
  std::string nodes = R"({"mesh":0,"children":[1,1]})";
  for (int i = 1; i < 40; ++i) {
    nodes += R"(,{"children":[)" + std::to_string(i + 1) + "," + std::to_string(i + 1) + "]}";
  }
  nodes += R"(,{"translation":[1,0,0]})";
  Gltf g;
  g.nodes = nodes;
  const std::string path = write("shared.gltf", g.json());
  const Outcome o = readIsolated(path, {}, nullptr, 10);
  EXPECT_TRUE(o.kind == Kind::returned || o.kind == Kind::modelError) << o;
  EXPECT_LT(o.seconds, 5) << o;
  if (o.kind == Kind::modelError) {
    EXPECT_TRUE(contains(o.message, path)) << o;
  }
}

TEST_F(HostileGltf, IndicesOfNodesAndMeshesOutOfRangeAreRefused) {
  const std::vector<std::pair<std::string, std::function<void(Gltf&)>>> cases = {
      {"root", [](Gltf& g) { g.scenes = R"("scene":0,"scenes":[{"nodes":[5]}])"; }},
      {"root-negative", [](Gltf& g) { g.scenes = R"("scene":0,"scenes":[{"nodes":[-2]}])"; }},
      {"root-huge", [](Gltf& g) { g.scenes = R"("scene":0,"scenes":[{"nodes":[2147483647]}])"; }},
      {"child", [](Gltf& g) { g.nodes = R"({"mesh":0,"children":[9]})"; }},
      {"mesh", [](Gltf& g) { g.nodes = R"({"mesh":7})"; }},
      {"mesh-huge", [](Gltf& g) { g.nodes = R"({"mesh":2147483647})"; }},
  };
  Batch batch;
  for (const auto& [name, change] : cases) {
    Gltf g;
    change(g);
    const std::string path = write(name + ".gltf", g.json());
    batch.read(path, [path](const Outcome& o) {
      EXPECT_REFUSED(o, path);
      EXPECT_TRUE(contains(o.message, "does not exist")) << o;
    });
  }
  // A default scene index out of range falls back to the first scene.
  Gltf g;
  g.scenes = R"("scene":9,"scenes":[{"nodes":[0]}])";
  batch.read(write("scene.gltf", g.json()), [](const Outcome& o) { EXPECT_EQ(o.kind, Kind::returned) << o; });
  batch.run();
}

TEST_F(HostileGltf, MaterialTextureImageAndSamplerIndicesOutOfRangeWarn) {
  const std::string image = R"({"uri":")" + dataUri(png(2, 2, 2)) + R"("})";
  const std::vector<std::tuple<std::string, std::string, std::string, std::string>> cases = {
      {"texture", "", "", R"("index":3)"},
      {"texture-huge", "", "", R"("index":2147483647)"},
      {"image", R"({"source":4})", "", R"("index":0)"},
      {"image-negative", R"({"source":-3})", "", R"("index":0)"},
  };
  Batch batch;
  ModelReadOptions strict;
  strict.strict = true;
  for (const auto& [name, textures, images, info] : cases) {
    const std::string path = write(name + ".gltf", texturedGltf(textures, images, "", info));
    batch.read(path, [path](const Outcome& o) { EXPECT_READ_WITH_WARNING(o, path, "does not exist"); });
    batch.read(path, [path](const Outcome& o) { expectRefused(o, path); }, strict);
  }
  // A sampler out of range: the texture is sampled as glTF's default says.
  batch.read(write("sampler.gltf", texturedGltf(R"({"source":0,"sampler":6})", image)), [](const Outcome& o) {
    EXPECT_EQ(o.message, "objects 1, lights 0, cameras 0, textures 1") << o;
  });
  // A material out of range: PRT's default material.
  Gltf g;
  g.meshes = R"({"primitives":[{"attributes":{"POSITION":0},"indices":1,"material":12}]})";
  batch.read(write("material.gltf", g.json()), [](const Outcome& o) { EXPECT_EQ(o.kind, Kind::returned) << o; });
  batch.run();
}

TEST_F(HostileGltf, TextureImagesThatAreNotImagesWarn) {
  write("not-an-image.png", "this is text, not a PNG");
  write("truncated.png", png(4, 4, 4).substr(0, 40));
  write("tiny.png", png(2, 2, 2));
  Batch batch;
  int k = 0;
  for (const std::string& uri : std::vector<std::string>{"not-an-image.png", "truncated.png", "missing.png",
                                dataUri("plain bytes"), "data:image/png;base64,",
                                "data:image/png;base64,!!!!", "data:image/png,notbase64"}) {
    const std::string path = write("image" + std::to_string(k++) + ".gltf",
                                   texturedGltf(R"({"source":0})", R"({"uri":")" + uri + R"("})"));
    batch.read(path, [path, uri](const Outcome& o) {
      if (o.kind == Kind::modelError) {
        EXPECT_REFUSED(o, path) << uri;
      } else {
        EXPECT_EQ(o.kind, Kind::returned) << uri << ": " << o;
        EXPECT_EQ(o.message, "objects 1, lights 0, cameras 0, textures 0") << uri;
        EXPECT_TRUE(anyContains(o.warnings, path)) << uri << ": " << o;
      }
    });
  }
  batch.read(write("good.gltf", texturedGltf(R"({"source":0})", R"({"uri":"tiny.png"})")), [](const Outcome& o) {
    EXPECT_EQ(o.message, "objects 1, lights 0, cameras 0, textures 1") << o;
  });
  batch.run();
}

// Image URIs as other tools write them, for a file that sits beside the model: found as the
// OBJ and FBX readers find their textures (texture_file.h, findTextureFile).
TEST_F(HostileGltf, TextureImagesAreFoundAsOtherToolsWriteTheirPaths) {
  write("tiny.png", png(2, 2, 2));
  Batch batch;
  int k = 0;
  for (const std::string& uri : std::vector<std::string>{"/no/such/folder/tiny.png", "file:///no/such/tiny.png",
                                R"(sub\\tiny.png)", "TINY.PNG", "C:/Users/someone/tiny.png"}) {
    const std::string path = write("found" + std::to_string(k++) + ".gltf",
                                   texturedGltf(R"({"source":0})", R"({"uri":")" + uri + R"("})"));
    batch.read(path, [uri](const Outcome& o) {
      EXPECT_EQ(o.message, "objects 1, lights 0, cameras 0, textures 1") << uri << ": " << o;
      EXPECT_FALSE(anyContains(o.warnings, "not found")) << uri << ": " << o;
    });
  }
  batch.run();
}

// An image whose data: URI tinygltf cannot decode (a type it does not know, no data) made it
// refuse the whole file: the image is missing instead, with a warning (an error with
// --strict), and the other image of the file is still read; as .gltf and as .glb.
TEST_F(HostileGltf, ImagesWithUndecodableDataUrisAreMissingNotTheWholeFile) {
  const std::string good = R"({"uri":"data:image/png;base64,)" + base64(png(2, 2, 2)) + R"("})";
  const std::vector<std::string> bad = {R"({"uri":"data:image/webp;base64,UklGRg=="})",
                                        R"({"uri":"data:image/png;base64,"})",
                                        R"({"uri":"data:image/ktx2;base64,q0tUWCAyMLsNChoK"})"};
  for (const std::string& image : bad) {
    Gltf g;
    g.meshes = R"({"primitives":[{"attributes":{"POSITION":0},"indices":1,"material":0}]})";
    g.more = R"(,"materials":[{"pbrMetallicRoughness":{"baseColorTexture":{"index":1}},)"
             R"("emissiveTexture":{"index":0}}],"textures":[{"source":0},{"source":1}],"images":[)" +
             good + "," + image + "," + image + "]";
    for (const bool binary : {false, true}) {
      const std::string path =
          write(binary ? "undecodable.glb" : "undecodable.gltf", binary ? glb(g.json(), "") : g.json());
      const ImportedModel m = readModelFile(path);
      EXPECT_EQ(m.objects.size(), 1u) << image;
      EXPECT_EQ(m.textures.size(), 1u) << image;  // the good image, as the emission's texture
      bool warned = false;
      for (const std::string& w : m.warnings) warned |= contains(w, "image 1") && contains(w, "data: URI");
      EXPECT_TRUE(warned) << image << (m.warnings.empty() ? "" : ": " + m.warnings.front());
      ModelReadOptions strict;
      strict.strict = true;
      EXPECT_THROW(readModelFile(path, strict), ModelFileError) << image;
    }
  }
}

// An image in a buffer view that reaches past its buffer: tinygltf hands the image loader a
// pointer and the view's length without checking them against the buffer.
TEST_F(HostileGltf, ImageBufferViewsReachingPastTheirBufferAreRefused) {
  Batch batch;
  int k = 0;
  for (const std::string view : {R"({"buffer":0,"byteOffset":40,"byteLength":4096})",
                                 R"({"buffer":0,"byteOffset":4096,"byteLength":4})",
                                 R"({"buffer":0,"byteOffset":0,"byteLength":4294967296})",
                                 R"({"buffer":0,"byteOffset":0,"byteLength":3000000000})"}) {
    Gltf g;
    g.bufferViews += "," + view;
    g.meshes = R"({"primitives":[{"attributes":{"POSITION":0},"indices":1,"material":0}]})";
    g.more = R"(,"materials":[{"pbrMetallicRoughness":{"baseColorTexture":{"index":0}}}])"
             R"(,"textures":[{"source":0}],"images":[{"bufferView":2,"mimeType":"image/png"}])";
    const std::string path = write("image-view" + std::to_string(k++) + ".gltf", g.json());
    batch.read(path, [path, view](const Outcome& o) {
      EXPECT_NE(o.kind, Kind::crashed) << view << ": " << o;
      if (o.kind == Kind::modelError) {
        EXPECT_REFUSED(o, path) << view;
      } else {
        EXPECT_READ_WITH_WARNING(o, path, "image") << view;
      }
    });
  }
  batch.run();
}

TEST_F(HostileGltf, HugeImageHeadersAreRefusedBeforeDecoding) {
  write("huge.png", png(100000, 100000, 0));
  write("wide.png", png(40000, 1, 0));
  write("big.png", png(4096, 4096, 0));
  Batch batch;
  for (const std::string name : {"huge.png", "wide.png"}) {
    const std::string path = write(name + ".gltf", texturedGltf(R"({"source":0})", R"({"uri":")" + name + R"("})"));
    batch.read(path, [path, name](const Outcome& o) {
      EXPECT_READ_WITH_WARNING(o, path, name);
      EXPECT_EQ(o.message, "objects 1, lights 0, cameras 0, textures 0") << o;
    });
  }
  // A size within the side limit but beyond a small budget.
  const std::string path = write("big.gltf", texturedGltf(R"({"source":0})", R"({"uri":"big.png"})"));
  ModelReadOptions small;
  small.textureBudgetBytes = 1 << 20;
  batch.read(path, [path](const Outcome& o) { EXPECT_READ_WITH_WARNING(o, path, "budget"); }, small);
  batch.run();
}

// --- buffers and images that are not plain files ---------------------------------------------

TEST_F(HostileGltf, BufferDataUrisThatAreNotBase64AreRefused) {
  Batch batch;
  int k = 0;
  for (const std::string uri : {"data:application/octet-stream;base64,!!!!!!!!",
                                "data:application/octet-stream;base64,",
                                "data:application/octet-stream;base64,AAAA",  // 3 bytes, not 44
                                "data:application/octet-stream,plain",
                                "data:application/gltf-buffer;base64,%%%%"}) {
    Gltf g;
    g.buffers = R"({"byteLength":44,"uri":")" + uri + R"("})";
    const std::string path = write("uri" + std::to_string(k++) + ".gltf", g.json());
    batch.read(path, [path](const Outcome& o) { expectRefused(o, path); });
  }
  batch.run();
}

TEST_F(HostileGltf, BuffersThatAreMissingOrNotRegularFilesAreRefusedQuickly) {
  fifo("pipe.bin");
  fs::create_symlink("/dev/zero", dir_ / "zero.bin");
  fs::create_directories(dir_ / "folder.bin");
  std::string up;
  for (const auto& part : dir_) up += part.empty() || part == "/" ? "" : "../";
  Batch batch;
  int k = 0;
  for (const std::string& uri : {std::string("missing.bin"), std::string("pipe.bin"), std::string("zero.bin"),
                                 std::string("folder.bin"), up + "dev/zero", up + "dev/urandom",
                                 std::string("/dev/zero"), std::string("%2Fdev%2Fzero")}) {
    Gltf g;
    g.buffers = R"({"byteLength":44,"uri":")" + uri + R"("})";
    const std::string path = write("buffer" + std::to_string(k++) + ".gltf", g.json());
    batch.read(path, [path](const Outcome& o) {
      EXPECT_REFUSED(o, path);
      EXPECT_LT(o.seconds, 3) << o;
    });
  }
  // The same for an image: a warning, not a read of the FIFO or the device.
  for (const std::string uri : {"pipe.bin", "zero.bin", "folder.bin"}) {
    const std::string path = write("image" + std::to_string(k++) + ".gltf",
                                   texturedGltf(R"({"source":0})", R"({"uri":")" + uri + R"("})"));
    batch.read(path, [path](const Outcome& o) {
      EXPECT_EQ(o.kind, Kind::returned) << o;
      EXPECT_TRUE(anyContains(o.warnings, path)) << o;
      EXPECT_LT(o.seconds, 3) << o;
    });
  }
  batch.run(10);
}

// 400 images naming one 256 KiB file: a 10 KB model must not hold 100 MiB of copies of it,
// neither in what it returns nor while it reads.
TEST_F(HostileGltf, ManyImagesOfOneFileDoNotMultiplyTheMemory) {
  std::string blob(256 << 10, '\0');
  for (size_t i = 0; i < blob.size(); ++i) blob[i] = static_cast<char>(i * 2654435761u >> 24);
  write("blob.bin", blob);
  std::string images;
  for (int i = 0; i < 400; ++i) images += std::string(i ? "," : "") + R"({"uri":"blob.bin"})";
  Gltf g;
  g.more = R"(,"images":[)" + images + "]";
  const std::string path = write("images.gltf", g.json());
  const Outcome o = readIsolated(path);
  EXPECT_EQ(o.kind, Kind::returned) << o;
  EXPECT_LT(o.retainedKb, 16 * 1024) << o;
#ifndef PRT_HOSTILE_ASAN  // AddressSanitizer's quarantine keeps what was freed resident
  EXPECT_LT(o.peakGrowthKb, 64 * 1024) << o;
#endif
}

// --- numbers no scene can use ----------------------------------------------------------------

TEST_F(HostileGltf, NonFinitePositionsSkipTheirTriangles) {
  const float nan = std::numeric_limits<float>::quiet_NaN();
  const float inf = std::numeric_limits<float>::infinity();
  Batch batch;
  int k = 0;
  for (const float bad : {nan, inf, -inf}) {
    Gltf g;
    g.buffers += R"(,{"byteLength":44,"uri":")" + dataUri(triangleBytes(bad)) + R"("})";
    g.bufferViews += R"(,{"buffer":1,"byteOffset":0,"byteLength":36},{"buffer":1,"byteOffset":36,"byteLength":6})";
    g.accessors += R"(,{"bufferView":2,"componentType":5126,"count":3,"type":"VEC3"},)"
                   R"({"bufferView":3,"componentType":5123,"count":3,"type":"SCALAR"})";
    g.withSecondMesh(R"({"attributes":{"POSITION":2},"indices":3})");
    const std::string path = write("nan" + std::to_string(k++) + ".gltf", g.json());
    batch.read(path, [path](const Outcome& o) {
      EXPECT_READ_WITH_WARNING(o, path, "not finite");
      EXPECT_EQ(o.message, "objects 1, lights 0, cameras 0, textures 0");
    });
  }
  batch.run();
}

// A file whose only mesh is skipped is refused, and the refusal says why: the warnings that
// would have explained it are not shown once the file is refused.
TEST_F(HostileGltf, AFileLeftWithNoTrianglesSaysWhatWasSkippedAndWhy) {
  const std::string triangle = dataUri(triangleBytes(0));
  const std::string head = R"({"asset":{"version":"2.0"},"scenes":[{"nodes":[0]}],"nodes":[{"mesh":0}],)"
                           R"("meshes":[{"primitives":[{"attributes":{"POSITION":0}}]}],)"
                           R"("buffers":[{"byteLength":44,"uri":")" + triangle + R"("}],)"
                           R"("bufferViews":[{"buffer":0,"byteLength":36}],)";
  const std::string past = head + R"("accessors":[{"bufferView":0,"componentType":5126,"count":1000,"type":"VEC3"}]})";
  // A sparse index read from the bytes of 1.0f: 1065353216, far past the three vertices.
  const std::string sparse = head + R"("accessors":[{"bufferView":0,"componentType":5126,"count":3,"type":"VEC3",)"
                                    R"("sparse":{"count":1,"indices":{"bufferView":0,"byteOffset":12,"componentType":5125},)"
                                    R"("values":{"bufferView":0}}}]})";
  for (const auto& [name, json, why] :
       {std::tuple<std::string, std::string, std::string>{"past.gltf", past, "reaches past its buffer view"},
        {"sparse.gltf", sparse, "index 1065353216 is not below the count, 3"}}) {
    const std::string path = write(name, json);
    try {
      readModelFile(path);
      ADD_FAILURE() << name << " was read";
    } catch (const ModelFileError& e) {
      const std::string message = e.what();
      EXPECT_NE(message.find("has no triangles to render: "), std::string::npos) << message;
      EXPECT_NE(message.find(why), std::string::npos) << message;
    }
  }
}

TEST_F(HostileGltf, TransformsThatAreNotFiniteOrFlatHideTheirNodes) {
  const std::vector<std::pair<std::string, std::string>> cases = {
      {"zero-scale", R"({"mesh":1,"scale":[0,0,0]})"},
      {"flat", R"({"mesh":1,"scale":[1,1,0]})"},
      {"overflow", R"({"children":[2],"matrix":[1e300,0,0,0, 0,1e300,0,0, 0,0,1e300,0, 0,0,0,1]}, {"mesh":1,"scale":[1e300,1,1]})"},
      {"translation", R"({"mesh":1,"translation":[1e308,0,0],"children":[2]},{"translation":[1e308,0,0]})"},
      {"rotation", R"({"mesh":1,"rotation":[0,0,0,0]})"},
      {"rotation-huge", R"({"mesh":1,"rotation":[1e300,1e300,1e300,1e300]})"},
  };
  const Facts usable = [](const ImportedModel& m) {
    std::string facts = counts(m);
    for (const Object& object : m.objects) {
      if (!std::get<InstanceShape>(object.shape).worldFromMesh.isUsable()) facts += "; an unusable transform";
    }
    return facts;
  };
  Batch batch;
  for (const auto& [name, second] : cases) {
    Gltf g;
    g.nodes = R"({"mesh":0},)" + second;
    g.scenes = R"("scene":0,"scenes":[{"nodes":[0,1]}])";
    g.meshes += R"(,{"primitives":[{"attributes":{"POSITION":0},"indices":1}]})";
    batch.read(write(name + ".gltf", g.json()), [](const Outcome& o) {
      EXPECT_EQ(o.kind, Kind::returned) << o;
      EXPECT_FALSE(contains(o.message, "unusable")) << o;
    }, {}, usable);
  }
  Gltf g;
  g.nodes = R"({"mesh":0,"scale":[0,0,0]})";
  const std::string path = write("only-zero.gltf", g.json());
  batch.read(path, [path](const Outcome& o) { expectRefused(o, path); });
  batch.run();
}

std::string cameraFacts(const ImportedModel& m) {
  std::ostringstream out;
  for (const ModelCamera& c : m.cameras) {
    const Camera& v = c.camera;
    const bool finite = std::isfinite(v.eye.x) && std::isfinite(v.lookAt.x) && std::isfinite(v.up.x) &&
                        std::isfinite(v.orthoHeight) && std::isfinite(c.aspectRatio);
    out << (finite ? "finite" : "NOT FINITE") << " fov " << v.fovDegrees << " ortho " << v.orthoHeight
        << " aspect " << c.aspectRatio << "; ";
  }
  return out.str();
}

TEST_F(HostileGltf, CamerasWithImpossibleProjectionsAreUsableOrLeftOut) {
  const std::vector<std::string> cameras = {
      R"({"type":"perspective","perspective":{"yfov":0,"znear":0.1}})",
      R"({"type":"perspective","perspective":{"yfov":-1,"znear":0.1}})",
      R"({"type":"perspective","perspective":{"yfov":1e308,"znear":0.1,"aspectRatio":1e-308}})",
      R"({"type":"perspective","perspective":{"yfov":3.1415926,"znear":-1,"zfar":-2,"aspectRatio":-1}})",
      R"({"type":"orthographic","orthographic":{"xmag":0,"ymag":0,"znear":0,"zfar":1}})",
      R"({"type":"orthographic","orthographic":{"xmag":-1,"ymag":-1,"znear":0,"zfar":1}})",
      R"({"type":"orthographic","orthographic":{"xmag":1e308,"ymag":1e308,"znear":0,"zfar":1}})",
      R"({"type":"orthographic","orthographic":{"xmag":1e-300,"ymag":1e300,"znear":0,"zfar":1}})",
      R"({"type":"fisheye"})",
  };
  Batch batch;
  int k = 0;
  for (const std::string& camera : cameras) {
    Gltf g;
    g.nodes = R"({"mesh":0},{"camera":0,"translation":[0,0,5]},{"camera":3})";
    g.scenes = R"("scene":0,"scenes":[{"nodes":[0,1,2]}])";
    g.more = R"(,"cameras":[)" + camera + "]";
    const std::string path = write("camera" + std::to_string(k++) + ".gltf", g.json());
    batch.read(path, [path, camera](const Outcome& o) {
      if (o.kind == Kind::modelError) {
        EXPECT_REFUSED(o, path) << camera;
        return;
      }
      ASSERT_EQ(o.kind, Kind::returned) << camera << ": " << o;
      EXPECT_FALSE(contains(o.message, "NOT FINITE")) << camera << ": " << o;
      for (size_t at = 0; (at = o.message.find("fov ", at)) != std::string::npos; at += 4) {
        const double fov = std::stod(o.message.substr(at + 4));
        EXPECT_TRUE(fov > 0 && fov < 180) << camera << ": " << o;
      }
    }, {}, cameraFacts);
  }
  batch.run();
}

std::string lightFacts(const ImportedModel& m) {
  std::string facts = "lights " + std::to_string(m.lights.size());
  for (const Light& l : m.lights) {
    if (!isFinite(l.color)) facts += "; a colour that is not finite";
    if (const auto* spot = std::get_if<SpotLight>(&l.shape)) {
      if (!(spot->innerDegrees >= 0 && spot->innerDegrees <= spot->outerDegrees && spot->outerDegrees <= 90)) {
        facts += "; cone angles out of order";
      }
    }
  }
  return facts;
}

TEST_F(HostileGltf, LightsWithAbsurdNumbersAreFiniteOrLeftOut) {
  const std::vector<std::string> lights = {
      R"({"type":"point","intensity":1e308})",
      R"({"type":"point","intensity":1e308,"color":[1e308,1e308,1e308]})",
      R"({"type":"point","intensity":-5,"color":[-1,-1,-1]})",
      R"({"type":"point","intensity":"NaN"})",
      R"({"type":"spot","spot":{"innerConeAngle":1e308,"outerConeAngle":-1e308}})",
      R"({"type":"spot","spot":{"innerConeAngle":2,"outerConeAngle":1}})",
      R"({"type":"directional","intensity":1e300})",
      R"({"type":"area"})",
  };
  Batch batch;
  int k = 0;
  for (const std::string& light : lights) {
    Gltf g;
    g.nodes = R"({"mesh":0},{"extensions":{"KHR_lights_punctual":{"light":0}}},)"
              R"({"extensions":{"KHR_lights_punctual":{"light":7}}},)"
              R"({"extensions":{"KHR_lights_punctual":{"light":-1}}},)"
              R"({"extensions":{"KHR_lights_punctual":{"light":"zero"}}})";
    g.scenes = R"("scene":0,"scenes":[{"nodes":[0,1,2,3,4]}])";
    g.more = R"(,"extensionsUsed":["KHR_lights_punctual"],"extensions":{"KHR_lights_punctual":{"lights":[)" +
             light + "]}}";
    const std::string path = write("light" + std::to_string(k++) + ".gltf", g.json());
    batch.read(path, [path, light](const Outcome& o) {
      if (o.kind == Kind::modelError) {
        EXPECT_REFUSED(o, path) << light;
        return;
      }
      EXPECT_EQ(o.kind, Kind::returned) << light << ": " << o;
      EXPECT_FALSE(contains(o.message, ";")) << light << ": " << o;
    }, {}, lightFacts);
  }
  batch.run();
}

// A light of negative intensity darkens in some renderers; no scene light can. It is left out
// with a warning, not made a light of no light (nor, with a negative colour, a bright one).
TEST_F(HostileGltf, LightsOfNegativeIntensityAreLeftOutWithAWarning) {
  for (const std::string color : {"[1,1,1]", "[-1,-1,-1]"}) {
    Gltf g;
    g.nodes = R"({"mesh":0},{"extensions":{"KHR_lights_punctual":{"light":0}}})";
    g.scenes = R"("scene":0,"scenes":[{"nodes":[0,1]}])";
    g.more = R"(,"extensionsUsed":["KHR_lights_punctual"],"extensions":{"KHR_lights_punctual":)"
             R"({"lights":[{"type":"point","name":"dark","intensity":-5,"color":)" + color + "}]}}";
    const ImportedModel m = readModelFile(write("dark.gltf", g.json()));
    EXPECT_TRUE(m.lights.empty()) << color;
    bool warned = false;
    for (const std::string& w : m.warnings) warned |= contains(w, "light 'dark', of negative intensity");
    EXPECT_TRUE(warned) << color;
  }
}

// Numbers far beyond an int where the reader casts them to one (undefined behaviour that
// clang's -fsanitize=undefined reports; GCC's does not check float-to-int conversions).
TEST_F(HostileGltf, TextureTransformsWithAbsurdNumbersStayFinite) {
  write("tiny.png", png(2, 2, 2));
  const Facts finiteUv = [](const ImportedModel& m) {
    std::string facts = counts(m);
    for (const Object& object : m.objects) {
      for (const double v : object.material.colorTexture.uv.m) {
        if (!std::isfinite(v)) facts += "; a texture transform that is not finite";
      }
    }
    return facts;
  };
  Batch batch;
  int k = 0;
  for (const std::string transform :
       {R"({"offset":[1e308,-1e308],"scale":[1e308,1e308],"rotation":1e308})",
        R"({"offset":"left","scale":[1],"rotation":"round"})",
        R"({"scale":[1e308,1e308],"rotation":0.7853981633974483})",
        R"({"texCoord":-5})", R"({"texCoord":1e10})", R"([1,2,3])", R"(7)"}) {
    const std::string path = write("transform" + std::to_string(k++) + ".gltf",
                                   texturedGltf(R"({"source":0})", R"({"uri":"tiny.png"})", "",
                                                R"("index":0,"extensions":{"KHR_texture_transform":)" + transform + "}"));
    batch.read(path, [transform](const Outcome& o) {
      EXPECT_EQ(o.kind, Kind::returned) << transform << ": " << o;
      EXPECT_FALSE(contains(o.message, "not finite")) << transform << ": " << o;
    }, {}, finiteUv);
  }
  // The specular-glossiness extension's texture index, read as a number and cast.
  Gltf g;
  g.meshes = R"({"primitives":[{"attributes":{"POSITION":0},"indices":1,"material":0}]})";
  for (const std::string index : {"1e10", "-1e10", "0.5", "\"zero\""}) {
    g.more = R"(,"materials":[{"extensions":{"KHR_materials_pbrSpecularGlossiness":{"diffuseTexture":{"index":)" +
             index + R"(}}}}],"textures":[{"source":0}],"images":[{"uri":"tiny.png"}])";
    batch.read(write("gloss" + std::to_string(k++) + ".gltf", g.json()), [index](const Outcome& o) {
      EXPECT_EQ(o.kind, Kind::returned) << index << ": " << o;
    });
  }
  batch.run();
}

TEST_F(HostileGltf, RequiredExtensionsPrtCannotReadAreRefused) {
  Batch batch;
  int k = 0;
  for (const std::string required : {"KHR_draco_mesh_compression", "EXT_meshopt_compression", ""}) {
    Gltf g;
    g.more = R"(,"extensionsUsed":[")" + required + R"("],"extensionsRequired":[")" + required + R"("])";
    const std::string path = write("required" + std::to_string(k++) + ".gltf", g.json());
    batch.read(path, [path, required](const Outcome& o) {
      EXPECT_REFUSED(o, path);
      EXPECT_TRUE(contains(o.message, required)) << o;
    });
  }
  batch.run();
}

// tinygltf turns every "extras" and "extensions" value into its own tree by recursion: JSON
// nested 100000 deep (200 KB) must be refused, not overflow the stack.
TEST_F(HostileGltf, DeeplyNestedJsonIsRefusedWithoutOverflowingTheStack) {
  const size_t depth = 100000;
  Batch batch;
  for (const std::string member : {"extras", "extensions"}) {
    Gltf g;
    const std::string nested = member == "extras" ? std::string(depth, '[') + std::string(depth, ']')
                                                  : "{\"x\":" + std::string(depth, '[') + std::string(depth, ']') + "}";
    g.nodes = R"({"mesh":0,")" + member + R"(":)" + nested + "}";
    batch.read(write(member + ".gltf", g.json()), [](const Outcome& o) {
      EXPECT_NE(o.kind, Kind::crashed) << o;
      EXPECT_TRUE(o.kind == Kind::returned || o.kind == Kind::modelError) << o;
    });
  }
  batch.run(10);
}

}  // namespace
}  // namespace prt
