// End-to-end tests of animations through the prt command: a sequence is one job whose frames
// are each bit for bit the frame rendered alone (--frame N), serially, under the thread driver
// with every strategy and across a SIGKILL and --resume; the flags that name frames and the
// output pattern are checked before anything renders.

#include <gtest/gtest.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>
#include <thread>

#include "prt_command.h"

namespace prt {
namespace {

namespace fs = std::filesystem;
using prt::e2e::Result;
using prt::e2e::run;
using AnimationCliTest = prt::e2e::ScratchDirTest;

const fs::path kSource(PRT_SOURCE_DIR);

std::string readAll(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

const std::string kScene = (kSource / "scenes" / "keyframes.scene").string();
const std::string kGltfScene = (kSource / "scenes" / "animated.scene").string();
const std::string kSize = " --width 32 --height 24 --spp 2 --fps 2 -q";

TEST_F(AnimationCliTest, EveryFrameOfASequenceIsThatFrameRenderedAlone) {
  for (const std::string& scene : {kScene, kGltfScene}) {
    const Result seq = run("render " + scene + kSize + " --frames 0-6:3 -o " + path("s_##.pfm"));
    ASSERT_EQ(seq.exitCode, 0) << seq.output;
    for (const char* f : {"0", "3", "6"}) {
      const std::string alone = path(std::string("alone_") + f + ".pfm");
      ASSERT_EQ(run("render " + scene + kSize + " --frame " + f + " -o " + alone).exitCode, 0);
      EXPECT_EQ(readAll(alone), readAll(path(std::string("s_0") + f + ".pfm"))) << scene << f;
    }
    EXPECT_FALSE(fs::exists(path("s_01.pfm")));  // the step skips it
    EXPECT_NE(readAll(path("s_00.pfm")), readAll(path("s_06.pfm"))) << scene << ": nothing moved";
  }
}

TEST_F(AnimationCliTest, EveryStrategyRendersTheSequenceBitForBit) {
  ASSERT_EQ(run("render " + kScene + kSize + " --frames 0-5 -o " + path("ref_#.pfm")).exitCode, 0);
  for (const char* strategy : {"adaptive", "scatter", "hybrid", "reservoir", "reservoir-scatter",
                               "frames", "self", "stealing", "awf-b"}) {
    const Result r = run("render " + kScene + kSize + " --frames 0-5 --workers 3 --slowdown 1,2,3 "
                         "--batch 16 --strategy " + strategy + " -o " + path("p_#.pfm") +
                         " --report " + path("r.json"));
    ASSERT_EQ(r.exitCode, 0) << strategy << "\n" << r.output;
    for (int f = 0; f <= 5; ++f) {
      const std::string n = std::to_string(f);
      EXPECT_EQ(readAll(path("ref_" + n + ".pfm")), readAll(path("p_" + n + ".pfm")))
          << strategy << " frame " << f;
    }
    const std::string report = readAll(path("r.json"));
    EXPECT_NE(report.find("\"frame_count\": 6"), std::string::npos) << strategy;
  }
}

// An import's keyed placement moves the whole file (a model without an animation of its own),
// under the thread driver as serially.
TEST_F(AnimationCliTest, AKeyedImportMovesTheWholeFile) {
  const std::string crate = (kSource / "scenes" / "models" / "crate.glb").string();
  const std::string scene = write(
      "moving.scene", "image { width 32 height 24 }\n"
                      "import { file \"" + crate + "\" key 2 { translate 1 0 0 rotate 0 90 0 } }\n"
                      "plane { point 0 0 0 normal 0 1 0 }\n");
  ASSERT_EQ(run("render " + scene + kSize + " --frames 0-4:2 -o " + path("s_#.pfm")).exitCode, 0);
  const Result r = run("render " + scene + kSize + " --frames 0-4:2 --workers 2 -o " +
                       path("p_#.pfm"));
  ASSERT_EQ(r.exitCode, 0) << r.output;
  for (const char* f : {"0", "2", "4"}) {
    EXPECT_EQ(readAll(path(std::string("s_") + f + ".pfm")),
              readAll(path(std::string("p_") + f + ".pfm"))) << f;
  }
  EXPECT_NE(readAll(path("s_0.pfm")), readAll(path("s_4.pfm")));
}

// The simulator takes a sequence as one job too: whole frames per worker leave the slow
// machines' last frames to decide the end, the default balances within frames.
TEST_F(AnimationCliTest, TheSimulatorBalancesASequenceAndShowsWholeFramesLosing) {
  const std::string common = "simulate --workers 8 --width 32 --height 24 --slow-share 0.5 "
                             "--slow-factor 4 --frames 10 --report ";
  const Result adaptive = run(common + path("a.json"));
  ASSERT_EQ(adaptive.exitCode, 0) << adaptive.output;
  EXPECT_NE(adaptive.output.find("10 frames"), std::string::npos) << adaptive.output;
  ASSERT_EQ(run(common + path("f.json") + " --strategy frames").exitCode, 0);
  const auto elapsed = [&](const std::string& file) {
    const std::string text = readAll(path(file));
    const size_t at = text.find("\"elapsed_s\": ");
    return std::stod(text.substr(at + 13));
  };
  EXPECT_LT(elapsed("a.json") * 1.2, elapsed("f.json"));
  EXPECT_NE(run("simulate --workers 4 --frames 0").exitCode, 0);
}

// The run's page of a sequence shows a sheet of its frames and one frame's ownership map.
TEST_F(AnimationCliTest, TheRunPageOfASequenceShowsItsFrames) {
  const Result r = run("render " + kScene + kSize + " --frames 0-20:4 --workers 2 -o " +
                       path("f_##.png") + " --html " + path("page.html"));
  ASSERT_EQ(r.exitCode, 0) << r.output;
  const std::string page = readAll(path("page.html"));
  EXPECT_NE(page.find("6 frames of 32×24"), std::string::npos);
  EXPECT_NE(page.find("shown: frames 0, 4, 8, 12, 16, 20"), std::string::npos);
  EXPECT_NE(page.find("ownership_map"), std::string::npos);
}

TEST_F(AnimationCliTest, FlagsAndPatternsAreCheckedBeforeRendering) {
  struct Case {
    std::string flags, message;
  };
  const Case cases[] = {
      {"--frames 0-4 -o plain.png", "needs an output pattern"},
      {"--frames 5-1 -o f_#.png", "comes before the first"},
      {"--frames 1-x -o f_#.png", "whole numbers"},
      {"--frames 0-9:0 -o f_#.png", "STEP"},
      {"--frames 0-4 --frame 2 -o f_#.png", "not both"},
      {"--frame 1-3 -o f.png", "one frame number"},
      {"--frames 0-4 --fps 0 -o f_#.png", "--fps"},
      {"--frames 0-4 --fps nan -o f_#.png", "--fps"},
      {"--frames 0-2000000 -o f_#######.png", "one job may hold"},
      {"--frames 0-3 -o f_#_#.png", "needs an output pattern"},
  };
  for (const Case& c : cases) {
    const Result r = run("render " + kScene + kSize + " " + c.flags);
    EXPECT_EQ(r.exitCode, 2) << c.flags << "\n" << r.output;
    EXPECT_NE(r.output.find(c.message), std::string::npos) << c.flags << "\n" << r.output;
  }
}

TEST_F(AnimationCliTest, KeyframesThatMakeAFrameImpossibleAreCaughtAtThatFrame) {
  // The camera's eye passes through its look_at at time 1: frame 2 (at 2 fps) cannot render.
  const std::string scene = write("bad.scene",
                                  "camera { eye 0 0 -5 look_at 0 0 0 key 2 { eye 0 0 5 } }\n"
                                  "image { width 8 height 6 }\n"
                                  "sphere { center 0 0 0 radius 1 }\n");
  const Result r = run("render " + scene + " -q --fps 2 --frames 0-4 -o " + path("b_#.png"));
  EXPECT_EQ(r.exitCode, 2) << r.output;
  EXPECT_NE(r.output.find("frame 2"), std::string::npos) << r.output;
  EXPECT_FALSE(fs::exists(path("b_0.png"))) << "nothing is written before the check";
}

// A real SIGKILL of a sequence render part-way, then --resume: every frame is the serial one,
// and the frames finished before the kill are not rendered again.
TEST_F(AnimationCliTest, AKilledSequenceResumesToTheSameFrames) {
  const std::string size = " --width 48 --height 36 --spp 2 --fps 4 -q --frames 0-7";
  ASSERT_EQ(run("render " + kScene + size + " -o " + path("ref_#.pfm")).exitCode, 0);
  const std::string command = prt::e2e::prtBinary() + " render " + kScene + size +
                              " --workers 2 --slowdown 8,8 --batch 16 -o " + path("k_#.pfm") +
                              " --checkpoint " + path("ck") + " --checkpoint-every 0.05";
  const pid_t child = fork();
  ASSERT_GE(child, 0);
  if (child == 0) {
    execl("/bin/sh", "sh", "-c", ("exec " + command + " >/dev/null 2>&1").c_str(), nullptr);
    _exit(127);
  }
  // Until the checkpoint holds some pixels, then SIGKILL.
  for (int i = 0; i < 400; ++i) {
    std::error_code ec;
    if (fs::exists(path("ck"), ec) && fs::file_size(path("ck"), ec) > 4000) break;
    std::this_thread::sleep_for(std::chrono::milliseconds(25));
  }
  kill(child, SIGKILL);
  int status = 0;
  waitpid(child, &status, 0);
  ASSERT_TRUE(WIFSIGNALED(status)) << "the render ended before it was killed";
  ASSERT_TRUE(fs::exists(path("ck")));
  const Result resumed = run("render " + kScene + size + " --workers 2 -o " + path("k_#.pfm") +
                             " --checkpoint " + path("ck") + " --resume --report " +
                             path("r.json"));
  ASSERT_EQ(resumed.exitCode, 0) << resumed.output;
  for (int f = 0; f <= 7; ++f) {
    const std::string n = std::to_string(f);
    EXPECT_EQ(readAll(path("ref_" + n + ".pfm")), readAll(path("k_" + n + ".pfm"))) << f;
  }
  EXPECT_FALSE(fs::exists(path("ck")));
  const std::string report = readAll(path("r.json"));
  EXPECT_EQ(report.find("\"resumed_pixels\": 0,"), std::string::npos) << report;
}

// The serial render with a checkpoint: killed and resumed the same way.
TEST_F(AnimationCliTest, ASerialSequenceWithACheckpointResumes) {
  const std::string size = " --width 64 --height 48 --spp 4 --fps 4 -q --frames 0-5 --threads 1";
  ASSERT_EQ(run("render " + kScene + size + " -o " + path("ref_#.pfm")).exitCode, 0);
  const std::string command = prt::e2e::prtBinary() + " render " + kScene + size + " -o " +
                              path("k_#.pfm") + " --checkpoint " + path("ck") +
                              " --checkpoint-every 0.02";
  const pid_t child = fork();
  ASSERT_GE(child, 0);
  if (child == 0) {
    execl("/bin/sh", "sh", "-c", ("exec " + command + " >/dev/null 2>&1").c_str(), nullptr);
    _exit(127);
  }
  for (int i = 0; i < 400 && !fs::exists(path("k_1.pfm")); ++i) {
    std::this_thread::sleep_for(std::chrono::milliseconds(10));
  }
  kill(child, SIGKILL);
  int status = 0;
  waitpid(child, &status, 0);
  const Result resumed = run("render " + kScene + size + " -o " + path("k_#.pfm") +
                             " --checkpoint " + path("ck") + " --resume");
  ASSERT_EQ(resumed.exitCode, 0) << resumed.output;
  for (int f = 0; f <= 5; ++f) {
    const std::string n = std::to_string(f);
    EXPECT_EQ(readAll(path("ref_" + n + ".pfm")), readAll(path("k_" + n + ".pfm"))) << f;
  }
}

}  // namespace
}  // namespace prt
