#pragma once
// The prt subcommands. Each registers its flags on the CLI11 app and returns the action to run
// once parsing succeeded. Commands are thin: parse, validate, call the libraries.

#include <CLI/CLI.hpp>
#include <functional>
#include <optional>
#include <string>

#include "trace/scene.h"

namespace prt::cli {

// The file a command renders, and how to read it: the scene (or model) argument and the
// flags every command that reads one shares.
struct SceneSource {
  std::string path;
  std::string camera;   // --camera: an imported file's camera, by name or index
  bool strict = false;  // --strict: a model file's missing texture is an error
};
// Adds the scene argument (required), --camera and --strict to `cmd`.
void addSceneSource(CLI::App& cmd, SceneSource& source);

// loadSceneFile, printing what it skipped (Scene::warnings) to stderr.
Scene loadScene(const SceneSource& source);

// --width and --height over the scene's image size. One of them alone keeps the scene's
// aspect ratio: the other side is scaled to match, rounded, at least 1 pixel.
void applyImageSize(Scene& scene, std::optional<int> width, std::optional<int> height);

using Action = std::function<int()>;  // returns the process exit code

// `commandLine` (as typed) is recorded in reports, pages and summaries.
Action addRenderCommand(CLI::App& app, const std::string& commandLine);
Action addSpeedIndexCommand(CLI::App& app);
// Workers that join a running MPI render (join_command.cpp).
Action addJoinCommand(CLI::App& app);
// Discrete-event simulation (simulate_command.cpp).
Action addSimulateCommand(CLI::App& app, const std::string& commandLine);
// A saved report's page (report_command.cpp).
Action addReportCommand(CLI::App& app);
Action addExportCommand(CLI::App& app);   // POV-Ray export (export_command.cpp)
Action addCompareCommand(CLI::App& app);  // PRT vs POV-Ray images (compare_command.cpp)
// The paper's experiments (experiment_command.cpp); `commandLine` is recorded in summaries.
Action addExperimentCommand(CLI::App& app, const std::string& commandLine);

}  // namespace prt::cli
