#include "lab/chart.h"

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>

#include "core/subprocess.h"

namespace prt {
namespace {

Chart lines() {
  Chart c;
  c.title = "Speed-up \"real\"";
  c.xLabel = "workers";
  c.yLabel = "efficiency_%";
  c.logX = true;
  c.series = {{"scatter", {4, 8}, {0.9, 0.8}, false}, {"self", {4, 8}, {0.95, NAN}, true}};
  c.referenceLines = {{"MASU 1.5", 1.5}};
  return c;
}

TEST(Chart, LineScriptHoldsItsDataAndEscapesText) {
  const std::string s = gnuplotScript(lines(), "x.png");
  EXPECT_NE(s.find("set output \"x.png\""), std::string::npos);
  EXPECT_NE(s.find("set title \"Speed-up \\\"real\\\"\""), std::string::npos) << s;
  EXPECT_NE(s.find("noenhanced"), std::string::npos) << "underscores stay literal";
  EXPECT_NE(s.find("set logscale x 2"), std::string::npos);
  EXPECT_NE(s.find("$d0 << EOD\n4 0.9\n8 0.8\nEOD"), std::string::npos) << s;
  EXPECT_NE(s.find("8 NaN"), std::string::npos) << "missing points stay missing";
  EXPECT_NE(s.find("dashtype 2 title \"self\""), std::string::npos) << s;
  EXPECT_NE(s.find("MASU 1.5"), std::string::npos);
}

TEST(Chart, BarScriptHasOneRowPerCategory) {
  Chart c;
  c.kind = Chart::Kind::Bars;
  c.categories = {"case A", "case B"};
  c.series = {{"scatter", {}, {1, 2}, false}, {"hybrid", {}, {3, 4}, false}};
  const std::string s = gnuplotScript(c, "bars.png");
  EXPECT_NE(s.find("\"case A\" 1 3\n\"case B\" 2 4\n"), std::string::npos) << s;
  EXPECT_NE(s.find("using 2:xtic(1)"), std::string::npos) << s;
  EXPECT_NE(s.find("using 3 "), std::string::npos) << s;
}

TEST(Chart, DrawsAPngWhenGnuplotIsInstalled) {
  const auto dir =
      std::filesystem::temp_directory_path() / ("prt-chart-test-" + std::to_string(::getpid()));
  std::filesystem::create_directories(dir);
  const std::string png = (dir / "chart.png").string();
  const std::string why = drawChart(lines(), png);
  EXPECT_TRUE(std::filesystem::exists(dir / "chart.gp")) << "the script is kept either way";
  if (findProgram("gnuplot").empty()) {
    EXPECT_NE(why.find("gnuplot"), std::string::npos);
  } else {
    EXPECT_EQ(why, "");
    EXPECT_GT(std::filesystem::file_size(png), 1000u);
    // Only the script and the chart: no temporary files left behind.
    int files = 0;
    for ([[maybe_unused]] const auto& e : std::filesystem::directory_iterator(dir)) ++files;
    EXPECT_EQ(files, 2);
  }
  std::filesystem::remove_all(dir);
}

}  // namespace
}  // namespace prt
