#include "export/povray_runner.h"

#include <gtest/gtest.h>
#include <unistd.h>

#include <cstdlib>
#include <filesystem>
#include <string>

#include "export/pov_exporter.h"

namespace prt {
namespace {

namespace fs = std::filesystem;

// Points TMPDIR at a private directory for the test, so that leftovers can be counted.
class PovrayRunnerTest : public ::testing::Test {
 protected:
  void SetUp() override {
    const char* old = std::getenv("TMPDIR");
    oldTmp_ = old ? old : "";
    hadTmp_ = old != nullptr;
    dir_ = fs::temp_directory_path() /
           ("prt-povray-runner-test-" + std::to_string(::getpid()) + "-" +
            ::testing::UnitTest::GetInstance()->current_test_info()->name());
    fs::create_directories(dir_);
    ::setenv("TMPDIR", dir_.c_str(), 1);
  }
  void TearDown() override {
    if (hadTmp_) {
      ::setenv("TMPDIR", oldTmp_.c_str(), 1);
    } else {
      ::unsetenv("TMPDIR");
    }
    fs::remove_all(dir_);
  }
  bool leftovers() const { return !fs::is_empty(dir_); }

  fs::path dir_;
  std::string oldTmp_;
  bool hadTmp_ = false;
};

TEST_F(PovrayRunnerTest, MissingProgramIsReportedClearly) {
  PovrayJob job;
  job.program = "prt-no-such-povray";
  EXPECT_FALSE(povrayAvailable(job.program));
  try {
    renderWithPovray(job);
    FAIL() << "expected PovrayError";
  } catch (const PovrayError& e) {
    EXPECT_NE(std::string(e.what()).find("not found"), std::string::npos) << e.what();
  }
  EXPECT_FALSE(leftovers());
}

TEST_F(PovrayRunnerTest, FailureCarriesPovrayOutputAndLeavesNothing) {
  if (!povrayAvailable()) GTEST_SKIP() << "povray is not installed";
  PovrayJob job;
  job.sceneText = "#version 3.7;\nsphere { <0, 0, 0> 1 no_such_keyword }\n";
  job.width = 8;
  job.height = 6;
  try {
    renderWithPovray(job);
    FAIL() << "expected PovrayError";
  } catch (const PovrayError& e) {
    EXPECT_NE(std::string(e.what()).find("povray exited"), std::string::npos) << e.what();
    EXPECT_FALSE(e.output().empty());
  }
  EXPECT_FALSE(leftovers());
}

TEST_F(PovrayRunnerTest, RendersAnExportedScene) {
  if (!povrayAvailable()) GTEST_SKIP() << "povray is not installed";
  Scene scene;
  scene.image.width = 16;
  scene.image.height = 12;
  scene.environment.background = Color(0.5, 0.25, 0.125);
  PovrayJob job;
  job.sceneText = toPovray(scene, {});
  job.width = 16;
  job.height = 12;
  job.threads = 1;
  const Image image = renderWithPovray(job);
  ASSERT_EQ(image.width(), 16);
  ASSERT_EQ(image.height(), 12);
  // An empty scene shows the background everywhere, to 8-bit sRGB precision.
  EXPECT_NEAR(image.at(3, 4).x, 0.5, 0.01);
  EXPECT_NEAR(image.at(3, 4).y, 0.25, 0.005);
  EXPECT_NEAR(image.at(3, 4).z, 0.125, 0.003);
  EXPECT_FALSE(leftovers());
}

}  // namespace
}  // namespace prt
