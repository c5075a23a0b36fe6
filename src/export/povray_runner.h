#pragma once
// Running POV-Ray on an exported scene and reading back its image.
//
// POV-Ray runs as a child process (fork/exec, no shell, so no quoting) in a fresh temporary
// directory that is removed afterwards whatever happens: Debian's POV-Ray may only write to
// its working directory and /tmp, and no file is left behind. Its chatter on stdout and stderr
// goes to a file in that directory and is returned only with a failure.
//
// Thread-safe: concurrent calls use distinct directories. Blocks until POV-Ray exits.

#include <stdexcept>
#include <string>

#include "export/pov_exporter.h"
#include "image/image.h"

namespace prt {

// POV-Ray is missing, could not be started, failed or wrote no readable image.
class PovrayError : public std::runtime_error {
 public:
  PovrayError(const std::string& message, std::string output)
      : std::runtime_error(message), output_(std::move(output)) {}
  const std::string& output() const { return output_; }  // POV-Ray's stdout and stderr

 private:
  std::string output_;
};

struct PovrayJob {
  std::string program = "povray";  // a path, or a name looked up on PATH
  std::string sceneText;           // the .pov text (exportPovray)
  std::vector<PovImage> images;    // the texture images it names, written beside it
  int width = 320;
  int height = 240;
  int samplesPerPixel = 1;  // mapped to POV-Ray antialiasing (povAntialiasDepth)
  int threads = 0;          // 0: POV-Ray's default (all cores)
};

// Renders the job and returns the image, decoded to linear RGB like readImage.
// Throws PovrayError as described above.
Image renderWithPovray(const PovrayJob& job);

// True when `program` names an executable file (a path, or found on PATH).
bool povrayAvailable(const std::string& program = "povray");

}  // namespace prt
