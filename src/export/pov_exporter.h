#pragma once
// POV-Ray 3.7 export: a Scene written as a POV-Ray scene description that renders the image
// PRT renders, as far as the two shading models can agree. docs/povray-mapping.md explains
// every choice and lists what cannot be reproduced (glossy reflection, blurry transmission,
// one-sided planes, total internal reflection weights).
//
// The text is meant to be rendered with the command line povrayArguments() gives: linear
// maths (assumed_gamma 1) and an sRGB-encoded output file, as PRT's PNGs are.
//
// All functions are pure and thread-safe.

#include <string>
#include <vector>

#include "image/image.h"
#include "trace/render_settings.h"
#include "trace/scene.h"

namespace prt {

struct PovOptions {
  int areaLightGrid = 0;  // n: POV samples each light with extent on an n x n grid; 0: automatic
  std::string fileName = "scene.pov";  // the .pov file's name, for the command in its header
};

// A texture image the exported scene names, to be written beside the .pov file.
struct PovImage {
  std::string fileName;  // relative to the .pov file
  Image image;           // linear RGB; written as an sRGB PNG
};

struct PovExport {
  std::string text;  // the .pov file
  std::vector<PovImage> images;
};

// The scene as POV-Ray 3.7 scene-description text for an image of scene.image.width x
// scene.image.height pixels (the camera is exact for that size only), and the texture images
// it names. `settings` sets the sampling of lights with extent and the command line written
// into the header comment. A mesh placed by several instances is declared once and placed by
// a matrix; a texture is written as an image map (with the material's colour multiplied in,
// which POV-Ray's pigments cannot do), vertex colours as a texture per vertex.
PovExport exportPovray(const Scene& scene, const RenderSettings& settings,
                       const PovOptions& options = {});
// Its text alone, for scenes without textures.
std::string toPovray(const Scene& scene, const RenderSettings& settings,
                     const PovOptions& options = {});

// POV-Ray's `angle`, the horizontal field of view in degrees, of a camera whose vertical field
// of view is `verticalDegrees` on an image of aspect `widthOverHeight`.
double horizontalFovDegrees(double verticalDegrees, double widthOverHeight);

// POV-Ray's max_trace_level for PRT's maximum recursion depth: PRT traces ray generations
// 0..maxDepth (0: primary rays), POV-Ray traces generation g while g < max_trace_level.
int povMaxTraceLevel(int maxDepth);

// The side n of the n x n grid POV-Ray uses for each light with extent: options.areaLightGrid
// when set, otherwise the smallest 2^k + 1 >= 9 with n^2 >= samplesPerPixel * drtRate.
int povAreaLightGrid(const RenderSettings& settings, const PovOptions& options = {});

// POV-Ray's antialiasing depth for `samplesPerPixel` PRT samples: 0 (antialiasing off) for one
// sample, otherwise n with n^2 + 1 closest to the PRT count, at most 9. With non-adaptive
// supersampling at threshold 0 POV-Ray traces every pixel with n x n samples plus its centre.
int povAntialiasDepth(int samplesPerPixel);

struct PovRun {
  std::string sceneFile;  // the exported .pov file
  std::string imageFile;  // output; .png (8-bit sRGB) or .ppm
  int width = 320;
  int height = 240;
  int samplesPerPixel = 1;
  int threads = 0;  // render threads, 0: POV-Ray's default (all cores)
};

// The povray arguments (without the program name) that render run.sceneFile to run.imageFile
// deterministically: no display, no jitter, sRGB-encoded output, antialiasing as
// povAntialiasDepth(run.samplesPerPixel).
std::vector<std::string> povrayArguments(const PovRun& run);

}  // namespace prt
