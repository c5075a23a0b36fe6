#pragma once
// The image file formats, one writer and one reader each. Internal to the image library:
// image_io.h dispatches on the file extension and owns file handling (atomic writes, reading
// the bytes); these functions only encode and decode.
//
// Writers stream to an open FILE* and throw InputError on failure; the caller detects stream
// errors and removes the partial file. Readers decode a whole file already in memory and
// throw InputError naming `path` for anything malformed (wrong magic, truncated, bad
// header). All functions are thread-safe.

#include <cstdio>
#include <span>
#include <string>

#include "image/image.h"
#include "image/image_io.h"

namespace prt {

struct ImageFormat {
  const char* extension;  // lower case, with the leading dot
  void (*write)(const Image& image, std::FILE* file, const std::string& path,
                const ImageWriteOptions& options);
  Image (*read)(std::span<const unsigned char> bytes, const std::string& path);
};

// PNG: 8-bit RGB, sRGB-encoded, with an sRGB chunk. Reads 8- and 16-bit gray, gray+alpha,
// RGB, RGBA and palette files; alpha is composited onto black.
void writePng(const Image& image, std::FILE* file, const std::string& path,
              const ImageWriteOptions& options);
Image readPng(std::span<const unsigned char> bytes, const std::string& path);

// PPM: binary "P6", 8-bit sRGB-encoded. Reads P6 and ASCII P3 with any maxval up to 65535
// (samples are sRGB-encoded fractions of maxval).
void writePpm(const Image& image, std::FILE* file, const std::string& path,
              const ImageWriteOptions& options);
Image readPpm(std::span<const unsigned char> bytes, const std::string& path);

// PFM: "PF", 32-bit float linear RGB, little-endian (scale -1.0), rows bottom to top as the
// format specifies. Reads "PF" (RGB) and "Pf" (gray) of either byte order; the magnitude of
// the scale is ignored, as most tools do.
void writePfm(const Image& image, std::FILE* file, const std::string& path,
              const ImageWriteOptions& options);
Image readPfm(std::span<const unsigned char> bytes, const std::string& path);

// OpenEXR: RGB, 32-bit float (every float bit kept) or 16-bit half (options.exrHalf), linear,
// ZIP-compressed, scan lines. Reads any scan-line or tiled file's R, G and B channels (a
// file of Y alone as grey; missing channels are 0), half, float or uint.
void writeExr(const Image& image, std::FILE* file, const std::string& path,
              const ImageWriteOptions& options);
Image readExr(std::span<const unsigned char> bytes, const std::string& path);
// The same, refusing (before decoding) an image of more than maxPixels pixels.
Image readExr(std::span<const unsigned char> bytes, const std::string& path, size_t maxPixels);

// JPEG: 8-bit sRGB, baseline, options.jpegQuality (1-100). Reads grey and colour files.
void writeJpeg(const Image& image, std::FILE* file, const std::string& path,
               const ImageWriteOptions& options);
Image readJpeg(std::span<const unsigned char> bytes, const std::string& path);

// Largest image a reader accepts, in pixels. Guards against a corrupt header making us
// allocate terabytes; far above any image this project renders.
inline constexpr size_t kMaxReadPixels = size_t{1} << 28;

}  // namespace prt
