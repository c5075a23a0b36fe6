#include "scene/scene_file.h"

#include <gtest/gtest.h>
#include <sys/stat.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>

namespace prt {
namespace {

namespace fs = std::filesystem;

constexpr const char* kValidScene =
    "camera { eye 0 0 -5 look_at 0 0 0 }\nimage { width 4 height 3 }\n";

// A fresh directory per test, removed afterwards.
class SceneFile : public ::testing::Test {
 protected:
  void SetUp() override {
    const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
    dir_ = fs::temp_directory_path() /
           ("prt-scene-file-" + std::to_string(::getpid()) + "-" + info->name());
    fs::remove_all(dir_);
    fs::create_directories(dir_);
  }
  void TearDown() override { fs::remove_all(dir_); }

  std::string write(const std::string& name, const std::string& bytes) const {
    const fs::path path = dir_ / name;
    std::ofstream(path, std::ios::binary) << bytes;
    return path.string();
  }

  static std::string loadError(const std::string& path) {
    try {
      loadSceneFile(path);
    } catch (const InputError& error) {
      EXPECT_NE(std::string(error.what()).find(path), std::string::npos)
          << "the message should name the file: " << error.what();
      EXPECT_EQ(std::string(error.what()).find('\n'), std::string::npos) << "one line";
      return error.what();
    }
    ADD_FAILURE() << "no error for " << path;
    return {};
  }

  fs::path dir_;
};

bool contains(const std::string& text, const std::string& part) {
  return text.find(part) != std::string::npos;
}

TEST_F(SceneFile, LoadsAValidFile) {
  const Scene scene = loadSceneFile(write("ok.scene", kValidScene));
  EXPECT_EQ(scene.image.width, 4);
}

TEST_F(SceneFile, AcceptsOtherExtensions) {
  EXPECT_EQ(loadSceneFile(write("ok.txt", kValidScene)).image.height, 3);
}

TEST_F(SceneFile, ParseErrorsCarryThePath) {
  const std::string path = write("bad.scene", std::string(kValidScene) + "sphere { radius 1 }");
  try {
    loadSceneFile(path);
    FAIL() << "no error";
  } catch (const InputError& error) {
    EXPECT_EQ(error.where().file, path);
    EXPECT_EQ(error.where().line, 3);
    EXPECT_EQ(error.where().column, 1);
  }
}

TEST_F(SceneFile, MissingFile) {
  EXPECT_TRUE(contains(loadError((dir_ / "nope.scene").string()), "does not exist"));
}

TEST_F(SceneFile, Directory) {
  EXPECT_TRUE(contains(loadError(dir_.string()), "is a directory"));
}

TEST_F(SceneFile, FifoAndDevicesAreRefusedWithoutReading) {
  // Opening a FIFO would wait for a writer forever; /dev/zero would never end.
  const fs::path fifo = dir_ / "pipe.scene";
  ASSERT_EQ(::mkfifo(fifo.c_str(), 0600), 0);
  EXPECT_TRUE(contains(loadError(fifo.string()), "is a FIFO (named pipe), not a regular file"));
  EXPECT_TRUE(contains(loadError("/dev/zero"), "is a character device, not a regular file"));
}

TEST_F(SceneFile, CarriageReturnLineEndsCountLines) {
  const std::string path =
      write("mac.scene", "camera { eye 0 0 -5 look_at 0 0 0 }\rimage { width 4 height 3 }\r"
                         "sphere { radius -1 }\r");
  try {
    loadSceneFile(path);
    ADD_FAILURE() << "no error";
  } catch (const InputError& error) {
    EXPECT_EQ(error.where().line, 3);
    EXPECT_EQ(error.where().column, 17);
    EXPECT_EQ(error.where().lineText, "sphere { radius -1 }");
  }
}

TEST_F(SceneFile, EmptyFile) {
  EXPECT_TRUE(contains(loadError(write("empty.scene", "")), "is empty"));
}

TEST_F(SceneFile, OnlyCommentsAndWhiteSpace) {
  const std::string message = loadError(write("c.scene", "# nothing here\n\n   \t# still\r\n"));
  EXPECT_TRUE(contains(message, "is empty")) << message;
  EXPECT_TRUE(contains(message, "only comments")) << message;
}

TEST_F(SceneFile, BinaryFileWithNulBytes) {
  const std::string message = loadError(write("b.scene", std::string("camera\0\x01\x02", 9)));
  EXPECT_TRUE(contains(message, "binary")) << message;
}

TEST_F(SceneFile, InvalidUtf8) {
  const std::string message = loadError(write("u.scene", "# caf\xE9\ncamera {}\n"));
  EXPECT_TRUE(contains(message, "not valid UTF-8")) << message;
  EXPECT_TRUE(contains(message, "line 1")) << message;
  EXPECT_TRUE(contains(loadError(write("s.scene", "# \xED\xA0\x80 surrogate")), "UTF-8"));
  EXPECT_TRUE(contains(loadError(write("o.scene", "# \xC0\xAF overlong")), "UTF-8"));
  EXPECT_TRUE(contains(loadError(write("t.scene", "# cut \xE2\x82")), "UTF-8"));
}

TEST_F(SceneFile, ControlCharacters) {
  const std::string message = loadError(write("k.scene", "camera {\n\x1B[31m }"));
  EXPECT_TRUE(contains(message, "control character 0x1B")) << message;
  EXPECT_TRUE(contains(message, "line 2")) << message;
}

TEST_F(SceneFile, AcceptsUtf8CommentsStringsAndAByteOrderMark) {
  const Scene scene = loadSceneFile(
      write("bom.scene",
            "\xEF\xBB\xBF# caf\xC3\xA9 \xF0\x9F\x98\x80\ncamera { eye 0 0 -5 look_at 0 0 0 }\n"
            "image { width 4 height 3 output \"caf\xC3\xA9.png\" }\n"));
  EXPECT_EQ(scene.image.output, "caf\xC3\xA9.png");
}

TEST_F(SceneFile, ReportsColumnsFromTheStartOfALineAfterAByteOrderMark) {
  try {
    loadSceneFile(write("bom.scene",
                        "\xEF\xBB\xBF"
                        "bogus"));
    FAIL() << "no error";
  } catch (const InputError& error) {
    EXPECT_EQ(error.where().line, 1);
    EXPECT_EQ(error.where().column, 1);
    EXPECT_EQ(error.where().lineText, "bogus");
  }
}

// The scenes shipped with the project must all load.
TEST(SceneFiles, ShippedScenesLoad) {
  const fs::path scenes = fs::path(PRT_SOURCE_DIR) / "scenes";
  if (!fs::is_directory(scenes)) GTEST_SKIP() << "no scenes directory";
  int count = 0;
  for (const auto& entry : fs::directory_iterator(scenes)) {
    if (entry.path().extension() != ".scene") continue;
    SCOPED_TRACE(entry.path().string());
    try {
      const Scene scene = loadSceneFile(entry.path().string());
      EXPECT_FALSE(scene.objects.empty());
      ++count;
    } catch (const InputError& error) {
      ADD_FAILURE() << error.format();
    }
  }
  EXPECT_GT(count, 0);
}

}  // namespace
}  // namespace prt
