// PNG via libpng's "simplified" API (png_image). It reports errors through a message in the
// png_image instead of longjmp, so no setjmp is needed across C++ frames, and it performs
// the conversions a reader needs (palette, gray, 16-bit, alpha, gamma) itself.
#include <png.h>

#include <cerrno>
#include <stdexcept>
#include <system_error>
#include <vector>

#include "core/input_error.h"
#include "image/image_formats.h"
#include "image/image_io.h"
#include "image/srgb.h"

namespace prt {

namespace {

std::vector<png_byte> srgbSamples(const Image& image) {
  const std::span<const float> samples = image.data();
  std::vector<png_byte> encoded(samples.size());
  for (size_t i = 0; i < samples.size(); ++i) encoded[i] = linearToSrgb8(samples[i]);
  return encoded;
}

png_image pngHeader(const Image& image) {
  png_image png{};  // value-initialised: the zeroed struct libpng requires
  png.version = PNG_IMAGE_VERSION;
  png.width = static_cast<png_uint_32>(image.width());
  png.height = static_cast<png_uint_32>(image.height());
  png.format = PNG_FORMAT_RGB;
  // No PNG_IMAGE_FLAG_COLORSPACE_NOT_sRGB: libpng then writes an sRGB chunk, telling viewers
  // the samples are sRGB-encoded. PNG_IMAGE_FLAG_FAST: zlib's fast settings.
  png.flags = PNG_IMAGE_FLAG_FAST;
  return png;
}

}  // namespace

std::string encodePng(const Image& image) {
  const std::vector<png_byte> encoded = srgbSamples(image);
  png_image png = pngHeader(image);
  png_alloc_size_t size = 0;  // first call: the size needed
  if (png_image_write_to_memory(&png, nullptr, &size, 0, encoded.data(), 0, nullptr) == 0) {
    throw std::runtime_error(std::string("PNG encoding failed: ") + png.message);
  }
  std::string bytes(size, '\0');
  if (png_image_write_to_memory(&png, bytes.data(), &size, 0, encoded.data(), 0, nullptr) == 0) {
    throw std::runtime_error(std::string("PNG encoding failed: ") + png.message);
  }
  bytes.resize(size);
  return bytes;
}

void writePng(const Image& image, std::FILE* file, const std::string& path,
              const ImageWriteOptions& /*options*/) {
  const std::vector<png_byte> encoded = srgbSamples(image);
  png_image png = pngHeader(image);
  if (png_image_write_to_stdio(&png, file, 0, encoded.data(), 0, nullptr) == 0) {
    // A failed fwrite is the likely cause; prefer its errno text to libpng's "Write Error".
    const std::string reason =
        std::ferror(file) && errno != 0 ? std::generic_category().message(errno) : png.message;
    png_image_free(&png);
    throw InputError("cannot write '" + path + "': " + reason);
  }
}

Image readPng(std::span<const unsigned char> bytes, const std::string& path) {
  constexpr size_t kSignatureSize = 8;
  if (bytes.size() < kSignatureSize || png_sig_cmp(bytes.data(), 0, kSignatureSize) != 0) {
    throw InputError("'" + path + "' is not a PNG file (wrong signature)");
  }
  png_image png{};
  png.version = PNG_IMAGE_VERSION;
  // libpng frees the png_image itself when a begin/finish call fails.
  if (png_image_begin_read_from_memory(&png, bytes.data(), bytes.size()) == 0) {
    throw InputError("'" + path + "': invalid PNG file: " + png.message);
  }
  const size_t pixelCount = size_t{png.width} * size_t{png.height};
  if (pixelCount == 0 || pixelCount > kMaxReadPixels) {
    png_image_free(&png);
    throw InputError("'" + path + "': unsupported PNG image size (" + std::to_string(png.width) +
                     "x" + std::to_string(png.height) + ")");
  }
  // 8-bit sRGB out, whatever the file holds; decoded to linear with our own table below so
  // that PNG and PPM round trips agree exactly.
  png.format = PNG_FORMAT_RGB;
  // Zero-filled: with a null background libpng composites alpha onto the buffer, i.e. black.
  std::vector<png_byte> encoded(3 * pixelCount, 0);
  if (png_image_finish_read(&png, nullptr, encoded.data(), 0, nullptr) == 0) {
    throw InputError("'" + path + "': invalid or truncated PNG file: " + png.message);
  }

  Image image(static_cast<int>(png.width), static_cast<int>(png.height));
  const std::span<float> samples = image.data();
  for (size_t i = 0; i < samples.size(); ++i) {
    samples[i] = static_cast<float>(srgb8ToLinear(encoded[i]));
  }
  return image;
}

}  // namespace prt
