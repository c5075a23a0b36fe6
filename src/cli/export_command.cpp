// prt export: a .scene file translated for another renderer (POV-Ray 3.7), for validating
// PRT's images against an independent implementation (docs/povray-mapping.md).

#include <cstdio>
#include <filesystem>
#include <memory>
#include <optional>
#include <string>

#include "cli/commands.h"
#include "cli/flag_checks.h"
#include "core/input_error.h"
#include "export/pov_exporter.h"
#include "image/atomic_file.h"
#include "image/image_io.h"
#include "scene/scene_file.h"
#include "trace/render_settings.h"

namespace prt::cli {
namespace {

struct ExportOptions {
  SceneSource scene;
  std::string format = "pov";
  std::string output;
  std::optional<int> width;
  std::optional<int> height;
  std::optional<int> spp;
  std::optional<int> drt;
  std::string testCase;
  int areaGrid = 0;
  bool quiet = false;
};

int runExport(const ExportOptions& o) {
  Scene scene = loadScene(o.scene);
  scene.environment.integrator = Integrator::hall;  // what POV-Ray's model can be compared with
  // As `prt render` resolves them: the scene's sampling, then --case, then --spp and --drt.
  RenderSettings settings{scene.sampling.samplesPerPixel, scene.sampling.drtRate};
  if (!o.testCase.empty()) settings = *paperTestCase(o.testCase);
  if (o.spp) settings.samplesPerPixel = *o.spp;
  if (o.drt) settings.drtRate = *o.drt;
  applyImageSize(scene, o.width, o.height);

  PovOptions options;
  options.areaLightGrid = o.areaGrid;
  options.fileName = std::filesystem::path(o.output).filename().string();
  const PovExport pov = exportPovray(scene, settings, options);
  // The texture images first: a .pov file that exists is one whose images do too.
  const std::filesystem::path directory = std::filesystem::path(o.output).parent_path();
  for (const PovImage& image : pov.images) writeImage(image.image, (directory / image.fileName).string());
  writeFileAtomically(o.output, pov.text);
  if (!o.quiet) {
    std::printf("%s: POV-Ray 3.7 scene for %dx%d pixels, %d spp\n", o.output.c_str(),
                scene.image.width, scene.image.height, settings.samplesPerPixel);
  }
  return 0;
}

}  // namespace

Action addExportCommand(CLI::App& app) {
  auto o = std::make_shared<ExportOptions>();
  auto* cmd = app.add_subcommand(
      "export",
      "Translate a .scene or model file for another renderer: POV-Ray 3.7 (the image POV-Ray renders "
      "from it matches PRT's except where docs/povray-mapping.md says otherwise)");
  addSceneSource(*cmd, o->scene);
  cmd->add_option("--format", o->format, "Output format")
      ->check(CLI::IsMember({"pov"}))
      ->capture_default_str();
  cmd->add_option("-o,--output", o->output, "Output file (.pov); written atomically")
      ->required()
      ->check(fileName());
  cmd->add_option("--width", o->width, "Image width in pixels (the camera depends on it; alone, the height keeps the scene's aspect ratio)")
      ->check(CLI::Range(1, 32768));
  cmd->add_option("--height", o->height, "Image height in pixels (alone: the width follows the scene's aspect ratio)")->check(CLI::Range(1, 32768));
  cmd->add_option("--spp", o->spp,
                  "Samples per pixel, mapped to POV-Ray antialiasing in the command line "
                  "written into the file's header")
      ->check(CLI::Range(1, 4096));
  cmd->add_option("--drt", o->drt, "Distributed ray tracing rate (sets the area-light grid)")
      ->check(CLI::Range(1, 64));
  cmd->add_option("--case", o->testCase,
                  "The paper's test cases A, B, C, D; --spp and --drt override")
      ->check(CLI::IsMember({"A", "B", "C", "D"}));
  cmd->add_option("--area-grid", o->areaGrid,
                  "POV-Ray samples each sphere or rectangle light on an N x N grid (1: a point "
                  "light at its centre); 0 chooses from --spp and --drt")
      ->check(CLI::Range(0, 65))
      ->capture_default_str();
  cmd->add_flag("-q,--quiet", o->quiet, "Print nothing on success");
  return [o] { return runExport(*o); };
}

}  // namespace prt::cli
