#pragma once
// Reading and writing image files. The format follows the file extension, case-insensitively:
//   .png  8-bit RGB, sRGB-encoded (with an sRGB chunk)      - for viewing
//   .ppm  binary P6, 8-bit sRGB-encoded                      - trivial to parse anywhere
//   .pfm  32-bit float linear RGB, little-endian             - lossless, for comparisons
//   .exr  OpenEXR, linear RGB, 32-bit float or 16-bit half    - for compositing tools
//   .jpg  JPEG (also .jpeg), 8-bit sRGB-encoded, lossy        - small, for sharing
// Writing clamps to [0, 1] and rounds for the 8-bit formats; PFM and float EXR keep every
// float bit.
//
// All functions are thread-safe (writes to different paths run independently).

#include <string>
#include <vector>

#include "image/image.h"

namespace prt {

// How the formats with a choice write.
struct ImageWriteOptions {
  bool exrHalf = false;  // .exr: 16-bit half floats instead of 32-bit floats
  int jpegQuality = 95;  // .jpg: 1 (smallest) to 100 (best)
};

// Writes `image` to `path` atomically: the file appears complete or not at all, and an
// existing file is replaced only by a complete new one (see image/atomic_file.h).
// Throws InputError for an unsupported extension (the message lists the valid ones) or any
// I/O failure ("cannot write 'out/x.png': No such file or directory").
void writeImage(const Image& image, const std::string& path,
                const ImageWriteOptions& options = {});

// The bytes of `image` as a PNG file (8-bit sRGB, as writeImage writes .png), for embedding
// an image in another document. Throws std::runtime_error if libpng fails.
std::string encodePng(const Image& image);

// Reads a .png, .ppm (P6 or P3) or .pfm (PF or Pf) file into linear RGB. 8-bit files are
// decoded from sRGB. Throws InputError naming the file when it cannot be read, has an
// unsupported extension, or is malformed (wrong magic number, truncated, bad header).
Image readImage(const std::string& path);

// True when writeImage/readImage support the extension of `path`; lets the command line
// reject "-o out.jpg" before rendering instead of after.
bool isSupportedImagePath(const std::string& path);

// The supported extensions, lower case with the dot: {".png", ".ppm", ".pfm", ".exr", ".jpg",
// ".jpeg"}.
std::vector<std::string> supportedImageExtensions();

}  // namespace prt
