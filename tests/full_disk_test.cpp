// End-to-end tests of renders whose output disk is full: a real tmpfs, small enough to fill,
// mounted for each test (root only; skipped where mounting is not allowed) and unmounted
// after. The master's own write failures are its own, never a worker's: the run ends with a
// non-zero exit naming the file and the error, the checkpoint keeps what is finished (a
// still: every pixel; a sequence: its pixels, so the frames not written are written by
// --resume), and no half-written file is left.

#include <cstdio>
#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>
#include <vector>

#include "prt_command.h"

namespace prt {
namespace {

namespace fs = std::filesystem;
using prt::e2e::Result;
using prt::e2e::run;

const std::string kFullDiskScene =
    (fs::path(PRT_SOURCE_DIR) / "scenes" / "keyframes.scene").string();

std::string fullDiskRead(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

class FullDiskTest : public prt::e2e::ScratchDirTest {
 protected:
  void SetUp() override {
    ScratchDirTest::SetUp();
    disk_ = dir_ / "disk";
    fs::create_directories(disk_);
  }
  void TearDown() override {
    if (mounted_) (void)std::system(("umount '" + disk_.string() + "'").c_str());
    ScratchDirTest::TearDown();
  }

  // A tmpfs of `size` (mount's syntax: 64k) on disk_; false where it cannot be mounted.
  bool mountDisk(const std::string& size) {
    const std::string options = mounted_ ? "remount,size=" + size : "size=" + size;
    const std::string command = "mount -t tmpfs -o " + options + " prt-full-disk '" +
                                disk_.string() + "' 2>/dev/null";
    if (std::system(command.c_str()) != 0) return false;
    mounted_ = true;
    return true;
  }
  std::string onDisk(const std::string& name) const { return (disk_ / name).string(); }

  // Files on the disk whose names hold ".tmp-": a half-written file left behind.
  std::vector<std::string> temporaries() const {
    std::vector<std::string> found;
    for (const auto& e : fs::directory_iterator(disk_)) {
      const std::string name = e.path().filename().string();
      if (name.find(".tmp-") != std::string::npos) found.push_back(name);
    }
    return found;
  }

  fs::path disk_;
  bool mounted_ = false;
};

#define PRT_MOUNT_OR_SKIP(size)                                                    \
  if (!mountDisk(size)) {                                                          \
    GTEST_SKIP() << "cannot mount a tmpfs here (needs root): the full-disk cases " \
                    "are not tested";                                              \
  }

// 30 frames of 2,317 bytes each (a page of the tmpfs each) to a disk of 16 pages: the frame
// that does not fit stops the run, whatever the strategy; the run says which file and why,
// keeps its pixels, and --resume on a disk with room writes every frame bit for bit.
TEST_F(FullDiskTest, AParallelSequenceStopsAtTheFrameThatDoesNotFitAndResumes) {
  PRT_MOUNT_OR_SKIP("64k");
  const std::string size = " --width 32 --height 24 --spp 1 --frames 0-29 ";
  ASSERT_EQ(run("render " + kFullDiskScene + size + "-q --threads 1 -o " + path("ref_##.ppm"))
                .exitCode,
            0);
  for (const char* strategy : {"adaptive", "self"}) {
    for (const auto& e : fs::directory_iterator(disk_)) fs::remove(e.path());
    ASSERT_TRUE(mountDisk("64k"));
    const std::string command = "render " + kFullDiskScene + size + "--workers 2 --strategy " +
                                strategy + " -o " + onDisk("f_##.ppm") + " --checkpoint " +
                                path("ck");
    const Result full = run(command);
    EXPECT_EQ(full.exitCode, 1) << strategy << "\n" << full.output;
    EXPECT_NE(full.output.find("cannot write '" + onDisk("f_")), std::string::npos)
        << full.output;
    EXPECT_NE(full.output.find("No space left on device"), std::string::npos) << full.output;
    EXPECT_EQ(full.output.find("malformed"), std::string::npos) << full.output;
    EXPECT_EQ(full.output.find("was lost"), std::string::npos) << full.output;
    EXPECT_NE(full.output.find("are saved in '" + path("ck") + "'"), std::string::npos)
        << full.output;
    ASSERT_TRUE(fs::exists(path("ck"))) << strategy;
    EXPECT_TRUE(temporaries().empty());
    // Room again: the frames not written are, from the checkpoint.
    ASSERT_TRUE(mountDisk("1m"));
    const Result resumed = run(command + " --resume -q --report " + path("r.json"));
    ASSERT_EQ(resumed.exitCode, 0) << strategy << "\n" << resumed.output;
    for (int f = 0; f <= 29; ++f) {
      char n[8];
      std::snprintf(n, sizeof n, "%02d", f);
      const bool same =
          fullDiskRead(path(std::string("ref_") + n + ".ppm")) == fullDiskRead(onDisk(std::string("f_") + n + ".ppm"));
      EXPECT_TRUE(same) << strategy << " frame " << f;
    }
    EXPECT_EQ(fullDiskRead(path("r.json")).find("\"resumed_pixels\": 0,"), std::string::npos);
    EXPECT_FALSE(fs::exists(path("ck")));
  }
}

// A still whose image does not fit: exit 2 naming the file, and the checkpoint holds every
// pixel, so --resume writes the image without rendering any again; serially and in parallel.
TEST_F(FullDiskTest, AStillThatDoesNotFitKeepsEveryPixel) {
  PRT_MOUNT_OR_SKIP("8k");
  const std::string size = " --width 80 --height 60 --spp 1 -q ";
  ASSERT_EQ(run("render " + kFullDiskScene + size + "-o " + path("ref.ppm")).exitCode, 0);
  for (const char* driver : {"--workers 2", "--threads 2"}) {
    ASSERT_TRUE(mountDisk("8k"));
    const std::string command = "render " + kFullDiskScene + size + driver + " -o " +
                                onDisk("still.ppm") + " --checkpoint " + path("ck");
    const Result full = run(command);
    EXPECT_EQ(full.exitCode, 2) << driver << "\n" << full.output;
    EXPECT_NE(full.output.find("cannot write '" + onDisk("still.ppm") +
                               "': No space left on device"),
              std::string::npos)
        << full.output;
    EXPECT_NE(full.output.find("the 4800 finished pixels are saved in '" + path("ck") + "'"),
              std::string::npos)
        << full.output;
    EXPECT_TRUE(temporaries().empty());
    EXPECT_FALSE(fs::exists(onDisk("still.ppm")));
    ASSERT_TRUE(mountDisk("1m"));
    const bool parallel = std::string(driver) == "--workers 2";
    const Result resumed =
        run(command + " --resume" + (parallel ? " --report " + path("r.json") : ""));
    ASSERT_EQ(resumed.exitCode, 0) << driver << "\n" << resumed.output;
    EXPECT_TRUE(fullDiskRead(path("ref.ppm")) == fullDiskRead(onDisk("still.ppm"))) << driver;
    if (parallel) {  // written, not rendered again
      EXPECT_NE(fullDiskRead(path("r.json")).find("\"resumed_pixels\": 4800,"), std::string::npos);
    }
    EXPECT_FALSE(fs::exists(path("ck")));
    fs::remove(onDisk("still.ppm"));
  }
  // The automatic checkpoint beside an image on the full disk cannot be written either, and
  // the run says so instead of claiming it.
  ASSERT_TRUE(mountDisk("8k"));
  const Result both = run("render " + kFullDiskScene + size + "--workers 2 -o " +
                          onDisk("auto.ppm"));
  EXPECT_EQ(both.exitCode, 2) << both.output;
  EXPECT_NE(both.output.find("could not be saved either"), std::string::npos) << both.output;
  EXPECT_TRUE(temporaries().empty());
}

}  // namespace
}  // namespace prt
