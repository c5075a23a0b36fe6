// End-to-end tests of animations through the prt command: a sequence is one job whose frames
// are each bit for bit the frame rendered alone (--frame N), serially, under the thread driver
// with every strategy and across a SIGKILL and --resume; the flags that name frames and the
// output pattern are checked before anything renders.

#include <gtest/gtest.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>
#include <thread>
#include <vector>

#include "prt_command.h"

namespace prt {
namespace {

namespace fs = std::filesystem;
using prt::e2e::Result;
using prt::e2e::run;
using AnimationCliTest = prt::e2e::ScratchDirTest;

const fs::path kAnimationSource(PRT_SOURCE_DIR);

std::string readWhole(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

const std::string kKeyframesScene = (kAnimationSource / "scenes" / "keyframes.scene").string();
const std::string kGltfScene = (kAnimationSource / "scenes" / "animated.scene").string();
const std::string kSize = " --width 32 --height 24 --spp 2 --fps 2 -q";

TEST_F(AnimationCliTest, EveryFrameOfASequenceIsThatFrameRenderedAlone) {
  for (const std::string& scene : {kKeyframesScene, kGltfScene}) {
    const Result seq = run("render " + scene + kSize + " --frames 0-6:3 -o " + path("s_##.pfm"));
    ASSERT_EQ(seq.exitCode, 0) << seq.output;
    for (const char* f : {"0", "3", "6"}) {
      const std::string alone = path(std::string("alone_") + f + ".pfm");
      ASSERT_EQ(run("render " + scene + kSize + " --frame " + f + " -o " + alone).exitCode, 0);
      EXPECT_EQ(readWhole(alone), readWhole(path(std::string("s_0") + f + ".pfm"))) << scene << f;
    }
    EXPECT_FALSE(fs::exists(path("s_01.pfm")));  // the step skips it
    EXPECT_NE(readWhole(path("s_00.pfm")), readWhole(path("s_06.pfm"))) << scene << ": nothing moved";
  }
}

TEST_F(AnimationCliTest, EveryStrategyRendersTheSequenceBitForBit) {
  ASSERT_EQ(run("render " + kKeyframesScene + kSize + " --frames 0-5 -o " + path("ref_#.pfm")).exitCode, 0);
  for (const char* strategy : {"adaptive", "scatter", "hybrid", "reservoir", "reservoir-scatter",
                               "frames", "self", "stealing", "awf-b"}) {
    const Result r = run("render " + kKeyframesScene + kSize + " --frames 0-5 --workers 3 --slowdown 1,2,3 "
                         "--batch 16 --strategy " + strategy + " -o " + path("p_#.pfm") +
                         " --report " + path("r.json"));
    ASSERT_EQ(r.exitCode, 0) << strategy << "\n" << r.output;
    for (int f = 0; f <= 5; ++f) {
      const std::string n = std::to_string(f);
      EXPECT_EQ(readWhole(path("ref_" + n + ".pfm")), readWhole(path("p_" + n + ".pfm")))
          << strategy << " frame " << f;
    }
    const std::string report = readWhole(path("r.json"));
    EXPECT_NE(report.find("\"frame_count\": 6"), std::string::npos) << strategy;
  }
}

// An import's keyed placement moves the whole file (a model without an animation of its own),
// under the thread driver as serially.
TEST_F(AnimationCliTest, AKeyedImportMovesTheWholeFile) {
  const std::string crate = (kAnimationSource / "scenes" / "models" / "crate.glb").string();
  const std::string scene = write(
      "moving.scene", "image { width 32 height 24 }\n"
                      "import { file \"" + crate + "\" key 2 { translate 1 0 0 rotate 0 90 0 } }\n"
                      "plane { point 0 0 0 normal 0 1 0 }\n");
  ASSERT_EQ(run("render " + scene + kSize + " --frames 0-4:2 -o " + path("s_#.pfm")).exitCode, 0);
  const Result r = run("render " + scene + kSize + " --frames 0-4:2 --workers 2 -o " +
                       path("p_#.pfm"));
  ASSERT_EQ(r.exitCode, 0) << r.output;
  for (const char* f : {"0", "2", "4"}) {
    EXPECT_EQ(readWhole(path(std::string("s_") + f + ".pfm")),
              readWhole(path(std::string("p_") + f + ".pfm"))) << f;
  }
  EXPECT_NE(readWhole(path("s_0.pfm")), readWhole(path("s_4.pfm")));
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
    const std::string text = readWhole(path(file));
    const size_t at = text.find("\"elapsed_s\": ");
    return std::stod(text.substr(at + 13));
  };
  EXPECT_LT(elapsed("a.json") * 1.2, elapsed("f.json"));
  EXPECT_NE(run("simulate --workers 4 --frames 0").exitCode, 0);
}

// The run's page of a sequence shows a sheet of its frames, one frame's ownership map and
// the frame boundaries on its timeline.
TEST_F(AnimationCliTest, TheRunPageOfASequenceShowsItsFrames) {
  const Result r = run("render " + kKeyframesScene + kSize + " --frames 0-20:4 --workers 2 -o " +
                       path("f_##.png") + " --html " + path("page.html"));
  ASSERT_EQ(r.exitCode, 0) << r.output;
  const std::string page = readWhole(path("page.html"));
  EXPECT_NE(page.find("6 frames of 32×24"), std::string::npos);
  EXPECT_NE(page.find("shown: frames 0, 4, 8, 12, 16, 20"), std::string::npos);
  EXPECT_NE(page.find("ownership_map"), std::string::npos);
  EXPECT_NE(page.find("class=\"frame-line\""), std::string::npos) << "frame boundaries";
  EXPECT_NE(page.find("frame 20 complete at"), std::string::npos);
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
    const Result r = run("render " + kKeyframesScene + kSize + " " + c.flags);
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
  ASSERT_EQ(run("render " + kKeyframesScene + size + " -o " + path("ref_#.pfm")).exitCode, 0);
  const std::string command = prt::e2e::prtBinary() + " render " + kKeyframesScene + size +
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
  const Result resumed = run("render " + kKeyframesScene + size + " --workers 2 -o " + path("k_#.pfm") +
                             " --checkpoint " + path("ck") + " --resume --report " +
                             path("r.json"));
  ASSERT_EQ(resumed.exitCode, 0) << resumed.output;
  for (int f = 0; f <= 7; ++f) {
    const std::string n = std::to_string(f);
    EXPECT_EQ(readWhole(path("ref_" + n + ".pfm")), readWhole(path("k_" + n + ".pfm"))) << f;
  }
  EXPECT_FALSE(fs::exists(path("ck")));
  const std::string report = readWhole(path("r.json"));
  EXPECT_EQ(report.find("\"resumed_pixels\": 0,"), std::string::npos) << report;
  // What is left is each frame's own share of pixels: a worker prepares each frame about once,
  // as in an uninterrupted run (a worker that met frames mixed in its batches once prepared
  // them for nearly every batch, a resume many times slower than the whole render).
  int workers = 0;
  for (size_t at = report.find("\"frames_built\": "); at != std::string::npos;
       at = report.find("\"frames_built\": ", at + 1)) {
    ++workers;
    const long built = std::stol(report.substr(at + 16));
    EXPECT_GE(built, 1) << report;
    EXPECT_LE(built, 3 * 8) << "frames prepared by one worker for 8 frames";
  }
  EXPECT_EQ(workers, 2) << report;
}

// The serial render with a checkpoint: killed and resumed the same way.
TEST_F(AnimationCliTest, ASerialSequenceWithACheckpointResumes) {
  const std::string size = " --width 64 --height 48 --spp 4 --fps 4 -q --frames 0-5 --threads 1";
  ASSERT_EQ(run("render " + kKeyframesScene + size + " -o " + path("ref_#.pfm")).exitCode, 0);
  const std::string command = prt::e2e::prtBinary() + " render " + kKeyframesScene + size + " -o " +
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
  const Result resumed = run("render " + kKeyframesScene + size + " -o " + path("k_#.pfm") +
                             " --checkpoint " + path("ck") + " --resume");
  ASSERT_EQ(resumed.exitCode, 0) << resumed.output;
  for (int f = 0; f <= 5; ++f) {
    const std::string n = std::to_string(f);
    EXPECT_EQ(readWhole(path("ref_" + n + ".pfm")), readWhole(path("k_" + n + ".pfm"))) << f;
  }
}

// A shell command's stdout.
Result shell(const std::string& command) {
  Result r;
  FILE* pipe = popen(command.c_str(), "r");
  if (pipe == nullptr) return r;
  char buffer[4096];
  size_t n = 0;
  while ((n = fread(buffer, 1, sizeof buffer, pipe)) > 0) r.output.append(buffer, n);
  const int status = pclose(pipe);
  r.exitCode = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  return r;
}

bool haveFfmpeg() {
  return std::system("command -v ffmpeg >/dev/null 2>&1 && command -v ffprobe >/dev/null 2>&1") ==
         0;
}

// Files in the scratch folder whose names hold ".tmp-": a temporary left behind.
std::vector<std::string> temporariesIn(const std::string& folder) {
  std::vector<std::string> found;
  for (const auto& e : fs::directory_iterator(folder)) {
    const std::string name = e.path().filename().string();
    if (name.find(".tmp-") != std::string::npos) found.push_back(name);
  }
  return found;
}

// --video: the frames, fed to Debian's ffmpeg in order, become a video another tool (ffprobe)
// reads back with every frame, at the animation's speed over the step, padded to even sizes.
TEST_F(AnimationCliTest, VideoOfASequenceHasEveryFrameAtTheAnimationsSpeed) {
  if (!haveFfmpeg()) GTEST_SKIP() << "ffmpeg and ffprobe are not installed (scripts/install-deps.sh)";
  // An older frame beside the pattern's is not picked up: only this run's frames are fed.
  write("f_99.png", "not a frame of this run");
  const Result r = run("render " + kKeyframesScene + " --width 33 --height 25 --spp 1 --fps 8 "
                       "--frames 0-22:2 --workers 2 -o " + path("f_##.png") + " --video " +
                       path("v.mp4"));
  ASSERT_EQ(r.exitCode, 0) << r.output;
  EXPECT_NE(r.output.find("v.mp4: video of 12 frames at 4 frames per second"), std::string::npos)
      << r.output;
  const Result probe = shell(
      "ffprobe -v error -count_frames -select_streams v:0 -show_entries "
      "stream=codec_name,width,height,pix_fmt,r_frame_rate,nb_read_frames -of csv=p=0 " +
      path("v.mp4"));
  EXPECT_EQ(probe.output, "h264,34,26,yuv420p,4/1,12\n");
  EXPECT_TRUE(temporariesIn(dir_.string()).empty());
  // A serial sequence, quiet, to a container of ffmpeg's own choice.
  const Result gif = run("render " + kKeyframesScene + " --width 16 --height 12 --spp 1 --frames 0-4 -q "
                         "-o " + path("g_#.ppm") + " --video " + path("v.gif"));
  ASSERT_EQ(gif.exitCode, 0) << gif.output;
  EXPECT_EQ(gif.output, "");
  EXPECT_EQ(shell("ffprobe -v error -count_frames -show_entries "
                               "stream=codec_name,nb_read_frames -of csv=p=0 " + path("v.gif"))
                .output,
            "gif,5\n");
}

TEST_F(AnimationCliTest, VideoProblemsAreCleanErrorsAndKeepTheFrames) {
  const std::string base = "render " + kKeyframesScene + " --width 16 --height 12 --spp 1 -q ";
  // Refused before anything renders (exit 2, no frames).
  EXPECT_EQ(run(base + "-o " + path("a.png") + " --video " + path("a.mp4")).exitCode, 2);
  EXPECT_EQ(run(base + "--frames 0-2 -o " + path("b_#.png") + " --video " + path("b")).exitCode,
            2);
  const Result missing = run(base + "--frames 0-2 -o " + path("c_#.png") + " --video " +
                             path("c.mp4"), "PRT_FFMPEG=/nonexistent/ffmpeg ");
  EXPECT_EQ(missing.exitCode, 2);
  EXPECT_NE(missing.output.find("--video needs ffmpeg"), std::string::npos) << missing.output;
  EXPECT_FALSE(fs::exists(path("c_0.png")));
  // An ffmpeg that fails after the render: exit 1 with what it said; the frames stay, no
  // video and no temporary files.
  const std::string failing = write("ffmpeg-fails", "#!/bin/sh\ncat >/dev/null\n"
                                                    "echo 'Unknown encoder boom' >&2\nexit 3\n");
  fs::permissions(failing, fs::perms::owner_all);
  const Result failed = run(base + "--frames 0-2 --workers 2 -o " + path("d_#.png") +
                            " --video " + path("d.mp4"), "PRT_FFMPEG=" + failing + " ");
  EXPECT_EQ(failed.exitCode, 1) << failed.output;
  EXPECT_NE(failed.output.find("Unknown encoder boom"), std::string::npos) << failed.output;
  EXPECT_NE(failed.output.find("frames are written"), std::string::npos) << failed.output;
  for (const char* f : {"d_0.png", "d_1.png", "d_2.png"}) EXPECT_TRUE(fs::exists(path(f))) << f;
  EXPECT_FALSE(fs::exists(path("d.mp4")));
  // An ffmpeg that stops reading at once, frames larger than a pipe holds (prt must not die
  // of SIGPIPE), and one that reads everything and writes nothing.
  const std::string deaf = write("ffmpeg-deaf", "#!/bin/sh\nexit 0\n");
  fs::permissions(deaf, fs::perms::owner_all);
  const Result stopped =
      run("render " + kKeyframesScene + " --width 200 --height 150 --spp 1 -q --frames 0-1 -o " +
          path("e_#.ppm") + " --video " + path("e.mp4"), "PRT_FFMPEG=" + deaf + " ");
  EXPECT_EQ(stopped.exitCode, 1) << stopped.output;
  EXPECT_NE(stopped.output.find("stopped reading"), std::string::npos) << stopped.output;
  EXPECT_FALSE(fs::exists(path("e.mp4")));
  const std::string silent = write("ffmpeg-silent", "#!/bin/sh\ncat >/dev/null\nexit 0\n");
  fs::permissions(silent, fs::perms::owner_all);
  const Result nothing = run(base + "--frames 0-2 -o " + path("g_#.png") + " --video " +
                             path("g.mp4"), "PRT_FFMPEG=" + silent + " ");
  EXPECT_EQ(nothing.exitCode, 1) << nothing.output;
  EXPECT_NE(nothing.output.find("without writing the video"), std::string::npos)
      << nothing.output;
  EXPECT_FALSE(fs::exists(path("g.mp4")));
  EXPECT_TRUE(temporariesIn(dir_.string()).empty());
}

// Ctrl-C while ffmpeg runs (SIGINT to the whole process group, as a terminal sends it): exit
// 130, no video and no temporary file left.
TEST_F(AnimationCliTest, CtrlCWhileTheVideoIsMadeLeavesNothingBehind) {
  const std::string slow = write("ffmpeg-slow", "#!/bin/sh\nfor a; do out=$a; done\n"
                                                "echo partial > \"$out\"\nexec sleep 30\n");
  fs::permissions(slow, fs::perms::owner_all);
  const std::string command = "PRT_FFMPEG=" + slow + " exec " + prt::e2e::prtBinary() +
                              " render " + kKeyframesScene + " --width 16 --height 12 --spp 1 -q "
                              "--frames 0-2 -o " + path("f_#.png") + " --video " +
                              path("v.mp4") + " >/dev/null 2>&1";
  const pid_t child = prt::e2e::spawnShellGroup(command);
  ASSERT_GE(child, 0);
  // Until ffmpeg has written into the temporary video.
  bool started = false;
  for (int i = 0; i < 400 && !started; ++i) {
    started = !temporariesIn(dir_.string()).empty() && fs::exists(path("f_2.png"));
    if (!started) std::this_thread::sleep_for(std::chrono::milliseconds(25));
  }
  std::this_thread::sleep_for(std::chrono::milliseconds(200));
  kill(-child, SIGINT);
  int status = 0;
  waitpid(child, &status, 0);
  ASSERT_TRUE(started);
  EXPECT_TRUE(WIFEXITED(status) && WEXITSTATUS(status) == 128 + SIGINT) << status;
  EXPECT_FALSE(fs::exists(path("v.mp4")));
  EXPECT_TRUE(temporariesIn(dir_.string()).empty());
}

// Whether process `pid` is gone (a zombie waiting for init counts as gone).
bool processGone(pid_t pid) {
  std::ifstream stat("/proc/" + std::to_string(pid) + "/stat");
  std::string text;
  if (!std::getline(stat, text)) return true;
  const size_t close = text.rfind(')');
  return close != std::string::npos && close + 2 < text.size() && text[close + 2] == 'Z';
}

// A stalled ffmpeg behind --video is ended at --video-timeout, with its child: the run fails
// with exit 1 and says why, the frames stay, no video and no temporary is left.
TEST_F(AnimationCliTest, AStalledEncoderIsEndedAtItsDeadline) {
  const std::string ffmpeg = write("ffmpeg-stalled", "#!/bin/sh\nsleep 300 &\necho $! > " +
                                                         path("child.pid") + "\nwait\n");
  fs::permissions(ffmpeg, fs::perms::owner_all);
  const auto start = std::chrono::steady_clock::now();
  const Result r = run("render " + kKeyframesScene + " --width 16 --height 12 --spp 1 "
                       "--frames 0-2 --workers 2 -o " + path("f_#.png") + " --video " +
                       path("v.mp4") + " --video-timeout 2",
                       "PRT_FFMPEG=" + ffmpeg + " timeout -k 2 40 ");
  const double seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  EXPECT_EQ(r.exitCode, 1) << r.output;
  EXPECT_LT(seconds, 30) << "the encoder's deadline is 2 s";
  EXPECT_NE(r.output.find("made no progress for 2 s"), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("--video-timeout"), std::string::npos) << r.output;
  for (const char* f : {"f_0.png", "f_1.png", "f_2.png"}) EXPECT_TRUE(fs::exists(path(f))) << f;
  EXPECT_FALSE(fs::exists(path("v.mp4")));
  EXPECT_TRUE(temporariesIn(dir_.string()).empty());
  const pid_t child = static_cast<pid_t>(std::stol(readWhole(path("child.pid"))));
  EXPECT_TRUE(processGone(child)) << "ffmpeg's child outlived it";
  if (!processGone(child)) kill(child, SIGKILL);
}

// SIGTERM to prt alone while a stalled ffmpeg runs ends the run at once (143), serially and in
// parallel (where the first signal only asks the run to stop): ffmpeg and its child are
// ended, no temporary is left, the frames stay.
TEST_F(AnimationCliTest, ASignalEndsAStalledEncoderAtOnce) {
  const std::string ffmpeg = write("ffmpeg-stalled", "#!/bin/sh\nsleep 300 &\necho $! > " +
                                                         path("child.pid") + "\nwait\n");
  fs::permissions(ffmpeg, fs::perms::owner_all);
  for (const char* driver : {"--workers 2", "--threads 1"}) {
    fs::remove(path("child.pid"));
    const std::string command = "PRT_FFMPEG=" + ffmpeg + " exec " + prt::e2e::prtBinary() +
                                " render " + kKeyframesScene + " --width 16 --height 12 "
                                "--spp 1 -q --frames 0-2 " + driver + " -o " + path("f_#.png") +
                                " --video " + path("v.mp4") + " >/dev/null 2>&1";
    const pid_t prt = prt::e2e::spawnShellGroup(command);
    ASSERT_GE(prt, 0);
    for (int i = 0; i < 400 && !fs::exists(path("child.pid")); ++i) {
      std::this_thread::sleep_for(std::chrono::milliseconds(25));
    }
    std::this_thread::sleep_for(std::chrono::milliseconds(200));
    ASSERT_TRUE(fs::exists(path("child.pid"))) << driver;
    kill(prt, SIGTERM);
    int status = 0;
    bool ended = false;
    for (int i = 0; i < 200 && !ended; ++i) {  // 10 s: "at once", generously
      ended = waitpid(prt, &status, WNOHANG) == prt;
      if (!ended) std::this_thread::sleep_for(std::chrono::milliseconds(50));
    }
    if (!ended) {
      kill(-prt, SIGKILL);
      waitpid(prt, &status, 0);
    }
    EXPECT_TRUE(ended) << driver << ": SIGTERM was not acted on";
    EXPECT_TRUE(WIFEXITED(status) && WEXITSTATUS(status) == 128 + SIGTERM) << driver << status;
    const pid_t child = static_cast<pid_t>(std::stol(readWhole(path("child.pid"))));
    for (int i = 0; i < 40 && !processGone(child); ++i) {
      std::this_thread::sleep_for(std::chrono::milliseconds(50));
    }
    EXPECT_TRUE(processGone(child)) << driver << ": ffmpeg's child outlived the run";
    if (!processGone(child)) kill(child, SIGKILL);
    EXPECT_FALSE(fs::exists(path("v.mp4")));
    EXPECT_TRUE(temporariesIn(dir_.string()).empty()) << driver;
    for (const char* f : {"f_0.png", "f_1.png", "f_2.png"}) EXPECT_TRUE(fs::exists(path(f))) << f;
  }
}

}  // namespace
}  // namespace prt
