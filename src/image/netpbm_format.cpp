// PPM (P6/P3) and PFM (PF/Pf): the Netpbm-style formats. Both start with a whitespace-
// separated text header and end it with exactly one whitespace byte before the raster.
#include <bit>
#include <charconv>
#include <climits>
#include <cmath>
#include <cstdint>
#include <string_view>
#include <vector>

#include "core/input_error.h"
#include "image/image_formats.h"
#include "image/srgb.h"

namespace prt {
namespace {

bool isNetpbmSpace(unsigned char c) {
  return c == ' ' || c == '\t' || c == '\n' || c == '\r' || c == '\v' || c == '\f';
}

// Reads header tokens (and, for P3, ASCII samples) from a file held in memory. Every error
// names the file and the format.
class HeaderReader {
 public:
  HeaderReader(std::span<const unsigned char> bytes, const std::string& path,
               std::string_view format, bool allowComments)
      : bytes_(bytes), path_(path), format_(format), allowComments_(allowComments) {}

  // Position just after the magic number, which the caller has checked.
  void skip(size_t n) { pos_ += n; }
  size_t offset() const { return pos_; }

  [[noreturn]] void fail(const std::string& what) const {
    throw InputError("'" + path_ + "': " + what);
  }

  // The next whitespace-separated token; `what` names it in the "truncated" error.
  std::string_view token(const char* what) {
    skipSpaceAndComments();
    const size_t start = pos_;
    while (pos_ < bytes_.size() && !isNetpbmSpace(bytes_[pos_])) ++pos_;
    if (pos_ == start) fail("truncated " + std::string(format_) + " file (missing " + what + ")");
    return {reinterpret_cast<const char*>(bytes_.data()) + start, pos_ - start};
  }

  long integer(const char* what, long min, long max) {
    const std::string_view t = token(what);
    long value = 0;
    const auto [end, ec] = std::from_chars(t.data(), t.data() + t.size(), value);
    if (ec != std::errc() || end != t.data() + t.size() || value < min || value > max) {
      fail("bad " + std::string(format_) + " " + what + " '" + std::string(t) + "' (expected " +
           std::to_string(min) + ".." + std::to_string(max) + ")");
    }
    return value;
  }

  double real(const char* what) {
    const std::string_view t = token(what);
    double value = 0;
    const auto [end, ec] = std::from_chars(t.data(), t.data() + t.size(), value);
    if (ec != std::errc() || end != t.data() + t.size() || !std::isfinite(value)) {
      fail("bad " + std::string(format_) + " " + what + " '" + std::string(t) + "'");
    }
    return value;
  }

  // The header ends with exactly one whitespace byte; the raster follows, and its first
  // bytes may themselves look like whitespace, so skip no more than that one.
  void endHeader() {
    if (pos_ >= bytes_.size() || !isNetpbmSpace(bytes_[pos_])) {
      fail("truncated " + std::string(format_) + " file (missing pixel data)");
    }
    ++pos_;
  }

  // The binary raster: exactly `size` bytes must follow the header (extra bytes are ignored).
  std::span<const unsigned char> raster(size_t size) const {
    const size_t available = bytes_.size() - pos_;
    if (available < size) {
      fail("truncated " + std::string(format_) + " file (expected " + std::to_string(size) +
           " bytes of pixel data, found " + std::to_string(available) + ")");
    }
    return bytes_.subspan(pos_, size);
  }

 private:
  void skipSpaceAndComments() {
    while (pos_ < bytes_.size()) {
      if (isNetpbmSpace(bytes_[pos_])) {
        ++pos_;
      } else if (allowComments_ && bytes_[pos_] == '#') {
        while (pos_ < bytes_.size() && bytes_[pos_] != '\n' && bytes_[pos_] != '\r') ++pos_;
      } else {
        break;
      }
    }
  }

  std::span<const unsigned char> bytes_;
  const std::string& path_;
  std::string_view format_;
  bool allowComments_;
  size_t pos_ = 0;
};

bool hasMagic(std::span<const unsigned char> bytes, char a, char b) {
  return bytes.size() >= 2 && bytes[0] == static_cast<unsigned char>(a) &&
         bytes[1] == static_cast<unsigned char>(b);
}

struct ImageSize {
  int width = 0;
  int height = 0;
  size_t pixels() const { return static_cast<size_t>(width) * static_cast<size_t>(height); }
};

// Width and height, validated so the size arithmetic is safe. The caller checks the file is
// long enough before allocating, so a corrupt header cannot make us allocate gigabytes.
ImageSize readImageSize(HeaderReader& header, const char* format) {
  ImageSize size;
  size.width = static_cast<int>(header.integer("width", 1, INT_MAX));
  size.height = static_cast<int>(header.integer("height", 1, INT_MAX));
  if (size.pixels() > kMaxReadPixels) {
    header.fail(std::string(format) + " image too large (" + std::to_string(size.width) + "x" +
                std::to_string(size.height) + ")");
  }
  return size;
}

void writeHeader(std::FILE* file, const char* magic, const Image& image, const char* last) {
  std::fprintf(file, "%s\n%d %d\n%s\n", magic, image.width(), image.height(), last);
}

}  // namespace

void writePpm(const Image& image, std::FILE* file, const std::string& /*path*/,
              const ImageWriteOptions& /*options*/) {
  writeHeader(file, "P6", image, "255");
  const std::span<const float> samples = image.data();
  std::vector<unsigned char> row(3 * static_cast<size_t>(image.width()));
  for (size_t start = 0; start < samples.size(); start += row.size()) {
    for (size_t i = 0; i < row.size(); ++i) row[i] = linearToSrgb8(samples[start + i]);
    // A short write leaves the stream's error flag set; the caller reports it.
    if (std::fwrite(row.data(), 1, row.size(), file) != row.size()) return;
  }
}

Image readPpm(std::span<const unsigned char> bytes, const std::string& path) {
  const bool binary = hasMagic(bytes, 'P', '6');
  if (!binary && !hasMagic(bytes, 'P', '3')) {
    throw InputError("'" + path + "' is not a PPM file (expected magic number P6 or P3)");
  }
  HeaderReader header(bytes, path, "PPM", /*allowComments=*/true);
  header.skip(2);
  const ImageSize size = readImageSize(header, "PPM");
  const long maxval = header.integer("maximum value", 1, 65535);
  const size_t sampleCount = 3 * size.pixels();

  // Samples are sRGB-encoded fractions of maxval; the common 8-bit case uses the exact table.
  auto decode = [maxval](long v) {
    return maxval == 255 ? srgb8ToLinear(static_cast<uint8_t>(v))
                         : srgbDecode(static_cast<double>(v) / static_cast<double>(maxval));
  };
  if (binary) {
    header.endHeader();
    const size_t bytesPerSample = maxval < 256 ? 1 : 2;
    const std::span<const unsigned char> raster = header.raster(sampleCount * bytesPerSample);
    Image image(size.width, size.height);
    const std::span<float> samples = image.data();
    for (size_t i = 0; i < samples.size(); ++i) {
      // 16-bit samples are big-endian.
      const long v = bytesPerSample == 1 ? raster[i] : raster[2 * i] * 256L + raster[2 * i + 1];
      if (v > maxval) header.fail("bad PPM sample " + std::to_string(v) + " > maximum value");
      samples[i] = static_cast<float>(decode(v));
    }
    return image;
  }
  // P3: each sample takes at least one digit and one separator (the last needs no separator).
  if (bytes.size() - header.offset() < 2 * sampleCount - 1) {
    header.fail("truncated PPM file (too short for " + std::to_string(size.width) + "x" +
                std::to_string(size.height) + " pixels)");
  }
  Image image(size.width, size.height);
  for (float& s : image.data()) {
    s = static_cast<float>(decode(header.integer("pixel data", 0, maxval)));
  }
  return image;
}

void writePfm(const Image& image, std::FILE* file, const std::string& /*path*/,
              const ImageWriteOptions& /*options*/) {
  // Negative scale = little-endian samples.
  writeHeader(file, "PF", image, "-1.0");
  const std::span<const float> samples = image.data();
  const size_t rowFloats = 3 * static_cast<size_t>(image.width());
  std::vector<unsigned char> row(4 * rowFloats);
  for (int y = image.height() - 1; y >= 0; --y) {  // PFM stores the bottom row first
    const size_t start = static_cast<size_t>(y) * rowFloats;
    // Byte by byte rather than memcpy, so the file is little-endian on any host.
    for (size_t i = 0; i < rowFloats; ++i) {
      const uint32_t bits = std::bit_cast<uint32_t>(samples[start + i]);
      for (size_t b = 0; b < 4; ++b) row[4 * i + b] = static_cast<unsigned char>(bits >> (8 * b));
    }
    if (std::fwrite(row.data(), 1, row.size(), file) != row.size()) return;
  }
}

Image readPfm(std::span<const unsigned char> bytes, const std::string& path) {
  const bool color = hasMagic(bytes, 'P', 'F');
  if (!color && !hasMagic(bytes, 'P', 'f')) {
    throw InputError("'" + path + "' is not a PFM file (expected magic number PF or Pf)");
  }
  // The PFM header has no comments.
  HeaderReader header(bytes, path, "PFM", /*allowComments=*/false);
  header.skip(2);
  const ImageSize size = readImageSize(header, "PFM");
  const double scale = header.real("scale");
  if (scale == 0.0) header.fail("bad PFM scale 0 (its sign gives the byte order)");
  const bool littleEndian = scale < 0.0;
  header.endHeader();

  const size_t channels = color ? 3 : 1;
  const size_t rowFloats = channels * static_cast<size_t>(size.width);
  const std::span<const unsigned char> raster =
      header.raster(4 * rowFloats * static_cast<size_t>(size.height));
  Image image(size.width, size.height);
  const std::span<float> samples = image.data();
  for (int fileRow = 0; fileRow < image.height(); ++fileRow) {
    const size_t y = static_cast<size_t>(image.height() - 1 - fileRow);  // bottom row first
    const unsigned char* in = &raster[static_cast<size_t>(fileRow) * 4 * rowFloats];
    for (size_t i = 0; i < rowFloats; ++i, in += 4) {
      uint32_t bits = 0;
      for (size_t b = 0; b < 4; ++b) {
        const size_t shift = 8 * (littleEndian ? b : 3 - b);
        bits |= static_cast<uint32_t>(in[b]) << shift;
      }
      const float value = std::bit_cast<float>(bits);
      const size_t pixel = y * static_cast<size_t>(image.width()) + i / channels;
      if (color) {
        samples[3 * pixel + i % 3] = value;
      } else {
        for (size_t c = 0; c < 3; ++c) samples[3 * pixel + c] = value;
      }
    }
  }
  return image;
}

}  // namespace prt
