#include "core/input_file.h"

#include <gtest/gtest.h>
#include <sys/stat.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>

#include "core/input_error.h"
#include "core/memory_budget.h"

namespace prt {
namespace {

namespace fs = std::filesystem;

std::string messageOf(const std::string& path, uint64_t maxBytes) {
  try {
    readInputFile(path, "mesh file", maxBytes);
  } catch (const InputError& e) {
    return e.what();
  }
  return "(read)";
}

class InputFileTest : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::temp_directory_path() / ("prt-input-file-" + std::to_string(::getpid()));
    fs::create_directories(dir_);
  }
  void TearDown() override { fs::remove_all(dir_); }
  fs::path dir_;
};

TEST_F(InputFileTest, ReadsARegularFileWhole) {
  std::ofstream(dir_ / "a.obj", std::ios::binary) << std::string("v 0 0 0\n\0x", 10);
  EXPECT_EQ(readInputFile((dir_ / "a.obj").string(), "mesh file", 100), std::string("v 0 0 0\n\0x", 10));
  EXPECT_EQ(checkInputFile((dir_ / "a.obj").string(), "mesh file", 100), 10u);
}

// A FIFO with no writer would block a plain open for ever: it is refused at once.
TEST_F(InputFileTest, RefusesWhatIsNotARegularFileWithoutWaiting) {
  const fs::path fifo = dir_ / "pipe.ply";
  ASSERT_EQ(::mkfifo(fifo.c_str(), 0600), 0);
  EXPECT_NE(messageOf(fifo.string(), 100).find("is a FIFO (named pipe), not a regular file"),
            std::string::npos);
  EXPECT_NE(messageOf("/dev/zero", 100).find("is a character device"), std::string::npos);
  EXPECT_NE(messageOf(dir_.string(), 100).find("is a directory"), std::string::npos);
  EXPECT_NE(messageOf((dir_ / "none.obj").string(), 100).find("mesh file '"), std::string::npos);
  EXPECT_NE(messageOf((dir_ / "none.obj").string(), 100).find("does not exist"), std::string::npos);
  EXPECT_NE(messageOf("", 100).find("no mesh file name given"), std::string::npos);
}

TEST_F(InputFileTest, RefusesAFileLargerThanTheBoundUnread) {
  std::ofstream(dir_ / "big.obj") << std::string(3000, 'v');
  const std::string message = messageOf((dir_ / "big.obj").string(), 2048);
  EXPECT_NE(message.find("is 2.9 kiB, more than the 2.0 kiB a mesh file may be"), std::string::npos)
      << message;
}

TEST(MemoryBudgetTest, SizesAreReadAndWrittenAsPeopleWriteThem) {
  EXPECT_EQ(parseByteSize("512M"), uint64_t{512} << 20);
  EXPECT_EQ(parseByteSize("4G"), uint64_t{4} << 30);
  EXPECT_EQ(parseByteSize("4GB"), uint64_t{4} << 30);
  EXPECT_EQ(parseByteSize("1.5GiB"), uint64_t{3} << 29);
  EXPECT_EQ(parseByteSize("1000"), 1000u);
  EXPECT_EQ(parseByteSize("2k"), 2048u);
  for (const char* bad : {"", "G", "-1G", "0", "nan", "inf", "4Q", "1e30"}) {
    EXPECT_FALSE(parseByteSize(bad).has_value()) << bad;
  }
  EXPECT_EQ(formatMemorySize(12), "12 bytes");
  EXPECT_EQ(formatMemorySize(uint64_t{3} << 29), "1.5 GiB");
  EXPECT_EQ(formatMemorySize(uint64_t{312} << 20), "312 MiB");
}

TEST(MemoryBudgetTest, TheDefaultIsSomeOfTheMachinesMemoryAndCanBeSet) {
  const uint64_t fallback = memoryBudgetBytes();
  EXPECT_GT(fallback, uint64_t{64} << 20);
  setMemoryBudgetBytes(uint64_t{1} << 30);
  EXPECT_EQ(memoryBudgetBytes(), uint64_t{1} << 30);
  setMemoryBudgetBytes(0);
  EXPECT_EQ(memoryBudgetBytes(), fallback);
}

}  // namespace
}  // namespace prt
