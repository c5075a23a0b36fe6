// End-to-end tests of the prt command: exit codes, error messages and the promise that a
// failed run writes no image.

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>
#include <utility>
#include <vector>

#include <nlohmann/json.hpp>

#include "core/subprocess.h"
#include "image/image_io.h"
#include "prt_command.h"

namespace prt {
namespace {

namespace fs = std::filesystem;

using prt::e2e::Result;
using prt::e2e::run;
using CliTest = prt::e2e::ScratchDirTest;

const char* kValidScene =
    "camera { eye 0 1 -5 look_at 0 0.5 0 up 0 1 0 fov 40 }\n"
    "image { width 16 height 12 output \"x.png\" }\n"
    "light point { position -3 5 -5 color 1 1 1 }\n"
    "sphere { center 0 0.5 0 radius 0.5 surface { color 1 0 0 } }\n"
    "plane { point 0 0 0 normal 0 1 0 surface { color 0.8 0.8 0.8 } }\n";

TEST_F(CliTest, RendersAndPrintsSummary) {
  const std::string scene = write("ok.scene", kValidScene);
  const Result r = run("render " + scene + " -o " + path("out.png"));
  EXPECT_EQ(r.exitCode, 0) << r.output;
  EXPECT_TRUE(fs::exists(path("out.png")));
  EXPECT_NE(r.output.find("rays"), std::string::npos) << r.output;
}

// .exr (float: the same bits as .pfm; --exr-half: smaller) and .jpg, serial and parallel;
// --width alone keeps the scene's 4:3.
TEST_F(CliTest, WritesExrAndJpegAndWidthAloneKeepsTheAspectRatio) {
  const std::string scene = write("ok.scene", kValidScene);
  ASSERT_EQ(run("render " + scene + " -q -o " + path("ref.pfm")).exitCode, 0);
  const Image reference = readImage(path("ref.pfm"));
  for (const char* how : {"", " --workers 2"}) {
    const Result exr = run("render " + scene + how + " -q -o " + path("a.exr"));
    ASSERT_EQ(exr.exitCode, 0) << exr.output;
    EXPECT_EQ(readImage(path("a.exr")), reference) << how;
    const Result half = run("render " + scene + how + " -q --exr-half -o " + path("h.exr"));
    ASSERT_EQ(half.exitCode, 0) << half.output;
    EXPECT_LT(fs::file_size(path("h.exr")), fs::file_size(path("a.exr")));
    const Result jpg = run("render " + scene + how + " -q --jpeg-quality 80 -o " + path("a.jpg"));
    ASSERT_EQ(jpg.exitCode, 0) << jpg.output;
    EXPECT_EQ(readImage(path("a.jpg")).width(), 16);
  }
  const Result bad = run("render " + scene + " -q --jpeg-quality 0 -o " + path("b.jpg"));
  EXPECT_EQ(bad.exitCode, 2) << bad.output;
  ASSERT_EQ(run("render " + scene + " -q --width 40 -o " + path("w.png")).exitCode, 0);
  const Image wide = readImage(path("w.png"));
  EXPECT_EQ(wide.width(), 40);
  EXPECT_EQ(wide.height(), 30);
  ASSERT_EQ(run("render " + scene + " -q --height 3 -o " + path("t.png")).exitCode, 0);
  EXPECT_EQ(readImage(path("t.png")).width(), 4);
}

TEST_F(CliTest, SceneErrorNamesFileLineColumnAndWritesNothing) {
  std::string text = kValidScene;
  text += "sphere { center 0 0 0 radius -1 }\n";
  const std::string scene = write("bad.scene", text);
  const Result r = run("render " + scene + " -o " + path("out.png"));
  EXPECT_EQ(r.exitCode, 2);
  EXPECT_NE(r.output.find("bad.scene:6:"), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("^"), std::string::npos) << r.output;
  EXPECT_FALSE(fs::exists(path("out.png")));
}

// A broken mesh file: exit 2, the scene line and the mesh file's line, and no image.
TEST_F(CliTest, BrokenMeshFileIsALocatedErrorAndWritesNothing) {
  write("broken.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 4\n");
  std::string text = kValidScene;
  text += "mesh { file \"broken.obj\" }\n";
  const std::string scene = write("mesh.scene", text);
  for (const std::string extra : {"", " --workers 2"}) {
    const Result r = run("render " + scene + extra + " -o " + path("out.png"));
    EXPECT_EQ(r.exitCode, 2) << r.output;
    EXPECT_NE(r.output.find("mesh.scene:6:13: error:"), std::string::npos) << r.output;
    EXPECT_NE(r.output.find("broken.obj:4:7: a vertex index '4' is out of range"), std::string::npos)
        << r.output;
    EXPECT_FALSE(fs::exists(path("out.png")));
  }
  // Skipped triangles are warned about, and the rest is rendered.
  write("some.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 2 0 0\nf 1 2 3\nf 1 2 4\n");
  text = kValidScene;
  text += "mesh { file \"some.obj\" }\n";
  const Result r = run("render " + write("some.scene", text) + " -o " + path("out.png"));
  EXPECT_EQ(r.exitCode, 0) << r.output;
  EXPECT_NE(r.output.find("warning: "), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("skipped 1 triangle of zero area"), std::string::npos) << r.output;
  EXPECT_TRUE(fs::exists(path("out.png")));
}

// Workers get the meshes from the master, not from the disk, and render the serial image.
TEST_F(CliTest, MeshScenesRenderInParallelAsSerially) {
  const std::string scene = (fs::path(PRT_SOURCE_DIR) / "scenes" / "torus-knot.scene").string();
  const std::string size = " --width 48 --height 36 --case C -q";
  ASSERT_EQ(run("render " + scene + size + " -o " + path("ser.pfm")).exitCode, 0);
  const Result r = run("render " + scene + size + " --workers 3 --strategy reservoir --report " +
                       path("r.json") + " -o " + path("par.pfm"));
  ASSERT_EQ(r.exitCode, 0) << r.output;
  auto bytes = [](const std::string& file) {
    std::ifstream in(file, std::ios::binary);
    return std::string(std::istreambuf_iterator<char>(in), {});
  };
  EXPECT_TRUE(bytes(path("ser.pfm")) == bytes(path("par.pfm")));
  const std::string report = bytes(path("r.json"));
  // Two knots of 1,152 vertices (with normals) and 2,304 triangles each, and the text.
  const size_t at = report.find("\"scene_bytes\":");
  ASSERT_NE(at, std::string::npos) << report;
  EXPECT_GT(std::atoll(report.c_str() + at + 14), 2 * (1152 * 48 + 2304 * 12));
  EXPECT_NE(report.find("\"scene_transfer_s\":"), std::string::npos) << report;
}

TEST_F(CliTest, MissingEmptyAndBinaryFilesAreOneLineErrors) {
  for (const std::string& file : {path("missing.scene"), write("empty.scene", ""),
                                  write("bin.scene", std::string("\0\1\2", 3))}) {
    const Result r = run("render " + file + " -o " + path("out.png"));
    EXPECT_EQ(r.exitCode, 2) << file << ": " << r.output;
    EXPECT_NE(r.output.find("error"), std::string::npos) << r.output;
  }
  EXPECT_FALSE(fs::exists(path("out.png")));
}

TEST_F(CliTest, UnsupportedOutputExtensionIsRejectedBeforeRendering) {
  const Result r = run("render " + write("ok.scene", kValidScene) + " -o " + path("out.tga"));
  EXPECT_EQ(r.exitCode, 2);
  EXPECT_NE(r.output.find(".png"), std::string::npos) << r.output;
}

TEST_F(CliTest, BadFlagsExitWithCodeTwo) {
  const std::string scene = write("ok.scene", kValidScene);
  EXPECT_EQ(run("render " + scene + " --spp 0").exitCode, 2);
  EXPECT_EQ(run("render " + scene + " --case E").exitCode, 2);
  EXPECT_EQ(run("render").exitCode, 2);
  EXPECT_EQ(run("nonesuch").exitCode, 2);
}

TEST_F(CliTest, ParallelInputErrors) {
  const std::string scene = write("ok.scene", kValidScene);
  const std::string out = " -o " + path("out.png");
  Result r = run("render " + scene + out + " --workers 2 --strategy nonesuch");
  EXPECT_EQ(r.exitCode, 2);
  EXPECT_NE(r.output.find("reservoir"), std::string::npos) << "lists the valid names: " << r.output;
  r = run("render " + scene + out + " --workers 2 --initial-percent 0");
  EXPECT_EQ(r.exitCode, 2) << r.output;
  r = run("render " + scene + out + " --workers 2 --initial-percent 101");
  EXPECT_EQ(r.exitCode, 2) << r.output;
  r = run("render " + scene + out + " --workers 3 --slowdown 1,2");
  EXPECT_EQ(r.exitCode, 2) << r.output;
  r = run("render " + scene + out + " --workers 2 --slowdown 1,0.5");
  EXPECT_EQ(r.exitCode, 2) << r.output;
  for (const char* bad : {"3:0:2", "0:-1:2", "0:1:0.5", "0:1", "x"}) {
    r = run("render " + scene + out + " --workers 2 --slowdown-at " + bad);
    EXPECT_EQ(r.exitCode, 2) << bad << ": " << r.output;
    EXPECT_NE(r.output.find("--slowdown-at"), std::string::npos) << r.output;
  }
  for (const char* bad : {"-1:2", "1:0", "1:2.5", "1", "x:1", "1:2,", "1:5000"}) {
    r = run("render " + scene + out + " --workers 2 --join-at " + bad);
    EXPECT_EQ(r.exitCode, 2) << bad << ": " << r.output;
    EXPECT_NE(r.output.find("--join-at"), std::string::npos) << r.output;
    r = run("simulate --workers 2 --join-at " + std::string(bad));
    EXPECT_EQ(r.exitCode, 2) << bad << ": " << r.output;
  }
  // Per-worker lists count the joiners: 2 + 1 workers need 3 slowdowns.
  r = run("render " + scene + out + " --workers 2 --join-at 1:1 --slowdown 1,2");
  EXPECT_EQ(r.exitCode, 2) << r.output;
  EXPECT_NE(r.output.find("those that join"), std::string::npos) << r.output;
  r = run("simulate --workers 2 --join-at 1:1 --speeds 1,1");
  EXPECT_EQ(r.exitCode, 2) << r.output;
  r = run("render " + scene + out + " --join-at 1:1");
  EXPECT_EQ(r.exitCode, 2) << "a serial render has no joiners: " << r.output;
  r = run("render " + scene + out + " --workers 2 --join-at 1:1 --accept-workers " + path("port"));
  EXPECT_EQ(r.exitCode, 2) << "--join-at and --accept-workers in one local render: " << r.output;
  r = run("render " + scene + out + " --accept-workers " + path("port"));
  EXPECT_EQ(r.exitCode, 2) << "--accept-workers in a serial render: " << r.output;
  r = run("render " + scene + out + " --workers 2 --accept-address :7000");
  EXPECT_EQ(r.exitCode, 2) << "--accept-address without --accept-workers: " << r.output;
  r = run("render " + scene + out + " --workers 2 --accept-workers " + path("port") +
          " --accept-address 10.0.0:70000");
  EXPECT_EQ(r.exitCode, 2) << "a bad --accept-address: " << r.output;
  EXPECT_NE(r.output.find("[ADDRESS][:PORT]"), std::string::npos) << r.output;
  // Outside mpirun, prt join goes over TCP: a missing port file, or one with no TCP address (an
  // MPI port only), is bad input; --via mpi outside mpirun says it needs mpirun.
  r = run("join " + path("port"));
  EXPECT_EQ(r.exitCode, 2) << "prt join of a missing file: " << r.output;
  EXPECT_NE(r.output.find(path("port")), std::string::npos) << r.output;
  {
    std::ofstream(path("mpi-port")) << "tag#0$port#1234$\nsecret 00\n";
  }
  r = run("join " + path("mpi-port"));
  EXPECT_EQ(r.exitCode, 2) << "a port file without TCP addresses: " << r.output;
  EXPECT_NE(r.output.find("no TCP address"), std::string::npos) << r.output;
  r = run("join " + path("port") + " --via mpi");
  EXPECT_EQ(r.exitCode, 2) << "prt join --via mpi outside mpirun: " << r.output;
  EXPECT_NE(r.output.find("mpirun"), std::string::npos) << r.output;
  // prt join's own flags are checked first, and its --slowdown-at is T:K (no worker field):
  // an error speaks of what was typed.
  for (const char* bad : {"5", "1:2:3", "-1:2", "1:0.5", "1:2,", "x:2"}) {
    r = run("join " + path("port") + " --slowdown-at " + bad);
    EXPECT_EQ(r.exitCode, 2) << bad << ": " << r.output;
    EXPECT_NE(r.output.find("--slowdown-at"), std::string::npos) << bad << ": " << r.output;
    EXPECT_NE(r.output.find("T:K"), std::string::npos) << bad << ": " << r.output;
    EXPECT_EQ(r.output.find("0:"), std::string::npos) << bad << ": " << r.output;
    EXPECT_EQ(r.output.find("W:T"), std::string::npos) << bad << ": " << r.output;
  }
  for (const char* bad : {"--slowdown 0", "--slowdown 2000", "--connect-timeout 0"}) {
    r = run("join " + path("port") + " " + bad);
    EXPECT_EQ(r.exitCode, 2) << bad << ": " << r.output;
    EXPECT_EQ(r.output.find("runs under mpirun"), std::string::npos) << bad << ": " << r.output;
  }
  r = run("render " + scene + out + " --workers 2 --min-chunk 0");
  EXPECT_EQ(r.exitCode, 2) << r.output;
  r = run("render " + scene + out + " --workers 2 --chunk 1.5");
  EXPECT_EQ(r.exitCode, 2) << r.output;
  r = run("render " + scene + out + " --workers 2 --speed-index nonesuch");
  EXPECT_EQ(r.exitCode, 2) << r.output;
  r = run("simulate --workers 2 --speed-at 2:1:0.5");
  EXPECT_EQ(r.exitCode, 2) << r.output;
  r = run("simulate --workers 2 --slowdown-at 1:1:0.5");  // a slowdown is at least 1
  EXPECT_EQ(r.exitCode, 2) << r.output;
  EXPECT_NE(r.output.find("--slowdown-at"), std::string::npos) << r.output;
  r = run("simulate --workers 2 --speed-index-run maybe");
  EXPECT_EQ(r.exitCode, 2) << r.output;
  r = run("render " + scene + out + " --workers 1000");
  EXPECT_EQ(r.exitCode, 2) << r.output;
  EXPECT_NE(r.output.find("pixels"), std::string::npos) << r.output;
  EXPECT_FALSE(fs::exists(path("out.png")));
}

TEST_F(CliTest, ParallelRenderWritesReportTraceAndOwnership) {
  const std::string scene = write("ok.scene", kValidScene);
  const Result r = run("render " + scene + " -o " + path("par.pfm") +
                       " --workers 3 --strategy hybrid --slowdown 1,2,2 --serial-seconds 1" +
                       " --report " + path("r.json") + " --trace " + path("t.json") +
                       " --ownership " + path("own.png") + " --batch 8");
  ASSERT_EQ(r.exitCode, 0) << r.output;
  EXPECT_TRUE(fs::exists(path("r.json")));
  EXPECT_TRUE(fs::exists(path("t.json")));
  EXPECT_TRUE(fs::exists(path("own.png")));
  EXPECT_NE(r.output.find("efficiency"), std::string::npos) << r.output;
  // Same bytes as a serial render.
  ASSERT_EQ(run("render " + scene + " -o " + path("ser.pfm") + " --quiet").exitCode, 0);
  std::ifstream a(path("par.pfm"), std::ios::binary), b(path("ser.pfm"), std::ios::binary);
  const std::string sa((std::istreambuf_iterator<char>(a)), {});
  const std::string sb((std::istreambuf_iterator<char>(b)), {});
  EXPECT_EQ(sa, sb);
}

TEST_F(CliTest, AdaptiveRunWithAChangingSpeedMatchesTheSerialImage) {
  const std::string scene = write("ok.scene", kValidScene);
  const Result r = run("render " + scene + " -o " + path("par.pfm") +
                       " --workers 2 --slowdown 1,2 --slowdown-at 0:0:3 --serial-seconds 1" +
                       " --report " + path("r.json") + " --batch 8");
  ASSERT_EQ(r.exitCode, 0) << r.output;
  EXPECT_NE(r.output.find("strategy adaptive"), std::string::npos) << "the default: " << r.output;
  EXPECT_NE(r.output.find("measured throughput"), std::string::npos) << r.output;
  std::ifstream report(path("r.json"));
  const std::string json((std::istreambuf_iterator<char>(report)), {});
  EXPECT_NE(json.find("\"masu_basis\": \"measured_throughput\""), std::string::npos) << json;
  ASSERT_EQ(run("render " + scene + " -o " + path("ser.pfm") + " --quiet").exitCode, 0);
  std::ifstream a(path("par.pfm"), std::ios::binary), b(path("ser.pfm"), std::ios::binary);
  const std::string sa((std::istreambuf_iterator<char>(a)), {});
  const std::string sb((std::istreambuf_iterator<char>(b)), {});
  EXPECT_EQ(sa, sb);
}

TEST_F(CliTest, SpeedIndexPrintsSeconds) {
  const Result r = run("speed-index --discs 16 --repeats 1");
  EXPECT_EQ(r.exitCode, 0);
  EXPECT_GT(std::atof(r.output.c_str()), 0.0) << r.output;
}

// The trace library's level as `prt --version` reports it ("... (trace kernels: LEVEL)").
std::string traceLevel(const std::string& environment) {
  const Result r = run("--version", environment);
  const std::string key = "trace kernels: ";
  const size_t at = r.output.find(key);
  if (r.exitCode != 0 || at == std::string::npos) return "?";
  return r.output.substr(at + key.size(), r.output.find(')', at) - at - key.size());
}

// The loader takes the best build of the trace library the processor supports; hiding
// AVX-512 or AVX2 from it (a glibc tunable) makes it fall back to a lesser one (x86-64-v3, or
// the baseline unless an x86-64-v2 build was asked for). Every build must render every pixel
// alike: a mixed cluster's nodes run different builds on parts of one image, and the builds
// test a mesh's triangles in blocks of eight with vectors of two, four or eight lanes. Every
// example scene, small: float pixels hide most last-bit differences of the doubles behind
// them, so one scene alone can miss a difference (a build with fused multiply-adds renders
// the benchmark scene alike at these sizes, but not the transmissions scene).
TEST_F(CliTest, EveryBuildOfTheKernelsRendersTheSameImages) {
  // The builds this processor can run, best first, each with the environment that picks it.
  std::vector<std::pair<std::string, std::string>> builds;
  for (const std::string environment :
       {"", "GLIBC_TUNABLES=glibc.cpu.hwcaps=-AVX512F ", "GLIBC_TUNABLES=glibc.cpu.hwcaps=-AVX2 "}) {
    const std::string level = traceLevel(environment);
    ASSERT_NE(level, "?") << environment;
    const bool seen = std::any_of(builds.begin(), builds.end(),
                                  [&](const auto& b) { return b.first == level; });
    if (!seen) builds.emplace_back(level, environment);
  }
  // Without AVX2, or with a glibc older than 2.33, only one build can run here.
  if (builds.size() < 2) GTEST_SKIP() << "one build of the kernels runs here: " << builds[0].first;
  auto bytes = [](const std::string& file) {
    std::ifstream in(file, std::ios::binary);
    return std::string(std::istreambuf_iterator<char>(in), {});
  };
  int scenes = 0;
  for (const auto& entry : fs::directory_iterator(fs::path(PRT_SOURCE_DIR) / "scenes")) {
    if (entry.path().extension() != ".scene") continue;
    // The one example model not in the repository (scripts/fetch-bunny.sh fetches it).
    if (bytes(entry.path().string()).find("models/bunny.ply") != std::string::npos &&
        !fs::exists(entry.path().parent_path() / "models" / "bunny.ply")) {
      continue;
    }
    ++scenes;
    // Case D: supersampling and every distributed effect (gloss, blur, soft shadows).
    const std::string args =
        "render " + entry.path().string() + " --width 64 --height 48 --case D -q -o ";
    std::string first;
    for (const auto& [level, environment] : builds) {
      const Result r = run(args + path("build.pfm"), environment);
      ASSERT_EQ(r.exitCode, 0) << level << ": " << r.output;
      const std::string image = bytes(path("build.pfm"));
      EXPECT_GT(image.size(), 64u * 48u * 12u);
      if (first.empty()) {
        first = image;
        continue;
      }
      EXPECT_TRUE(image == first) << entry.path().filename() << ": the " << builds[0].first
                                  << " and " << level << " builds rendered different images";
    }
  }
  EXPECT_GE(scenes, 8);
}

// Each worker's report names the build of the trace kernels it ran (the workers of a mixed
// cluster differ): for the thread driver, the process's own, which the loader picks.
TEST_F(CliTest, TheReportNamesEachWorkersBuildOfTheKernels) {
  for (const std::string environment : {"", "GLIBC_TUNABLES=glibc.cpu.hwcaps=-AVX2 "}) {
    const std::string level = traceLevel(environment);
    ASSERT_NE(level, "?");
    const Result r = run("render " + std::string(PRT_SOURCE_DIR) +
                             "/scenes/fig08-basic-features.scene --workers 2 --width 32 "
                             "--height 24 -q -o " + path("k.png") + " --report " + path("k.json"),
                         environment);
    ASSERT_EQ(r.exitCode, 0) << r.output;
    std::ifstream in(path("k.json"));
    const nlohmann::json report = nlohmann::json::parse(in);
    ASSERT_EQ(report["workers"].size(), 2u);
    for (const auto& w : report["workers"]) EXPECT_EQ(w["kernels"], level) << environment;
  }
}

// prt simulate takes prt render's --slowdown-at: K times slower is a speed of 1/K.
TEST_F(CliTest, SimulateTakesRendersSlowdownAt) {
  const auto elapsed = [&](const std::string& flags) {
    const Result r = run("simulate --workers 3 -q --report " + path("s.json") + " " + flags);
    EXPECT_EQ(r.exitCode, 0) << flags << ": " << r.output;
    return nlohmann::json::parse(readWholeFile(path("s.json")))["elapsed_s"].get<double>();
  };
  const double slowed = elapsed("--slowdown-at 1:2:4");
  EXPECT_DOUBLE_EQ(slowed, elapsed("--speed-at 1:2:0.25"));
  EXPECT_GT(slowed, elapsed(""));
}

}  // namespace
}  // namespace prt
