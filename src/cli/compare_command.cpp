// prt compare: renders a scene with PRT and with POV-Ray 3.7 and measures how far the two
// images differ, as the paper validated its serial tracer against Mental Ray. The numbers
// and their thresholds per scene are in docs/povray-mapping.md.

#include <chrono>
#include <cstdio>
#include <filesystem>
#include <memory>
#include <optional>
#include <string>
#include <system_error>
#include <variant>

#include "cli/commands.h"
#include "cli/flag_checks.h"
#include "core/input_error.h"
#include "export/box_blur.h"
#include "export/pov_exporter.h"
#include "export/povray_runner.h"
#include "image/atomic_file.h"
#include "image/image_compare.h"
#include "image/image_io.h"
#include "scene/scene_file.h"
#include "trace/render_settings.h"
#include "trace/renderer.h"

namespace prt::cli {
namespace {

namespace fs = std::filesystem;

struct CompareOptions {
  SceneSource scene;
  std::optional<int> width;
  std::optional<int> height;
  std::optional<int> spp;
  std::optional<int> drt;
  std::string testCase;
  int blurRadius = 0;
  int tolerance = 8;
  double diffScale = 4;
  std::string outDir;
  int threads = 0;
  int areaGrid = 0;
  std::string povray = "povray";
};

double secondsSince(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

int runCompare(const CompareOptions& o) {
  Scene scene = loadScene(o.scene);
  scene.environment.integrator = Integrator::hall;  // what POV-Ray's model can be compared with
  // As `prt render` resolves them: the scene's sampling, then --case, then --spp and --drt.
  RenderSettings settings{scene.sampling.samplesPerPixel, scene.sampling.drtRate};
  if (!o.testCase.empty()) settings = *paperTestCase(o.testCase);
  if (o.spp) settings.samplesPerPixel = *o.spp;
  if (o.drt) settings.drtRate = *o.drt;
  applyImageSize(scene, o.width, o.height);
  const uint64_t pixels = static_cast<uint64_t>(scene.image.width) * scene.image.height;
  if (pixels > (1ull << 26)) {
    throw InputError("image too large for a comparison: " + std::to_string(scene.image.width) +
                     "x" + std::to_string(scene.image.height) + " exceeds 2^26 pixels");
  }
  const std::string stem = fs::path(o.scene.path).stem().string();
  if (!o.outDir.empty()) {
    std::error_code error;
    fs::create_directories(o.outDir, error);
    if (error || !fs::is_directory(o.outDir)) {
      throw InputError("cannot create output directory '" + o.outDir +
                       "': " + (error ? error.message() : "not a directory"));
    }
  }
  // Fail before spending time on PRT's render when POV-Ray cannot run at all.
  if (!povrayAvailable(o.povray)) {
    std::fprintf(stderr,
                 "prt: error: POV-Ray not found: no executable '%s'%s; install POV-Ray 3.7 "
                 "(Debian: apt-get install povray) or pass --povray PATH\n",
                 o.povray.c_str(), o.povray.find('/') == std::string::npos ? " on PATH" : "");
    return 1;
  }

  PovOptions povOptions;
  povOptions.areaLightGrid = o.areaGrid;
  povOptions.fileName = stem + ".pov";
  const PovExport pov = exportPovray(scene, settings, povOptions);
  const std::string& povText = pov.text;

  auto start = std::chrono::steady_clock::now();
  const World world(scene);
  const Renderer renderer(world, settings);
  const Image prtImage = renderImage(renderer, o.threads);
  const double prtSeconds = secondsSince(start);

  PovrayJob job;
  job.program = o.povray;
  job.sceneText = povText;
  job.images = pov.images;
  job.width = scene.image.width;
  job.height = scene.image.height;
  job.samplesPerPixel = settings.samplesPerPixel;
  job.threads = o.threads;
  start = std::chrono::steady_clock::now();
  std::optional<Image> rendered;
  try {
    rendered = renderWithPovray(job);
  } catch (const PovrayError& e) {
    std::fprintf(stderr, "prt: error: %s\n", e.what());
    return 1;
  }
  const double povSeconds = secondsSince(start);
  const Image& povImage = *rendered;
  if (povImage.width() != prtImage.width() || povImage.height() != prtImage.height()) {
    std::fprintf(stderr, "prt: error: POV-Ray rendered %dx%d pixels instead of %dx%d\n",
                 povImage.width(), povImage.height(), prtImage.width(), prtImage.height());
    return 1;
  }

  const Image a = boxBlur(prtImage, o.blurRadius);
  const Image b = boxBlur(povImage, o.blurRadius);
  const double db = psnr(a, b);
  const double differing = 100.0 * differingPixelFraction(a, b, o.tolerance);

  bool extendedLights = false;
  for (const Light& light : scene.lights) {
    extendedLights |= !std::holds_alternative<PointLight>(light.shape);
  }
  std::printf("%s: %dx%d, %d spp, DRT %d, blur radius %d", stem.c_str(), scene.image.width,
              scene.image.height, settings.samplesPerPixel, settings.drtRate, o.blurRadius);
  if (extendedLights) {
    const int grid = povAreaLightGrid(settings, povOptions);
    std::printf(", POV-Ray area lights %dx%d", grid, grid);
  }
  std::printf("\n");
  std::printf("  PRT %.3f s, POV-Ray %.3f s\n", prtSeconds, povSeconds);
  std::printf("  PSNR %.2f dB, %.2f %% of pixels differ by more than %d/255\n", db, differing,
              o.tolerance);

  if (!o.outDir.empty()) {
    const fs::path dir(o.outDir);
    writeImage(prtImage, (dir / (stem + ".prt.png")).string());
    writeImage(povImage, (dir / (stem + ".pov.png")).string());
    const std::string pair = (dir / (stem + ".compare.png")).string();
    writeImage(sideBySide(a, b, o.diffScale), pair);
    writeFileAtomically((dir / povOptions.fileName).string(), povText);
    for (const PovImage& image : pov.images) writeImage(image.image, (dir / image.fileName).string());
    std::printf("  wrote %s (PRT | POV-Ray | difference x%g)\n", pair.c_str(), o.diffScale);
  }
  return 0;
}

}  // namespace

Action addCompareCommand(CLI::App& app) {
  auto o = std::make_shared<CompareOptions>();
  auto* cmd = app.add_subcommand(
      "compare",
      "Render a .scene or model file with PRT and with POV-Ray 3.7 and report how much the images "
      "differ (PSNR, share of differing pixels). Exit code 0 when the comparison ran, 1 when "
      "POV-Ray is missing or fails, 2 on bad input");
  addSceneSource(*cmd, o->scene);
  cmd->add_option("--width", o->width, "Image width in pixels (default: the scene's; alone, the height keeps its aspect ratio)")
      ->check(CLI::Range(1, 32768));
  cmd->add_option("--height", o->height, "Image height in pixels (default: the scene's)")
      ->check(CLI::Range(1, 32768));
  cmd->add_option("--spp", o->spp,
                  "Samples per pixel; POV-Ray antialiases every pixel with n*n+1 samples, "
                  "n*n+1 closest to it")
      ->check(CLI::Range(1, 4096));
  cmd->add_option("--drt", o->drt, "Distributed ray tracing rate of PRT's render")
      ->check(CLI::Range(1, 64));
  cmd->add_option("--case", o->testCase,
                  "The paper's test cases A, B, C, D; --spp and --drt override")
      ->check(CLI::IsMember({"A", "B", "C", "D"}));
  cmd->add_option("--blur", o->blurRadius,
                  "Box-blur both images with this radius in pixels before comparing: for soft "
                  "shadows and gloss, whose noise differs by design")
      ->check(CLI::Range(0, 64))
      ->capture_default_str();
  cmd->add_option("--tolerance", o->tolerance,
                  "A pixel differs when a channel's 8-bit sRGB codes differ by more than this")
      ->check(CLI::Range(0, 255))
      ->capture_default_str();
  cmd->add_option("--diff-scale", o->diffScale, "Gain of the difference image")
      ->check(finiteIn(0, 255))
      ->capture_default_str();
  cmd->add_option("--out", o->outDir,
                  "Directory for SCENE.prt.png, SCENE.pov.png, SCENE.compare.png (PRT | POV-Ray "
                  "| difference) and SCENE.pov; created if missing");
  cmd->add_option("--threads", o->threads, "Threads for each renderer (0: all cores)")
      ->check(CLI::Range(0, 1024))
      ->capture_default_str();
  cmd->add_option("--area-grid", o->areaGrid,
                  "POV-Ray samples each sphere or rectangle light on an N x N grid; 0 chooses "
                  "from --spp and --drt")
      ->check(CLI::Range(0, 65))
      ->capture_default_str();
  cmd->add_option("--povray", o->povray, "The POV-Ray executable")->capture_default_str();
  return [o] { return runCompare(*o); };
}

}  // namespace prt::cli
