#include <cstdio>

#include "cli/commands.h"
#include "core/speed_index.h"

namespace prt::cli {

Action addSpeedIndexCommand(CLI::App& app) {
  auto* cmd = app.add_subcommand(
      "speed-index",
      "Measure this machine's speed index: the seconds a recursive Towers of Hanoi run takes "
      "(lower is faster)");
  struct Options {
    int discs = kSpeedIndexDiscs;
    int repeats = 3;
  };
  auto options = std::make_shared<Options>();
  cmd->add_option("--discs", options->discs, "Number of discs (2^discs - 1 moves)")
      ->check(CLI::Range(1, 40))
      ->capture_default_str();
  cmd->add_option("--repeats", options->repeats, "Runs; the median is reported")
      ->check(CLI::Range(1, 100))
      ->capture_default_str();
  return [options] {
    const double seconds = measureSpeedIndexSeconds(options->discs, options->repeats);
    std::printf("%.6f\n", seconds);
    return 0;
  };
}

}  // namespace prt::cli
