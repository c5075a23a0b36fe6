// JPEG through libjpeg(-turbo). libjpeg reports a fatal error by calling error_exit, which
// must not return: ours longjmps back to the setjmp in the function that called libjpeg,
// where the message becomes an InputError. No C++ object with a destructor lives between the
// setjmp and the libjpeg calls (the buffers are allocated before).
// jpeglib.h needs size_t and FILE declared before it.
#include <algorithm>
#include <csetjmp>
#include <cstddef>
#include <cstdio>
#include <cstring>
#include <vector>

#include <jpeglib.h>

#include "core/input_error.h"
#include "image/image_formats.h"
#include "image/srgb.h"

namespace prt {
namespace {

struct ErrorTrap {
  jpeg_error_mgr manager;
  std::jmp_buf jump;
  char message[JMSG_LENGTH_MAX];
};

[[noreturn]] void onError(j_common_ptr info) {
  auto* trap = reinterpret_cast<ErrorTrap*>(info->err);
  (*info->err->format_message)(info, trap->message);
  std::longjmp(trap->jump, 1);
}

void silent(j_common_ptr, int) {}  // warnings (corrupt data libjpeg recovers from): ignored

// The steps that call libjpeg, each with its setjmp and nothing but plain data inside: false
// when libjpeg failed (the message is in the trap).
bool compress(jpeg_compress_struct* info, ErrorTrap* trap, std::FILE* file, JSAMPROW* rows,
              int width, int height, int quality) {
  if (setjmp(trap->jump) != 0) return false;
  jpeg_create_compress(info);
  jpeg_stdio_dest(info, file);
  info->image_width = static_cast<JDIMENSION>(width);
  info->image_height = static_cast<JDIMENSION>(height);
  info->input_components = 3;
  info->in_color_space = JCS_RGB;
  jpeg_set_defaults(info);
  jpeg_set_quality(info, quality, TRUE);
  if (quality >= 90) {  // no chroma subsampling (4:4:4) at high quality, as image editors do
    for (int c = 0; c < info->num_components; ++c) {
      info->comp_info[c].h_samp_factor = 1;
      info->comp_info[c].v_samp_factor = 1;
    }
  }
  jpeg_start_compress(info, TRUE);
  jpeg_write_scanlines(info, rows, static_cast<JDIMENSION>(height));
  jpeg_finish_compress(info);
  return true;
}

bool readHeader(jpeg_decompress_struct* info, ErrorTrap* trap, const unsigned char* bytes,
                size_t size) {
  if (setjmp(trap->jump) != 0) return false;
  jpeg_create_decompress(info);
  jpeg_mem_src(info, bytes, static_cast<unsigned long>(size));
  jpeg_read_header(info, TRUE);
  info->out_color_space = JCS_RGB;  // grey and YCbCr alike come out as RGB
  return true;
}

bool decompress(jpeg_decompress_struct* info, ErrorTrap* trap, JSAMPLE* out, size_t stride) {
  if (setjmp(trap->jump) != 0) return false;
  jpeg_start_decompress(info);
  while (info->output_scanline < info->output_height) {
    JSAMPROW row = out + stride * info->output_scanline;
    jpeg_read_scanlines(info, &row, 1);
  }
  jpeg_finish_decompress(info);
  return true;
}

void trapErrors(jpeg_common_struct* info, ErrorTrap& trap) {
  info->err = jpeg_std_error(&trap.manager);
  trap.manager.error_exit = onError;
  trap.manager.emit_message = silent;
}

}  // namespace

void writeJpeg(const Image& image, std::FILE* file, const std::string& path,
               const ImageWriteOptions& options) {
  const auto w = static_cast<size_t>(image.width());
  std::vector<JSAMPLE> samples(3 * image.pixelCount());
  const std::span<const float> linear = image.data();
  for (size_t i = 0; i < samples.size(); ++i) samples[i] = linearToSrgb8(linear[i]);
  std::vector<JSAMPROW> rows(static_cast<size_t>(image.height()));
  for (size_t y = 0; y < rows.size(); ++y) rows[y] = &samples[3 * w * y];
  jpeg_compress_struct info{};
  ErrorTrap trap{};
  trapErrors(reinterpret_cast<jpeg_common_struct*>(&info), trap);
  const bool ok = compress(&info, &trap, file, rows.data(), image.width(), image.height(),
                           std::clamp(options.jpegQuality, 1, 100));
  jpeg_destroy_compress(&info);
  if (!ok) throw InputError("cannot write '" + path + "': " + trap.message);
}

Image readJpeg(std::span<const unsigned char> bytes, const std::string& path) {
  jpeg_decompress_struct info{};
  ErrorTrap trap{};
  trapErrors(reinterpret_cast<jpeg_common_struct*>(&info), trap);
  const auto fail = [&](const std::string& why) {
    jpeg_destroy_decompress(&info);
    throw InputError("'" + path + "' is not a readable JPEG file: " + why);
  };
  if (!readHeader(&info, &trap, bytes.data(), bytes.size())) fail(trap.message);
  const uint64_t pixels = uint64_t{info.image_width} * info.image_height;
  if (info.image_width == 0 || info.image_height == 0 || pixels > kMaxReadPixels ||
      info.image_width > 65535 || info.image_height > 65535) {
    fail("an image of " + std::to_string(info.image_width) + "x" +
         std::to_string(info.image_height) + " pixels is empty or too large");
  }
  const size_t stride = size_t{info.image_width} * 3;
  std::vector<JSAMPLE> samples(stride * info.image_height);
  if (!decompress(&info, &trap, samples.data(), stride)) fail(trap.message);
  const int w = static_cast<int>(info.output_width), h = static_cast<int>(info.output_height);
  jpeg_destroy_decompress(&info);
  Image image(w, h);
  const std::span<float> out = image.data();
  for (size_t i = 0; i < out.size(); ++i) out[i] = static_cast<float>(srgb8ToLinear(samples[i]));
  return image;
}

}  // namespace prt
