// table3: the serial ray tracer's time for the paper's test cases A-D (Table III), one
// thread, on the benchmark scene, beside the paper's own times.

#include <cstdio>

#include "core/speed_index.h"
#include "lab/context.h"
#include "lab/experiments.h"
#include "lab/measure.h"

namespace prt {
namespace {

// Table III's execution times in seconds. A and B read as minutes:seconds (4:14.51, 8:34.16),
// C and D as hours:minutes:seconds (5:22:05, 10:46:12): the text calls C and D "much more
// difficult", and only hours make them so.
double paperSeconds(const std::string& c) {
  if (c == "A") return 4 * 60 + 14.51;
  if (c == "B") return 8 * 60 + 34.16;
  if (c == "C") return 5 * 3600 + 22 * 60 + 5;
  return 10 * 3600 + 46 * 60 + 12;
}

std::string fixed(double v, int decimals) {
  char buffer[64];
  std::snprintf(buffer, sizeof buffer, "%.*f", decimals, v);
  return buffer;
}

}  // namespace

void runTable3(ExperimentContext& cx) {
  std::vector<std::string> cases = cx.options().cases;
  if (cases.empty()) cases = {"A", "B", "C", "D"};
  const Scene scene = cx.scene(80, 60);
  const double speedIndex = cx.masterSpeedIndex(scene);

  CsvTable runs({"case", "run", "seconds", "rays"});
  CsvTable table({"case", "drt", "ss", "width", "height", "runs", "median_s", "min_s", "max_s",
                  "rays", "mrays_per_s", "relative_to_first", "paper_s", "paper_relative_to_first",
                  "source"});
  std::vector<double> ours, paper;
  for (const std::string& c : cases) {
    const RenderSettings s = cx.settings(c);
    cx.progress("case " + c + ": " + std::to_string(cx.runs()) + " serial render(s) at " +
                std::to_string(scene.image.width) + "x" + std::to_string(scene.image.height));
    const SerialMeasurement m = measureSerial(scene, s, cx.runs(), false);
    for (size_t r = 0; r < m.seconds.size(); ++r) {
      runs.addRow({c, std::to_string(r + 1), csvNumber(m.seconds[r], 5), std::to_string(m.rays)});
    }
    ours.push_back(m.medianSeconds);
    paper.push_back(paperSeconds(c));
    table.addRow({c, std::to_string(s.drtRate), std::to_string(s.samplesPerPixel),
                  std::to_string(scene.image.width), std::to_string(scene.image.height),
                  std::to_string(m.seconds.size()), csvNumber(m.medianSeconds, 5),
                  csvNumber(*std::min_element(m.seconds.begin(), m.seconds.end()), 5),
                  csvNumber(*std::max_element(m.seconds.begin(), m.seconds.end()), 5),
                  std::to_string(m.rays),
                  csvNumber(static_cast<double>(m.rays) / m.medianSeconds / 1e6, 4),
                  csvNumber(ours.back() / ours.front(), 4), csvNumber(paper.back(), 6),
                  csvNumber(paper.back() / paper.front(), 4), "real"});
  }
  cx.write(table, "table3.csv");
  cx.write(runs, "table3-runs.csv");

  Chart chart;
  chart.kind = Chart::Kind::Bars;
  chart.title = "Table III: serial time of each test case, relative to case " + cases.front();
  chart.yLabel = "time / time of case " + cases.front() + " (log scale)";
  chart.logY = true;
  chart.categories = cases;
  ChartSeries mine{"PRT, this machine (" + std::to_string(scene.image.width) + "x" +
                       std::to_string(scene.image.height) + ")",
                   {},
                   {},
                   false};
  ChartSeries theirs{"the paper's SRT (Table III)", {}, {}, false};
  for (size_t i = 0; i < cases.size(); ++i) {
    mine.y.push_back(ours[i] / ours.front());
    theirs.y.push_back(paper[i] / paper.front());
  }
  chart.series = {mine, theirs};
  cx.draw(chart, "table3.png");

  cx.say("Serial renders (the SRT: one thread) of `" + cx.options().scenePath + "` at " +
         std::to_string(scene.image.width) + "x" + std::to_string(scene.image.height) +
         ", median of " + std::to_string(cx.runs()) +
         " run(s) per case; all figures are real runs. This machine's speed index (Towers of "
         "Hanoi, " +
         std::to_string(kSpeedIndexDiscs) + " discs): " + fixed(speedIndex, 4) +
         " s (the paper's SRT: 0.3 s).\n\n");
  cx.say(markdownTable(table, {"case", "drt", "ss", "median_s", "rays", "mrays_per_s",
                               "relative_to_first", "paper_s", "paper_relative_to_first"}));
  cx.say(
      "\nThe paper's times read A and B as minutes:seconds and C and D as "
      "hours:minutes:seconds (its C and D take hours).\n");
}

}  // namespace prt
