// glTF animations made to break the reader (gltf_animation.h): samplers whose accessors have
// the wrong type or count, reach past their buffers or have no data, times that are not finite
// or do not increase, huge declared counts, channels naming nodes, samplers or paths that do
// not exist, a second channel for one path, morph weights, many broken animations. Each must
// leave out what it cannot play with a warning naming the file and the animation, and read the
// rest, quickly and in bounded memory; never crash. The harness is hostile_model_files.h's.

#include "scene/hostile_model_files.h"

namespace prt {
namespace {

// Its own suite's name: gtest wants one fixture class per suite, and each test file has its own.
using HostileAnimation = HostileModel;

// A glTF file whose one node (the minimal file's triangle) is moved by `animations`: accessor 2
// holds `times`, accessor 3 `values` (floats, in a second buffer), with the types and counts
// given (a count of -1: as many as there are).
struct AnimatedGltf {
  std::vector<float> times{0, 1};
  std::vector<float> values{0, 0, 0, 1, 0, 0};
  std::string timesType = "SCALAR", valuesType = "VEC3";
  int64_t timesCount = -1, valuesCount = -1;
  std::string interpolation = "LINEAR";
  std::string path = "translation";
  std::string animations;  // in place of the one animation made of the above

  std::string json() const {
    std::string bytes;
    for (const float t : times) append(bytes, t);
    const size_t valuesAt = bytes.size();
    for (const float v : values) append(bytes, v);
    const auto count = [](int64_t given, size_t n) { return std::to_string(given >= 0 ? given : static_cast<int64_t>(n)); };
    const int components = valuesType == "VEC4" ? 4 : valuesType == "SCALAR" ? 1 : 3;
    Gltf g;
    g.buffers += R"(,{"byteLength":)" + std::to_string(bytes.size()) + R"(,"uri":")" + dataUri(bytes) + R"("})";
    g.bufferViews += R"(,{"buffer":1,"byteOffset":0,"byteLength":)" + std::to_string(valuesAt) +
                     R"(},{"buffer":1,"byteOffset":)" + std::to_string(valuesAt) + R"(,"byteLength":)" +
                     std::to_string(bytes.size() - valuesAt) + "}";
    g.accessors += R"(,{"bufferView":2,"componentType":5126,"count":)" + count(timesCount, times.size()) +
                   R"(,"type":")" + timesType + R"("},{"bufferView":3,"componentType":5126,"count":)" +
                   count(valuesCount, values.size() / static_cast<size_t>(components)) + R"(,"type":")" +
                   valuesType + R"("})";
    g.more = R"(,"animations":[)" +
             (animations.empty()
                  ? R"({"name":"move","channels":[{"sampler":0,"target":{"node":0,"path":")" + path +
                        R"("}}],"samplers":[{"input":2,"output":3,"interpolation":")" + interpolation + R"("}]})"
                  : animations) +
             "]";
    return g.json();
  }
};

std::string rigFacts(const ImportedModel& m) {
  std::string facts = counts(m) + ", curves " + std::to_string(m.rig.curves.size());
  for (const Curve& c : m.rig.curves) facts += c.wellFormed() ? "" : ", A CURVE NOT WELL FORMED";
  return facts;
}

// The file was read, its triangle kept, with `curves` curves in its rig.
void expectRead(const Outcome& o, size_t curves) {
  EXPECT_EQ(o.kind, Kind::returned) << o;
  EXPECT_EQ(o.message, "objects 1, lights 0, cameras 0, textures 0, curves " + std::to_string(curves)) << o;
}

TEST_F(HostileAnimation, AGoodAnimationIsPlayed) {
  Batch batch;
  for (const char* interpolation : {"STEP", "LINEAR"}) {
    AnimatedGltf a;
    a.interpolation = interpolation;
    batch.read(write(std::string(interpolation) + ".gltf", a.json()), [](const Outcome& o) {
      expectRead(o, 1);
      EXPECT_TRUE(o.warnings.empty()) << o;
    }, {}, rigFacts);
  }
  AnimatedGltf cubic;
  cubic.interpolation = "CUBICSPLINE";
  cubic.values = std::vector<float>(18, 0.5f);
  batch.read(write("cubic.gltf", cubic.json()), [](const Outcome& o) { expectRead(o, 1); }, {}, rigFacts);
  AnimatedGltf rotation;
  rotation.path = "rotation";
  rotation.valuesType = "VEC4";
  rotation.values = {0, 0, 0, 1, 0, 1, 0, 0};
  batch.read(write("rotation.gltf", rotation.json()), [](const Outcome& o) { expectRead(o, 1); }, {}, rigFacts);
  batch.run();
}

TEST_F(HostileAnimation, SamplersThatCannotBePlayedAreLeftOutNamingTheirAnimation) {
  std::vector<std::pair<std::string, AnimatedGltf>> cases;
  const auto add = [&](const std::string& name, const std::function<void(AnimatedGltf&)>& change) {
    AnimatedGltf a;
    change(a);
    cases.emplace_back(name, a);
  };
  add("decreasing", [](AnimatedGltf& a) { a.times = {1, 0}; });
  add("repeated", [](AnimatedGltf& a) { a.times = {1, 1}; });
  add("nan-time", [](AnimatedGltf& a) { a.times = {0, std::nanf("")}; });
  add("inf-time", [](AnimatedGltf& a) { a.times = {0, std::numeric_limits<float>::infinity()}; });
  add("nan-value", [](AnimatedGltf& a) { a.values[4] = std::nanf(""); });
  add("too-few-values", [](AnimatedGltf& a) { a.values = {0, 0, 0}; });
  add("too-many-values", [](AnimatedGltf& a) { a.values = std::vector<float>(9, 0); });
  add("cubic-without-tangents", [](AnimatedGltf& a) { a.interpolation = "CUBICSPLINE"; });
  add("vec4-translation", [](AnimatedGltf& a) { a.valuesType = "VEC4"; a.values = std::vector<float>(8, 0); });
  add("vec3-rotation", [](AnimatedGltf& a) { a.path = "rotation"; });
  add("vec3-times", [](AnimatedGltf& a) { a.timesType = "VEC3"; a.times = std::vector<float>(6, 0); });
  add("no-keys", [](AnimatedGltf& a) { a.timesCount = 0; a.valuesCount = 0; });
  add("unknown-interpolation", [](AnimatedGltf& a) { a.interpolation = "QUADRATIC"; });
  add("unknown-path", [](AnimatedGltf& a) { a.path = "colour"; });
  // Counts far beyond the bytes: the accessor reaches past its buffer view.
  add("huge-times", [](AnimatedGltf& a) { a.timesCount = 2000000000; });
  add("huge-values", [](AnimatedGltf& a) { a.valuesCount = 2000000000; });
  add("bad-node", [](AnimatedGltf& a) {
    a.animations = R"({"name":"move","channels":[{"sampler":0,"target":{"node":9,"path":"translation"}}],)"
                   R"("samplers":[{"input":2,"output":3}]})";
  });
  add("bad-sampler", [](AnimatedGltf& a) {
    a.animations = R"({"name":"move","channels":[{"sampler":3,"target":{"node":0,"path":"translation"}}],)"
                   R"("samplers":[{"input":2,"output":3}]})";
  });
  add("bad-accessor", [](AnimatedGltf& a) {
    a.animations = R"({"name":"move","channels":[{"sampler":0,"target":{"node":0,"path":"translation"}}],)"
                   R"("samplers":[{"input":2,"output":77}]})";
  });
  // All zeros, bounded by no buffer: a billion keys must not be made.
  add("no-buffer-view", [](AnimatedGltf& a) {
    a.animations = R"({"name":"move","channels":[{"sampler":0,"target":{"node":0,"path":"translation"}}],)"
                   R"("samplers":[{"input":4,"output":5}]})";
  });
  Batch batch;
  for (auto& [name, a] : cases) {
    std::string json = a.json();
    if (name == "no-buffer-view") {
      const std::string extra = R"(,{"componentType":5126,"count":1000000000,"type":"SCALAR"},)"
                                R"({"componentType":5126,"count":1000000000,"type":"VEC3"}])";
      json.replace(json.find(R"("}],"bufferViews")"), 3, "\"}" + extra);
    }
    const std::string path = write(name + ".gltf", json);
    batch.read(path, [path](const Outcome& o) {
      EXPECT_READ_WITH_WARNING(o, path, "animation 0 'move'");
      expectRead(o, 0);
    }, {}, rigFacts);
  }
  batch.run();
}

TEST_F(HostileAnimation, ChannelsBeyondWhatPrtPlaysWarnOnceEach) {
  Batch batch;
  // Two channels on one node's translation: the second is ignored.
  AnimatedGltf twice;
  twice.animations = R"({"channels":[{"sampler":0,"target":{"node":0,"path":"translation"}},)"
                     R"({"sampler":0,"target":{"node":0,"path":"translation"}}],"samplers":[{"input":2,"output":3}]},)"
                     R"({"channels":[{"sampler":0,"target":{"node":0,"path":"translation"}}],"samplers":[{"input":2,"output":3}]})";
  const std::string twicePath = write("twice.gltf", twice.json());
  batch.read(twicePath, [twicePath](const Outcome& o) {
    EXPECT_READ_WITH_WARNING(o, twicePath, "2 channels are ignored");
    expectRead(o, 1);
  }, {}, rigFacts);
  // Morph weights: one line about their animation, nothing played.
  AnimatedGltf weights;
  weights.path = "weights";
  weights.valuesType = "SCALAR";
  weights.values = {0, 1};
  const std::string weightsPath = write("weights.gltf", weights.json());
  batch.read(weightsPath, [weightsPath](const Outcome& o) {
    EXPECT_READ_WITH_WARNING(o, weightsPath, "animations of morph weights are not played (1 animation)");
    EXPECT_EQ(o.warnings.size(), 1u) << o;
    expectRead(o, 0);
  }, {}, rigFacts);
  // A matrix node cannot be animated (glTF forbids it).
  AnimatedGltf matrix;
  std::string matrixJson = matrix.json();
  matrixJson.replace(matrixJson.find(R"({"mesh":0})"), 10,
                     R"({"mesh":0,"matrix":[1,0,0,0, 0,1,0,0, 0,0,1,0, 0,0,0,1]})");
  const std::string matrixPath = write("matrix.gltf", matrixJson);
  batch.read(matrixPath, [matrixPath](const Outcome& o) {
    EXPECT_READ_WITH_WARNING(o, matrixPath, "has a matrix");
    expectRead(o, 0);
  }, {}, rigFacts);
  // Many broken animations: a few lines, then a count.
  AnimatedGltf many;
  for (int i = 0; i < 200; ++i) {
    many.animations += std::string(i ? "," : "") +
                       R"({"channels":[{"sampler":0,"target":{"node":)" + std::to_string(100 + i) +
                       R"(,"path":"scale"}}],"samplers":[{"input":2,"output":3}]})";
  }
  const std::string manyPath = write("many.gltf", many.json());
  batch.read(manyPath, [manyPath](const Outcome& o) {
    EXPECT_READ_WITH_WARNING(o, manyPath, "192 more animations");
    EXPECT_LE(o.warnings.size(), 10u) << o;
    expectRead(o, 0);
  }, {}, rigFacts);
  batch.run();
}

TEST_F(HostileAnimation, ManyChannelsSharingOneLargeSamplerReadItOnce) {
  // 4000 keys, one sampler, the one node's three paths and 300 more animations naming it: the
  // keys are read once per path, not once per channel.
  AnimatedGltf a;
  a.times.resize(4000);
  for (size_t i = 0; i < a.times.size(); ++i) a.times[i] = static_cast<float>(i);
  a.values.assign(3 * 4000, 1.f);
  for (int i = 0; i < 300; ++i) {
    a.animations += std::string(i ? "," : "") +
                    R"({"channels":[{"sampler":0,"target":{"node":0,"path":"translation"}},)"
                    R"({"sampler":0,"target":{"node":0,"path":"scale"}}],"samplers":[{"input":2,"output":3}]})";
  }
  const std::string path = write("shared.gltf", a.json());
  const Outcome o = readIsolated(path, {}, rigFacts);
  expectRead(o, 2);
  EXPECT_LT(o.peakGrowthKb, 64 * 1024) << o;
}

TEST_F(HostileAnimation, AScenePlayingAHostileAnimationLoadsOrFailsCleanly) {
  AnimatedGltf a;
  a.times = {0, std::nanf("")};
  const std::string model = write("nan.gltf", a.json());
  const Outcome o = loadIsolated(sceneImporting(model));
  EXPECT_EQ(o.kind, Kind::returned) << o;
  EXPECT_TRUE(anyContains(o.warnings, "animation 0 'move'")) << o;
  AnimatedGltf good;
  const Outcome played = loadIsolated(sceneImporting(write("good.gltf", good.json()), "good.scene"));
  EXPECT_EQ(played.kind, Kind::returned) << played;
}

TEST_F(HostileAnimation, ByteFlipsOfARealAnimatedGlbNeverCrash) {
  // Flips in the binary chunk (times, values, meshes) and anywhere; every rig read must hold.
  const std::string real = readAll(kSource / "scenes/models/animated.glb");
  uint32_t jsonLength = 0;
  std::memcpy(&jsonLength, real.data() + 12, 4);
  const size_t binAt = 20 + jsonLength + 8;
  const std::string path = (dir_ / "flipped.glb").string();
  const Outcome o = isolated([&]() -> Report {
    std::mt19937 random(20250101);
    for (int round = 0; round < 400; ++round) {
      std::string bytes = real;
      const int flips = 1 + static_cast<int>(random() % 4);
      for (int f = 0; f < flips; ++f) {
        const size_t at = round % 2 == 0 ? binAt + random() % (bytes.size() - binAt) : random() % bytes.size();
        bytes[at] ^= static_cast<char>(1 + random() % 255);
      }
      std::ofstream(path, std::ios::binary | std::ios::trunc).write(bytes.data(), static_cast<std::streamsize>(bytes.size()));
      const Report r = readReport(path, {}, [](const ImportedModel& m) {
        SceneAnimation a;
        a.curves = m.rig.curves;
        a.nodes = m.rig.nodes;
        return rigProblem(a);
      });
      if (r.kind != Kind::modelError && r.kind != Kind::returned) {
        return {Kind::otherError, "round " + std::to_string(round) + ": " + kindName(r.kind) + ": " + r.message, {}};
      }
      if (r.kind == Kind::returned && !r.message.empty()) {
        return {Kind::otherError, "round " + std::to_string(round) + ": a rig that does not hold: " + r.message, {}};
      }
    }
    return {Kind::returned, "", {}};
  });
  EXPECT_EQ(o.kind, Kind::returned) << o;
}

}  // namespace
}  // namespace prt
