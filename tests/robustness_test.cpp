// End-to-end tests that every run ends and every bad input gets a clear error: the corpus of
// malformed scenes in tests/malformed, scenes whose cost or values would grow without bound,
// a FIFO as the scene, outputs checked before rendering, flags out of range, signals and
// running out of memory.

#include <gtest/gtest.h>
#include <signal.h>
#include <fcntl.h>
#include <spawn.h>
#include <sys/stat.h>
#include <sys/wait.h>

#include <chrono>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <thread>
#include <vector>

#include "core/subprocess.h"
#include "image/image_io.h"
#include "prt_command.h"

namespace prt {
namespace {

namespace fs = std::filesystem;

using prt::e2e::Result;
using prt::e2e::run;
using Robustness = prt::e2e::ScratchDirTest;

const char* kSmallScene =
    "camera { eye 0 1 -5 look_at 0 0.5 0 fov 40 }\n"
    "image { width 16 height 12 output \"x.png\" }\n"
    "light point { position -3 5 -5 }\n"
    "sphere { center 0 0.5 0 radius 0.5 surface { color 1 0 0 } }\n";

size_t filesIn(const fs::path& dir) {
  return static_cast<size_t>(std::distance(fs::directory_iterator(dir), {}));
}

// "FILE:LINE:COL: error: ...", then the line and a caret under the culprit. (Checked by hand:
// std::regex recurses per character and overflows the stack on the corpus's 100 kB line.)
bool isLocatedError(const std::string& output, const std::string& file) {
  if (output.rfind(file + ":", 0) != 0) return false;
  size_t i = file.size() + 1;
  for (int field = 0; field < 2; ++field) {
    const size_t digits = output.find_first_not_of("0123456789", i);
    if (digits == i || digits == std::string::npos || output[digits] != ':') return false;
    i = digits + 1;
  }
  if (output.compare(i, 8, " error: ") != 0) return false;
  const size_t lineStart = output.find("\n  ", i);
  return lineStart != std::string::npos && output.find('^', lineStart) != std::string::npos;
}

// Every file of the corpus must give file:line:col, the line with a caret, exit code 2 and
// no output at all.
TEST_F(Robustness, EveryMalformedSceneGivesALocatedErrorAndWritesNothing) {
  const fs::path corpus = fs::path(PRT_SOURCE_DIR) / "tests" / "malformed";
  const fs::path out = dir_ / "out";
  fs::create_directories(out);
  int scenes = 0;
  for (const auto& entry : fs::directory_iterator(corpus)) {
    if (entry.path().extension() != ".scene") continue;
    ++scenes;
    const std::string file = entry.path().string();
    const Result r = run("render '" + file + "' -q -o " + (out / "image.png").string() +
                         " --workers 2 --report " + (out / "report.json").string());
    EXPECT_EQ(r.exitCode, 2) << file << "\n" << r.output;
    EXPECT_TRUE(isLocatedError(r.output, file)) << "not a located error:\n" << r.output;
    EXPECT_EQ(filesIn(out), 0u) << file << " left output behind";
  }
  EXPECT_GE(scenes, 50);
}

TEST_F(Robustness, GlassInGlassAtDepth64Ends) {
  // Each hit spawns a reflected and a transmitted ray: 2^64 rays per sample without the path
  // weight cut-off (this ran for ever). With it, under a second; CTest's timeout is the bound.
  const std::string scene = write(
      "glass.scene",
      "camera { eye 0 0 -5 look_at 0 0 0 fov 40 }\n"
      "image { width 16 height 12 }\n"
      "environment { max_depth 64 }\n"
      "light point { position 2 3 -4 }\n"
      "sphere { center 0 0 0 radius 1 surface { color 1 1 1 reflect 0.5 transmit 0.5 ior 1.5 } }\n"
      "box { min -3 -3 -3 max 3 3 3 surface { color 1 1 1 reflect 0.5 transmit 0.5 ior 1.3 } }\n");
  const Result r = run("render " + scene + " -q --spp 4 -o " + path("glass.pfm"));
  ASSERT_EQ(r.exitCode, 0) << r.output;
  const Image image = readImage(path("glass.pfm"));
  for (size_t p = 0; p < 16 * 12; ++p) EXPECT_TRUE(std::isfinite(image.at(p).x));
}

TEST_F(Robustness, LargestColoursGiveFinitePixels) {
  // Every colour at its bound of 1e6, many lights, mirrors and glass: no infinity in a PFM.
  std::string text =
      "camera { eye 0 1 -5 look_at 0 0.5 0 fov 60 }\n"
      "image { width 12 height 9 }\n"
      "environment { background 1e6 1e6 1e6 ambient 1e6 1e6 1e6 max_depth 64 }\n"
      "sphere { center 0 0.5 0 radius 0.5 surface { color 1e6 1e6 1e6 ambient 1 diffuse 1 "
      "specular 1 phong 1 reflect 0.5 transmit 0.5 ior 1.5 } }\n"
      "plane { point 0 0 0 normal 0 1 0 surface { color 1e6 1e6 1e6 diffuse 1 reflect 1 } }\n";
  for (int i = 0; i < 200; ++i) text += "light point { position 0 3 -2 color 1e6 1e6 1e6 }\n";
  const Result r = run("render " + write("bright.scene", text) + " -q -o " + path("b.pfm"));
  ASSERT_EQ(r.exitCode, 0) << r.output;
  const Image image = readImage(path("b.pfm"));
  for (size_t p = 0; p < 12 * 9; ++p) {
    const Color c = image.at(p);
    EXPECT_TRUE(std::isfinite(c.x) && std::isfinite(c.y) && std::isfinite(c.z)) << p;
  }
}

TEST_F(Robustness, FifoAsTheSceneIsRefusedAtOnce) {
  // Opening it would wait for a writer for ever.
  ASSERT_EQ(::mkfifo(path("pipe.scene").c_str(), 0600), 0);
  const Result r = run("render " + path("pipe.scene") + " -q -o " + path("out.png"));
  EXPECT_EQ(r.exitCode, 2);
  EXPECT_NE(r.output.find("is a FIFO (named pipe), not a regular file"), std::string::npos)
      << r.output;
}

TEST_F(Robustness, EveryOutputIsCheckedBeforeRendering) {
  const std::string scene = write("ok.scene", kSmallScene);
  const std::string image = " -q -o " + path("out.png");
  const std::string missing = path("missing") + "/file";
  for (const std::string& flags :
       {" --workers 2 --report " + missing + ".json", " --workers 2 --trace " + missing + ".json",
        " --workers 2 --ownership " + missing + ".png", " --cost-map " + missing + ".cost",
        " --workers 2 --report " + dir_.string(), " --workers 2 --ownership " + path("out.png"),
        " --workers 2 --report " + path("r.json") + " --trace " + path("r.json")}) {
    // --measure-serial: the serial render would come first; it must not even start.
    const Result r = run("render " + scene + image + " --measure-serial" + flags);
    EXPECT_EQ(r.exitCode, 2) << flags << "\n" << r.output;
    EXPECT_EQ(r.output.find("measuring the serial time"), std::string::npos) << r.output;
    EXPECT_FALSE(fs::exists(path("out.png"))) << flags;
  }
  const Result r = run("render " + scene + " -q -o " + missing + ".png");
  EXPECT_EQ(r.exitCode, 2);
  EXPECT_NE(r.output.find("cannot write '" + missing + ".png'"), std::string::npos) << r.output;
  EXPECT_EQ(filesIn(dir_), 1u);  // the scene alone
}

TEST_F(Robustness, FlagsOutOfRangeAreRefusedWithReadableMessages) {
  const std::string scene = write("ok.scene", kSmallScene) + " -q -o " + path("out.png");
  const auto refused = [&](const std::string& flags, const std::string& fragment) {
    const Result r = run("render " + scene + " " + flags);
    EXPECT_EQ(r.exitCode, 2) << flags << "\n" << r.output;
    EXPECT_NE(r.output.find(fragment), std::string::npos) << flags << "\n" << r.output;
    EXPECT_LT(r.output.size(), 400u) << "no 300-digit numbers: " << r.output;
  };
  refused("--workers 2 --slowdown 1e12,1", "--slowdown values must be in [1, 1000] (got 1e+12)");
  refused("--workers 2 --slowdown 1e300,1", "(got 1e+300)");
  refused("--workers 2 --inject-fault 2:10:crash", "workers are numbered 0 to 1");
  refused("--workers 2 --inject-fault 1:-5:crash", "PIXELS must be a whole number");
  refused("--workers 2 --inject-fault 1:5:explode", "the fault must be crash, hang or corrupt");
  refused("--workers 2 --inject-fault 1:5", "three fields");
  refused("--inject-fault 0:10:crash", "describe a parallel run; add --workers N");
  refused("-o ''", "needs a file name; found an empty string");
  refused("--workers 2 --report ''", "needs a file name");
  refused("--workers 2 --serial-seconds -1", "must be a positive number of seconds, at most");
  refused("--workers 2 --serial-seconds inf", "must be a positive number of seconds");
  refused("--workers 2 --worker-timeout 1e300", "--worker-timeout: must be a number in [0.1, 86400]; found '1e300'");
  // One rule per flag, whatever the driver: a serial render refuses what a parallel one does,
  // and the message quotes what was given.
  for (const char* driver : {"", "--workers 2 "}) {
    for (const char* value : {"0", "-5", "nan", "inf"}) {
      refused(std::string(driver) + "--checkpoint-every " + value,
              std::string("--checkpoint-every: must be a number in [0.01, 86400]; found '") +
                  value + "'");
    }
    refused(std::string(driver) + "--batch-seconds nan", "--batch-seconds: must be a number in [0, 60]");
    refused(std::string(driver) + "--min-chunk 99999999999999999999",
            "--min-chunk: must be a whole number in [1, 9007199254740992]; found "
            "'99999999999999999999'");
    refused(std::string(driver) + "--chunk 2.5", "--chunk: must be a whole number in");
    refused(std::string(driver) + "--initial-percent nan", "--initial-percent: must be a number in (0, 100]");
  }
  EXPECT_FALSE(fs::exists(path("out.png")));
}

// Found by a hostile pass over the other subcommands.
TEST_F(Robustness, OtherCommandsRefuseAbsurdValuesAndReportFailuresPlainly) {
  const auto refused = [&](const std::string& args, const std::string& fragment) {
    const Result r = run(args);
    EXPECT_EQ(r.exitCode, 2) << args << "\n" << r.output;
    EXPECT_NE(r.output.find(fragment), std::string::npos) << args << "\n" << r.output;
    EXPECT_LT(r.output.size(), 400u) << r.output;
  };
  // A synthetic map of 2^30 pixels took gigabytes and ran for minutes.
  refused("simulate --width 32768 --height 32768", "image too large");
  // Simulated times of 1e301 seconds, printed in 300 digits.
  refused("simulate --latency-us 1e300", "--latency-us must be in [0, 1e9]");
  refused("simulate --bandwidth-mbps 1e-300", "--bandwidth-mbps must be in [0.001, 1e10]");
  refused("simulate --master-service-us 1e300", "--master-service-us must be in [0, 1e9]");
  refused("simulate --batch-seconds inf", "--batch-seconds: must be a number in [0, 60]; found 'inf'");
  refused("simulate --min-chunk 1e20", "--min-chunk: must be a whole number in [1, 9007199254740992]");
  refused("join port --connect-timeout nan", "--connect-timeout: must be a number in [1, 86400]");
  refused("render x.scene --max-memory 12Q", "--max-memory: must be a size such as 512M");
  const std::string scene = write("ok.scene", kSmallScene);
  refused("compare " + scene + " --diff-scale nan --out " + path("cmp"), "--diff-scale");
  refused("render " + scene + " --workers 2 --batch -1 -o " + path("o.png"), "--batch");
  // A POV-Ray that prints nothing and fails: its exit code, not a std::string exception.
  const Result r = run("compare " + scene + " --povray /bin/false --out " + path("cmp"));
  EXPECT_EQ(r.exitCode, 1) << r.output;
  EXPECT_NE(r.output.find("povray exited with code 1"), std::string::npos) << r.output;
}

// Starts a render of the benchmark scene (seconds long), sends `signal` once it runs and
// returns how it ended: its exit code, or -1 if the signal killed it (no handler ran).
int renderKilledBy(int signal, const std::vector<std::string>& flags, const std::string& out,
                   const std::string& errPath = "", int afterMs = 700) {
  std::vector<std::string> args = {prt::e2e::prtBinary(), "render",
                                   std::string(PRT_SOURCE_DIR) + "/scenes/complex.scene",
                                   "-q", "--spp", "64", "--width", "320", "--height", "240",
                                   "-o", out};
  args.insert(args.end(), flags.begin(), flags.end());
  std::vector<char*> argv;
  for (std::string& a : args) argv.push_back(a.data());
  argv.push_back(nullptr);
  pid_t pid = 0;
  posix_spawn_file_actions_t actions;
  posix_spawn_file_actions_init(&actions);
  if (!errPath.empty()) {
    posix_spawn_file_actions_addopen(&actions, STDERR_FILENO, errPath.c_str(),
                                     O_WRONLY | O_CREAT | O_TRUNC, 0644);
  }
  const int spawned = posix_spawn(&pid, argv[0], &actions, nullptr, argv.data(), environ);
  posix_spawn_file_actions_destroy(&actions);
  if (spawned != 0) return -2;
  std::this_thread::sleep_for(std::chrono::milliseconds(afterMs));  // past start-up, rendering
  ::kill(pid, signal);
  int status = 0;
  ::waitpid(pid, &status, 0);
  return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
}

TEST_F(Robustness, SignalsEndARunWith128PlusTheSignalAndNoFiles) {
  EXPECT_EQ(renderKilledBy(SIGTERM, {"--threads", "1", "--no-checkpoint"}, path("a.pfm")),
            128 + SIGTERM);
  EXPECT_EQ(renderKilledBy(SIGINT, {"--workers", "2", "--no-checkpoint"}, path("b.pfm")),
            128 + SIGINT);
  EXPECT_EQ(renderKilledBy(SIGHUP, {"--threads", "2", "--no-checkpoint"}, path("c.pfm")),
            128 + SIGHUP);
  EXPECT_EQ(filesIn(dir_), 0u);
}

// By default a stopped render keeps what it finished: the automatic checkpoint beside its
// output and nothing else, which the same command with --resume completes to the image an
// uninterrupted render gives.
TEST_F(Robustness, ByDefaultAStoppedRenderKeepsItsPixelsForResume) {
  EXPECT_EQ(renderKilledBy(SIGINT, {"--workers", "2"}, path("b.pfm")), 128 + SIGINT);
  EXPECT_EQ(renderKilledBy(SIGTERM, {"--threads", "1"}, path("a.pfm")), 128 + SIGTERM);
  EXPECT_EQ(filesIn(dir_), 2u);
  for (const char* name : {"a.pfm", "b.pfm"}) {
    ASSERT_TRUE(fs::exists(path(name) + ".ckpt")) << name;
    EXPECT_FALSE(fs::exists(path(name))) << name;
  }
  const std::string common = std::string("render ") + PRT_SOURCE_DIR +
                             "/scenes/complex.scene -q --spp 64 --width 320 --height 240 -o ";
  // Without --resume the same command refuses and says what to type.
  const Result refused = run(common + path("a.pfm") + " --threads 1");
  EXPECT_EQ(refused.exitCode, 2) << refused.output;
  EXPECT_NE(refused.output.find("--threads 1 --resume"), std::string::npos) << refused.output;
  EXPECT_NE(refused.output.find("rm '" + path("a.pfm") + ".ckpt'"), std::string::npos)
      << refused.output;
  for (const char* name : {"a.pfm", "b.pfm"}) {
    const Result resumed = run(common + path(name) + " --resume");
    ASSERT_EQ(resumed.exitCode, 0) << resumed.output;
    EXPECT_FALSE(fs::exists(path(name) + ".ckpt")) << name;
  }
  ASSERT_EQ(run(common + path("ref.pfm") + " --no-checkpoint").exitCode, 0);
  const std::string reference = readWholeFile(path("ref.pfm"));
  EXPECT_EQ(readWholeFile(path("a.pfm")), reference);
  EXPECT_EQ(readWholeFile(path("b.pfm")), reference);
}

// A stop signal is answered at once, before the checkpoint is written: a launcher that sends
// SIGKILL soon after SIGTERM must not take the resume command with it. Said once.
TEST_F(Robustness, AStopSaysHowToResumeBeforeSavingAndOnce) {
  for (const std::vector<std::string>& driver :
       {std::vector<std::string>{"--threads", "1"},
        std::vector<std::string>{"--workers", "2", "--slowdown", "4,4"}}) {  // still rendering at 1 s
    std::vector<std::string> flags = driver;
    for (const char* f : {"--checkpoint", "", "--checkpoint-every", "0.2"}) flags.push_back(f);
    flags[driver.size() + 1] = path("run.ckpt");
    const std::string err = path("err.txt");
    EXPECT_EQ(renderKilledBy(SIGTERM, flags, path("run.pfm"), err, 1000), 128 + SIGTERM);
    const std::string text = readWholeFile(err);
    const size_t stopping = text.find("prt: stopping on signal 15: saving the finished pixels in '" +
                                      path("run.ckpt") + "'");
    const size_t command = text.find("prt: to render the rest, run:");
    ASSERT_NE(stopping, std::string::npos) << text;
    ASSERT_NE(command, std::string::npos) << text;
    EXPECT_LT(stopping, command) << text;
    EXPECT_EQ(text.find("prt: to render the rest, run:", command + 1), std::string::npos) << text;
    EXPECT_NE(text.find("--checkpoint-every 0.2 --resume"), std::string::npos) << text;
    fs::remove(path("run.ckpt"));
  }
}

TEST_F(Robustness, OutOfMemoryInWorkerThreadsIsACleanError) {
#if defined(__SANITIZE_ADDRESS__)
  GTEST_SKIP() << "AddressSanitizer reserves more address space than the limit allows";
#endif
  // 20,000 spheres: a serial render fits in 200 MB of address space, eight workers (each with
  // its own copy of the scene) do not. Before, a worker thread's std::bad_alloc aborted the
  // process (SIGABRT, exit 134).
  std::ostringstream text;
  text << "camera { eye 0 0 -60 look_at 0 0 0 fov 40 }\nimage { width 32 height 24 }\n"
          "light point { position 10 20 -30 }\n";
  for (int i = 0; i < 20000; ++i) {
    text << "sphere { center " << (i % 40) - 20 << " " << (i / 40 % 30) - 15 << " "
         << (i / 1200) - 8 << " radius 0.1 }\n";
  }
  const std::string scene = write("many.scene", text.str());
  const std::string limit = "ulimit -v 200000; ";
  const Result serial = run("render " + scene + " -q -o " + path("serial.png"), limit);
  ASSERT_EQ(serial.exitCode, 0) << serial.output;
  const Result parallel = run("render " + scene + " -q --workers 8 -o " + path("out.png"), limit);
  EXPECT_EQ(parallel.exitCode, 1) << parallel.output;
  EXPECT_EQ(parallel.output.rfind("prt: error: out of memory", 0), 0u) << parallel.output;
  EXPECT_FALSE(fs::exists(path("out.png")));
  // Workers that join mid-render start their threads from another thread: a thread that
  // cannot be created there was an uncaught std::system_error (SIGABRT, exit 134).
  const Result joined = run("render " + scene + " -q --workers 1 --join-at 0:1000 -o " +
                                path("joined.png"),
                            limit);
  EXPECT_EQ(joined.exitCode, 1) << joined.output;
  EXPECT_EQ(joined.output.rfind("prt: error: out of memory", 0), 0u) << joined.output;
  EXPECT_FALSE(fs::exists(path("joined.png")));
}

}  // namespace
}  // namespace prt
