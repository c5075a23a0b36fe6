#include "net/port_file.h"

#include <gtest/gtest.h>
#include <sys/stat.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <optional>
#include <set>
#include <sstream>

#include "core/input_error.h"

namespace prt {
namespace {

namespace fs = std::filesystem;

class PortFileTest : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::temp_directory_path() /
           ("prt-port-file-" + std::to_string(::getpid()) + "-" +
            ::testing::UnitTest::GetInstance()->current_test_info()->name());
    fs::remove_all(dir_);
    fs::create_directories(dir_);
  }
  void TearDown() override { fs::remove_all(dir_); }
  std::string at(const std::string& name) const { return (dir_ / name).string(); }
  static std::string contents(const std::string& path) {
    std::ifstream in(path);
    std::stringstream s;
    s << in.rdbuf();
    return s.str();
  }
  // Only the files named are in the folder: no temporary file left.
  void expectOnly(std::set<std::string> names) const {
    std::set<std::string> found;
    for (const auto& entry : fs::directory_iterator(dir_))
      found.insert(entry.path().filename().string());
    EXPECT_EQ(found, names);
  }
  fs::path dir_;
};

const std::string kPortFileText = "port\nsecret " + std::string(64, 'b') + "\n";

TEST_F(PortFileTest, WrittenPrivatelyAndRemovedOnRelease) {
  const std::string path = at("prt-port");
  {
    PortFileClaim claim(path, kPortFileText);
    EXPECT_EQ(contents(path), kPortFileText);
    struct stat st {};
    ASSERT_EQ(::lstat(path.c_str(), &st), 0);
    EXPECT_TRUE(S_ISREG(st.st_mode));
    EXPECT_EQ(st.st_mode & 0777, 0600u);
    expectOnly({"prt-port"});
  }
  EXPECT_FALSE(fs::exists(path));
  expectOnly({});
}

TEST_F(PortFileTest, ASymbolicLinkIsRefusedAndWhatItNamesKept) {
  std::ofstream(at("victim.txt")) << "precious\n";
  fs::create_symlink(at("victim.txt"), at("prt-port"));
  EXPECT_THROW(PortFileClaim(at("prt-port"), kPortFileText), InputError);
  EXPECT_EQ(contents(at("victim.txt")), "precious\n");
  EXPECT_TRUE(fs::is_symlink(at("prt-port")));
  // A link to nowhere: refused, and nothing made where it points.
  fs::create_symlink(at("made"), at("dangling"));
  EXPECT_THROW(PortFileClaim(at("dangling"), kPortFileText), InputError);
  EXPECT_FALSE(fs::exists(at("made")));
  expectOnly({"victim.txt", "prt-port", "dangling"});
}

TEST_F(PortFileTest, APortFileHeldByARunningRenderIsRefused) {
  const std::string path = at("prt-port");
  std::optional<PortFileClaim> first(std::in_place, path, kPortFileText);
  const std::string other = "port2\nsecret " + std::string(64, 'c') + "\n";
  try {
    PortFileClaim second(path, other);
    ADD_FAILURE() << "a second claim of a held port file was allowed";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("belongs to a render that is running"), std::string::npos)
        << e.what();
  }
  EXPECT_EQ(contents(path), kPortFileText);
  expectOnly({"prt-port"});
  first.reset();  // that render ends: its file goes, and the path is free again
  EXPECT_FALSE(fs::exists(path));
  PortFileClaim again(path, other);
  EXPECT_EQ(contents(path), other);
}

TEST_F(PortFileTest, AStalePortFileIsReplacedAndAnyOtherFileKept) {
  const std::string path = at("prt-port");
  std::ofstream(path) << "old\nsecret " << std::string(64, 'd') << "\n";  // its render is gone
  {
    PortFileClaim claim(path, kPortFileText);
    EXPECT_EQ(contents(path), kPortFileText);
  }
  std::ofstream(path) << "my notes\n";
  EXPECT_THROW(PortFileClaim(path, kPortFileText), InputError);
  EXPECT_EQ(contents(path), "my notes\n");
  fs::remove(path);
  fs::create_directory(path);
  EXPECT_THROW(PortFileClaim(path, kPortFileText), InputError);
  EXPECT_TRUE(fs::is_directory(path));
}

TEST_F(PortFileTest, ReleaseLeavesAFileThatIsNoLongerItsOwn) {
  const std::string path = at("prt-port");
  PortFileClaim claim(path, kPortFileText);
  std::ofstream(at("new")) << "someone else's\n";
  fs::rename(at("new"), path);
  claim.release();
  EXPECT_EQ(contents(path), "someone else's\n");
}

TEST_F(PortFileTest, AMissingFolderIsAnInputError) {
  EXPECT_THROW(PortFileClaim(at("no/such/folder/prt-port"), kPortFileText), InputError);
}

}  // namespace
}  // namespace prt
