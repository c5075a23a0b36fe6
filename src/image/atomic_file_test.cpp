#include "image/atomic_file.h"

#include <gtest/gtest.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <string>

#include "core/input_error.h"

namespace prt {
namespace {

namespace fs = std::filesystem;

class AtomicFile : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::temp_directory_path() /
           ("prt-atomic-" + std::to_string(::getpid()) + "-" +
            ::testing::UnitTest::GetInstance()->current_test_info()->name());
    fs::remove_all(dir_);
    fs::create_directories(dir_);
  }
  void TearDown() override { fs::remove_all(dir_); }

  size_t fileCount() const {
    return static_cast<size_t>(std::distance(fs::directory_iterator(dir_), {}));
  }

  fs::path dir_;
};

// A pid that surely belongs to no process: a child's, once it has been reaped.
pid_t deadPid() {
  const pid_t child = ::fork();
  if (child == 0) ::_exit(0);
  int status = 0;
  ::waitpid(child, &status, 0);
  return child;
}

TEST_F(AtomicFile, SignalsRemoveTheTemporaryFileAndExitWith128PlusTheSignal) {
  for (const int signal : {SIGTERM, SIGINT, SIGHUP}) {
    const std::string target = (dir_ / "out.pfm").string();
    const pid_t child = ::fork();
    if (child == 0) {
      removeTemporaryFilesOnSignals();
      writeFileAtomically(target, [&](std::FILE* f) {
        std::fputs("half an image", f);
        std::fflush(f);
        ::raise(signal);  // as if killed mid-write
        std::fputs(" and the rest", f);
      });
      ::_exit(0);
    }
    int status = 0;
    ASSERT_EQ(::waitpid(child, &status, 0), child);
    ASSERT_TRUE(WIFEXITED(status)) << "signal " << signal;
    EXPECT_EQ(WEXITSTATUS(status), 128 + signal);
    EXPECT_EQ(fileCount(), 0u) << "signal " << signal << " left a file behind";
  }
}

TEST_F(AtomicFile, WritesRemoveStaleTemporaryFilesOfDeadProcessesOnly) {
  const fs::path target = dir_ / "out.png";
  const fs::path stale = dir_ / ("out.png.tmp-" + std::to_string(deadPid()) + "-3");
  const fs::path live = dir_ / ("out.png.tmp-" + std::to_string(::getppid()) + "-0");
  const fs::path other = dir_ / ("other.png.tmp-" + std::to_string(deadPid()) + "-0");
  const fs::path unlike = dir_ / "out.png.tmp-notes";
  for (const fs::path& p : {stale, live, other, unlike}) std::ofstream(p) << "x";
  writeFileAtomically(target.string(), "image");
  EXPECT_FALSE(fs::exists(stale));
  EXPECT_TRUE(fs::exists(live));    // its process still runs
  EXPECT_TRUE(fs::exists(other));   // another file's: not this write's business
  EXPECT_TRUE(fs::exists(unlike));  // not a name this code makes
  EXPECT_TRUE(fs::exists(target));
}

TEST_F(AtomicFile, CheckWritableLeavesNothingAndRefusesWhatCannotBeWritten) {
  const std::string target = (dir_ / "report.json").string();
  checkWritable(target);
  EXPECT_EQ(fileCount(), 0u);
  EXPECT_THROW(checkWritable((dir_ / "missing" / "report.json").string()), InputError);
  EXPECT_THROW(checkWritable(dir_.string()), InputError);
  EXPECT_THROW(checkWritable(""), InputError);
  // An existing file is kept as it was.
  std::ofstream(target) << "old";
  checkWritable(target);
  std::ifstream in(target);
  std::string text;
  in >> text;
  EXPECT_EQ(text, "old");
}

// An output path that is a symbolic link: the file it names gets the contents (in its own
// folder, where the temporary file goes too), the link stays a link; a dangling link gets its
// file made; links that loop are an error that names the path.
TEST_F(AtomicFile, ASymbolicLinkIsFollowedAndKept) {
  fs::create_directories(dir_ / "shared");
  std::ofstream(dir_ / "shared" / "frame.png") << "old";
  fs::create_directories(dir_ / "here");
  fs::create_symlink("../shared/frame.png", dir_ / "here" / "out.png");
  writeFileAtomically((dir_ / "here" / "out.png").string(), "new");
  EXPECT_TRUE(fs::is_symlink(fs::symlink_status(dir_ / "here" / "out.png")));
  std::ifstream in(dir_ / "shared" / "frame.png");
  std::string text;
  in >> text;
  EXPECT_EQ(text, "new");
  EXPECT_EQ(std::distance(fs::directory_iterator(dir_ / "shared"), {}), 1);
  EXPECT_EQ(std::distance(fs::directory_iterator(dir_ / "here"), {}), 1);
  // A link to a link to a file that is not there yet.
  fs::create_symlink(dir_ / "shared" / "later.png", dir_ / "shared" / "next.png");
  fs::create_symlink("../shared/next.png", dir_ / "here" / "chain.png");
  checkWritable((dir_ / "here" / "chain.png").string());
  writeFileAtomically((dir_ / "here" / "chain.png").string(), "made");
  EXPECT_TRUE(fs::is_regular_file(fs::symlink_status(dir_ / "shared" / "later.png")));
  EXPECT_TRUE(fs::is_symlink(fs::symlink_status(dir_ / "here" / "chain.png")));
  {
    TemporaryFile video((dir_ / "here" / "out.png").string(), ".png");
    EXPECT_EQ(fs::path(video.path()).parent_path(), dir_ / "shared");
    std::ofstream(video.path()) << "video";
    video.commit();
  }
  EXPECT_TRUE(fs::is_symlink(fs::symlink_status(dir_ / "here" / "out.png")));
  // Links that loop.
  fs::create_symlink("b.png", dir_ / "a.png");
  fs::create_symlink("a.png", dir_ / "b.png");
  try {
    writeFileAtomically((dir_ / "a.png").string(), "x");
    ADD_FAILURE() << "a loop of links was written";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("a.png"), std::string::npos) << e.what();
  }
  EXPECT_THROW(checkWritable((dir_ / "a.png").string()), InputError);
}

}  // namespace
}  // namespace prt
