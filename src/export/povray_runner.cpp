#include "export/povray_runner.h"

#include <filesystem>
#include <fstream>
#include <vector>

#include "core/subprocess.h"
#include "export/pov_exporter.h"
#include "image/image_io.h"

namespace prt {
namespace {

namespace fs = std::filesystem;

// The runner's failures are PovrayErrors, whatever part failed.
template <typename F>
auto asPovrayError(F&& f) {
  try {
    return f();
  } catch (const PovrayError&) {
    throw;
  } catch (const std::runtime_error& e) {
    throw PovrayError(e.what(), "");
  }
}

}  // namespace

bool povrayAvailable(const std::string& program) {
  return !findProgram(program).empty();
}

Image renderWithPovray(const PovrayJob& job) {
  const std::string program = findProgram(job.program);
  if (program.empty()) {
    throw PovrayError("POV-Ray not found: no executable '" + job.program + "'" +
                          (job.program.find('/') == std::string::npos ? " on PATH" : "") +
                          "; install POV-Ray 3.7 (Debian: apt-get install povray)",
                      "");
  }
  const TempDirectory dir = asPovrayError([] { return TempDirectory("prt-povray-"); });
  {
    std::ofstream scene(dir.path() / "scene.pov", std::ios::binary);
    scene << job.sceneText;
    scene.close();
    if (!scene) throw PovrayError("cannot write the POV-Ray scene to " + dir.path().string(), "");
  }
  for (const PovImage& image : job.images) {
    asPovrayError([&] {
      writeImage(image.image, (dir.path() / image.fileName).string());
      return 0;
    });
  }
  PovRun run;
  run.sceneFile = "scene.pov";  // relative: POV-Ray runs in the directory
  run.imageFile = "image.png";
  run.width = job.width;
  run.height = job.height;
  run.samplesPerPixel = job.samplesPerPixel;
  run.threads = job.threads;
  const fs::path log = dir.path() / "povray.log";
  const int status =
      asPovrayError([&] { return runProgram(program, povrayArguments(run), dir.path(), log); });
  const std::string output = readWholeFile(log);
  if (const std::string how = describeExit(status); !how.empty()) {
    throw PovrayError("povray " + how + "; its last output:\n" + lastLines(output, 15), output);
  }
  const fs::path image = dir.path() / run.imageFile;
  if (!fs::exists(image)) {
    throw PovrayError("povray wrote no image; its last output:\n" + lastLines(output, 15), output);
  }
  try {
    return readImage(image.string());
  } catch (const std::exception& e) {
    throw PovrayError(std::string("cannot read POV-Ray's image: ") + e.what(), output);
  }
}

}  // namespace prt
