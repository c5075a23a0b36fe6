// End-to-end tests of prt experiment: each experiment's quick version writes its CSV files,
// charts and summary; bad input is an error with exit code 2 and no results.

#include <gtest/gtest.h>

#include <filesystem>
#include <map>
#include <sstream>
#include <string>
#include <vector>

#include "balance/strategy.h"
#include "core/subprocess.h"
#include "prt_command.h"

namespace prt {
namespace {

namespace fs = std::filesystem;
using e2e::Result;
using e2e::run;

class ExperimentCliTest : public e2e::ScratchDirTest {
 protected:
  // Runs `prt experiment NAME --quick` on the benchmark scene into the scratch folder.
  Result quick(const std::string& name, const std::string& extra = "") {
    return run("experiment " + name +
               " --quick --quiet --scene " PRT_SOURCE_DIR "/scenes/complex.scene --out " +
               path("out") + " " + extra);
  }
  std::string header(const std::string& csv) {
    std::istringstream in(readWholeFile(dir_ / "out" / csv));
    std::string line;
    std::getline(in, line);
    return line;
  }
  int rows(const std::string& csv) {
    std::istringstream in(readWholeFile(dir_ / "out" / csv));
    std::string line;
    int n = -1;  // not the header
    while (std::getline(in, line)) ++n;
    return n;
  }
  void expectChart(const std::string& png) {
    EXPECT_TRUE(fs::exists(dir_ / "out" / fs::path(png).replace_extension(".gp"))) << png;
    if (!findProgram("gnuplot").empty()) {
      EXPECT_GT(fs::file_size(dir_ / "out" / png), 1000u) << png;
    }
  }
};

TEST_F(ExperimentCliTest, Table3) {
  const Result r = quick("table3");
  ASSERT_EQ(r.exitCode, 0) << r.output;
  EXPECT_EQ(header("table3.csv"),
            "case,drt,ss,width,height,runs,median_s,min_s,max_s,rays,mrays_per_s,"
            "relative_to_first,paper_s,paper_relative_to_first,source");
  EXPECT_EQ(rows("table3.csv"), 4);
  expectChart("table3.png");
  const std::string md = readWholeFile(dir_ / "out" / "table3.md");
  EXPECT_NE(md.find("real runs"), std::string::npos) << md;
}

TEST_F(ExperimentCliTest, SpeedIndex) {
  const Result r = quick("speed-index");
  ASSERT_EQ(r.exitCode, 0) << r.output;
  EXPECT_EQ(rows("speed-index.csv"), 2);          // hanoi, probe
  EXPECT_EQ(rows("speed-index-workers.csv"), 8);  // 2 kinds x 4 workers x 1 run
  expectChart("speed-index.png");
}

TEST_F(ExperimentCliTest, InitialPercent) {
  const Result r = quick("initial-percent", "--slowdown 2,4");
  ASSERT_EQ(r.exitCode, 0) << r.output;
  EXPECT_EQ(rows("initial-percent.csv"), 2 * 3 * 2);  // strategies x percents x sources
  const std::string csv = readWholeFile(dir_ / "out" / "initial-percent.csv");
  EXPECT_NE(csv.find(",real,"), std::string::npos);
  EXPECT_NE(csv.find(",simulated,"), std::string::npos);
  expectChart("initial-percent-speedup.png");
  expectChart("initial-percent-efficiency.png");
}

TEST_F(ExperimentCliTest, Compare) {
  const Result r = quick("compare", "--cases A --strategies scatter,hybrid,reservoir");
  ASSERT_EQ(r.exitCode, 0) << r.output;
  EXPECT_EQ(rows("compare.csv"), 3 * 2 * 2);  // strategies x sources x (A, A-slowing)
  expectChart("compare-speedup.png");
  expectChart("compare-efficiency.png");
  expectChart("compare-asu.png");
  const std::string md = readWholeFile(dir_ / "out" / "compare.md");
  EXPECT_NE(md.find("speedup vs scatter"), std::string::npos) << md;
}

TEST_F(ExperimentCliTest, Scale) {
  const Result r = quick("scale");
  ASSERT_EQ(r.exitCode, 0) << r.output;
  // scenarios x worker counts x strategies
  EXPECT_EQ(rows("scale.csv"), 3 * 5 * static_cast<int>(strategyNames().size()));
  const std::string csv = readWholeFile(dir_ / "out" / "scale.csv");
  EXPECT_EQ(csv.find(",real,"), std::string::npos) << "scale is simulated only";
  expectChart("scale-efficiency-homogeneous.png");
  expectChart("scale-asu-heterogeneous.png");
  expectChart("scale-efficiency-changing.png");
}

TEST_F(ExperimentCliTest, Joins) {
  const Result r = quick("joins", "--strategies adaptive,scatter");
  ASSERT_EQ(r.exitCode, 0) << r.output;
  EXPECT_EQ(rows("joins.csv"), 2 * (3 + 1));  // strategies x (3 simulated arrivals + 1 real)
  const std::string csv = readWholeFile(dir_ / "out" / "joins.csv");
  EXPECT_NE(csv.find("adaptive,real,"), std::string::npos) << csv;
  expectChart("joins-simulated.png");
  expectChart("joins-real.png");
  const std::string md = readWholeFile(dir_ / "out" / "joins.md");
  EXPECT_NE(md.find("schedule's ideal"), std::string::npos) << md;
  const Result bad = quick("joins", "--slowdown 4");
  EXPECT_EQ(bad.exitCode, 2) << "one worker cannot be joined: " << bad.output;
}

// The CSV's rows as column -> value maps.
std::vector<std::map<std::string, std::string>> csvRows(const std::string& text) {
  std::istringstream in(text);
  std::string line;
  auto split = [](const std::string& l) {
    std::vector<std::string> cells;
    std::istringstream cellsIn(l);
    for (std::string cell; std::getline(cellsIn, cell, ',');) cells.push_back(cell);
    return cells;
  };
  std::getline(in, line);
  const std::vector<std::string> names = split(line);
  std::vector<std::map<std::string, std::string>> rows;
  while (std::getline(in, line)) {
    const std::vector<std::string> cells = split(line);
    std::map<std::string, std::string> row;
    for (size_t i = 0; i < names.size() && i < cells.size(); ++i) row[names[i]] = cells[i];
    rows.push_back(row);
  }
  return rows;
}

TEST_F(ExperimentCliTest, Faults) {
  const Result r = quick("faults");
  ASSERT_EQ(r.exitCode, 0) << r.output;
  EXPECT_EQ(rows("faults.csv"), 2 * 4 * 3);  // MTBF (none, 1 h) x strategies x leases
  std::map<std::string, double> adaptive;    // "MTBF/lease" -> elapsed
  for (const auto& row : csvRows(readWholeFile(dir_ / "out" / "faults.csv"))) {
    EXPECT_EQ(row.at("source"), "simulated");
    const bool failing = row.at("mtbf_h") != "0";
    EXPECT_EQ(std::stod(row.at("lost_workers")) > 0, failing) << row.at("strategy");
    EXPECT_EQ(std::stod(row.at("reissued_tasks")) > 0, failing) << row.at("strategy");
    // No strategy beats the ideal: the work balanced over the machines while they were there.
    EXPECT_GE(std::stod(row.at("elapsed_over_ideal")), 1.0) << row.at("strategy");
    if (row.at("strategy") == "adaptive") {
      adaptive[row.at("mtbf_h") + "/" + row.at("lease_s")] = std::stod(row.at("elapsed_s"));
    }
  }
  // Failures cost time, and waiting longer for a machine that is gone costs more.
  EXPECT_GT(adaptive.at("1/2"), adaptive.at("0/2"));
  EXPECT_GT(adaptive.at("1/60"), adaptive.at("1/2"));
  EXPECT_NEAR(adaptive.at("0/60"), adaptive.at("0/2"), 0.01 * adaptive.at("0/2"))
      << "without failures the lease costs only heartbeats";
  expectChart("faults-time-mtbf-none.png");
  expectChart("faults-time-mtbf-1h.png");
  expectChart("faults-cost.png");
  const std::string md = readWholeFile(dir_ / "out" / "faults.md");
  EXPECT_NE(md.find("What lease to choose"), std::string::npos) << md;
}

TEST_F(ExperimentCliTest, BadInputIsExitCodeTwoAndWritesNothing) {
  Result r = run("experiment nonesuch --out " + path("out"));
  EXPECT_EQ(r.exitCode, 2);
  EXPECT_NE(r.output.find("initial-percent"), std::string::npos) << "lists the valid names";
  r = run("experiment table3 --out " + path("out") + " --scene " + path("missing.scene"));
  EXPECT_EQ(r.exitCode, 2);
  EXPECT_NE(r.output.find("missing.scene"), std::string::npos) << r.output;
  r = quick("compare", "--strategies scatter,nonesuch");
  EXPECT_EQ(r.exitCode, 2) << r.output;
  r = quick("speed-index", "--case E");
  EXPECT_EQ(r.exitCode, 2) << r.output;
  r = quick("table3", "--slowdown 0.5");
  EXPECT_EQ(r.exitCode, 2) << r.output;
  EXPECT_FALSE(fs::exists(dir_ / "out" / "table3.csv"));
  r = run("experiment table3");
  EXPECT_EQ(r.exitCode, 2) << "--out is required: " << r.output;
}

}  // namespace
}  // namespace prt
