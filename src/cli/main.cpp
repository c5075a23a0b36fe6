// prt: the command-line entry point. Exit codes: 0 success, 1 runtime failure, 2 bad input.

#include <CLI/CLI.hpp>
#include <cstdio>
#include <exception>
#include <new>
#include <string>
#include <system_error>

#include "cli/commands.h"
#include "core/exit_status.h"
#include "core/input_error.h"
#include "core/memory_budget.h"
#include "core/subprocess.h"
#include "core/thread_failures.h"
#include "image/atomic_file.h"
#include "farm/build_info.h"

namespace {

int runPrt(int argc, char** argv) {
  // A render stopped by Ctrl-C, kill or a closed terminal leaves no half-written file behind.
  prt::removeTemporaryFilesOnSignals();
  CLI::App app{"PRT: a ray tracer for networks of computers of different speeds"};
  app.require_subcommand(1);
  // The trace library's build in use, as the loader picked it for this processor.
  app.set_version_flag("--version", prt::buildDescription());
  std::string commandLine = "prt";
  // Quoted for a shell where needed: the report records it, and a stopped render prints it
  // back with --resume for the user to run.
  for (int i = 1; i < argc; ++i) {
    const std::string arg = argv[i];
    const bool plain = !arg.empty() && arg.find_first_not_of(
                                           "abcdefghijklmnopqrstuvwxyzABCDEFGHIJKLMNOPQRSTUVWXYZ"
                                           "0123456789-_./=:,@%+#") == std::string::npos;
    std::string quoted = "'";
    for (const char c : arg) quoted += c == '\'' ? std::string("'\\''") : std::string(1, c);
    commandLine += " " + (plain ? arg : quoted + "'");
  }
  // Given before or after the command's name (fallthrough): `prt render --max-memory 4G ...`.
  app.fallthrough();
  std::string maxMemory;
  app.add_option("--max-memory", maxMemory,
                 "What the files a run reads may make it allocate, e.g. 4G or 512M (default: "
                 "3/4 of physical memory or of ulimit -v); a larger file or a model declaring "
                 "more is refused with a message")
      ->check(CLI::Validator(
          [](std::string& text) -> std::string {
            return prt::parseByteSize(text) ? std::string()
                                            : "must be a size such as 512M, 4G or 1.5GiB; "
                                              "found '" + text + "'";
          },
          "SIZE"));
  const prt::cli::Action render = prt::cli::addRenderCommand(app, commandLine);
  const prt::cli::Action speedIndex = prt::cli::addSpeedIndexCommand(app);
  const prt::cli::Action join = prt::cli::addJoinCommand(app);
  const prt::cli::Action simulate = prt::cli::addSimulateCommand(app, commandLine);
  const prt::cli::Action exportPov = prt::cli::addExportCommand(app);
  const prt::cli::Action compare = prt::cli::addCompareCommand(app);
  const prt::cli::Action report = prt::cli::addReportCommand(app);
  const prt::cli::Action experiment = prt::cli::addExperimentCommand(app, commandLine);
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    const int code = app.exit(e);
    return code == 0 ? 0 : 2;
  }
  if (!maxMemory.empty()) prt::setMemoryBudgetBytes(*prt::parseByteSize(maxMemory));
  try {
    for (CLI::App* sub : app.get_subcommands()) {
      if (sub->get_name() == "render") return render();
      if (sub->get_name() == "speed-index") return speedIndex();
      if (sub->get_name() == "join") return join();
      if (sub->get_name() == "simulate") return simulate();
      if (sub->get_name() == "export") return exportPov();
      if (sub->get_name() == "compare") return compare();
      if (sub->get_name() == "experiment") return experiment();
      if (sub->get_name() == "report") return report();
    }
  } catch (const prt::InputError& e) {
    std::fprintf(stderr, "%s\n", e.format().c_str());
    return 2;
  } catch (const prt::ProgramEnded& e) {
    // A helper program (ffmpeg) ended early: by a stop signal (exit 128 + it), or stalled.
    std::fprintf(stderr, "prt: %s%s\n", e.signal() > 0 ? "" : "error: ", e.what());
    return e.signal() > 0 ? 128 + e.signal() : 1;
  } catch (const std::bad_alloc&) {
    std::fprintf(stderr, "prt: error: %s\n", prt::outOfMemoryMessage().c_str());
    return 1;
  } catch (const std::system_error& e) {
    // A thread that cannot start for want of memory (its stack counts against ulimit -v) is
    // the same shortage.
    if (e.code() == std::errc::resource_unavailable_try_again) {
      std::fprintf(stderr, "prt: error: %s\n", prt::outOfMemoryMessage().c_str());
    } else {
      std::fprintf(stderr, "prt: error: %s\n", e.what());
    }
    return 1;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "prt: error: %s\n", e.what());
    return 1;
  }
  return 1;
}

}  // namespace

int main(int argc, char** argv) {
  const int code = runPrt(argc, argv);
  prt::recordExitStatus(code);  // for scripts/prt-mpirun under --enable-recovery
  return code;
}
