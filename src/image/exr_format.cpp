// OpenEXR through the OpenEXR library's general (not Rgba) interface, so that float files keep
// every bit. Both directions go through streams of our own: the writer streams to the FILE*
// that the atomic writer owns, the reader decodes the bytes already in memory. The library
// reports errors as exceptions, which become InputError naming the file.
#include <ImfChannelList.h>
#include <ImfFrameBuffer.h>
#include <ImfHeader.h>
#include <ImfIO.h>
#include <ImfInputFile.h>
#include <ImfOutputFile.h>
#include <ImfThreading.h>
#include <half.h>

#include <algorithm>
#include <cerrno>
#include <cstring>
#include <limits>
#include <vector>

#include "core/input_error.h"
#include "image/image_formats.h"

namespace prt {
namespace {

class FileStream : public Imf::OStream {
 public:
  FileStream(std::FILE* file, const std::string& path) : Imf::OStream(path.c_str()), file_(file) {}
  void write(const char c[], int n) override {
    if (std::fwrite(c, 1, static_cast<size_t>(n), file_) != static_cast<size_t>(n)) {
      throw std::runtime_error(std::strerror(errno));
    }
  }
  uint64_t tellp() override { return static_cast<uint64_t>(ftello(file_)); }
  void seekp(uint64_t pos) override {
    if (fseeko(file_, static_cast<off_t>(pos), SEEK_SET) != 0) {
      throw std::runtime_error(std::strerror(errno));
    }
  }

 private:
  std::FILE* file_;
};

class MemoryStream : public Imf::IStream {
 public:
  MemoryStream(std::span<const unsigned char> bytes, const std::string& path)
      : Imf::IStream(path.c_str()), bytes_(bytes) {}
  bool read(char c[], int n) override {
    if (n < 0 || static_cast<uint64_t>(n) > bytes_.size() - position_) {
      throw std::runtime_error("the file ends early");
    }
    std::memcpy(c, bytes_.data() + position_, static_cast<size_t>(n));
    position_ += static_cast<uint64_t>(n);
    return position_ < bytes_.size();
  }
  uint64_t tellg() override { return position_; }
  void seekg(uint64_t pos) override { position_ = std::min<uint64_t>(pos, bytes_.size()); }
  void clear() override {}

 private:
  std::span<const unsigned char> bytes_;
  uint64_t position_ = 0;
};

}  // namespace

void writeExr(const Image& image, std::FILE* file, const std::string& path,
              const ImageWriteOptions& options) {
  const int w = image.width(), h = image.height();
  const Imf::PixelType type = options.exrHalf ? Imf::HALF : Imf::FLOAT;
  Imf::Header header(w, h);
  header.compression() = Imf::ZIP_COMPRESSION;
  for (const char* channel : {"R", "G", "B"}) header.channels().insert(channel, Imf::Channel(type));
  // The frame buffer holds what the file does: the image's floats, or a copy in halves.
  std::vector<half> halves;
  if (options.exrHalf) halves.assign(image.data().begin(), image.data().end());
  const size_t size = options.exrHalf ? sizeof(half) : sizeof(float);
  auto* base = options.exrHalf
                   ? reinterpret_cast<char*>(halves.data())
                   : const_cast<char*>(reinterpret_cast<const char*>(image.data().data()));
  Imf::FrameBuffer frame;
  const size_t xStride = 3 * size, yStride = xStride * static_cast<size_t>(w);
  for (int c = 0; c < 3; ++c) {
    frame.insert(c == 0 ? "R" : c == 1 ? "G" : "B",
                 Imf::Slice(type, base + static_cast<size_t>(c) * size, xStride, yStride));
  }
  try {
    FileStream stream(file, path);
    Imf::OutputFile out(stream, header, /*threads*/ 0);
    out.setFrameBuffer(frame);
    out.writePixels(h);
  } catch (const std::exception& e) {
    throw InputError("cannot write '" + path + "': " + e.what());
  }
}

Image readExr(std::span<const unsigned char> bytes, const std::string& path) {
  return readExr(bytes, path, kMaxReadPixels);
}

Image readExr(std::span<const unsigned char> bytes, const std::string& path, size_t maxPixels) {
  try {
    MemoryStream stream(bytes, path);
    Imf::InputFile in(stream, /*threads*/ 0);
    const Imath::Box2i window = in.header().dataWindow();
    const int64_t w = int64_t{window.max.x} - window.min.x + 1;
    const int64_t h = int64_t{window.max.y} - window.min.y + 1;
    if (w <= 0 || h <= 0 || w > std::numeric_limits<int>::max() ||
        h > std::numeric_limits<int>::max() ||
        static_cast<uint64_t>(w * h) > std::min<uint64_t>(maxPixels, kMaxReadPixels)) {
      throw InputError("'" + path + "': an OpenEXR image of " + std::to_string(w) + "x" +
                       std::to_string(h) + " pixels is empty or too large (at most " +
                       std::to_string(std::min<uint64_t>(maxPixels, kMaxReadPixels)) +
                       " pixels are read)");
    }
    Image image(static_cast<int>(w), static_cast<int>(h));
    const Imf::ChannelList& channels = in.header().channels();
    const bool grey = channels.findChannel("R") == nullptr && channels.findChannel("Y") != nullptr;
    // Slices address pixel (x, y) of the data window as base + x * xStride + y * yStride.
    char* origin = reinterpret_cast<char*>(image.data().data());
    const size_t xStride = 3 * sizeof(float), yStride = xStride * static_cast<size_t>(w);
    char* base = origin - static_cast<ptrdiff_t>(window.min.x) * static_cast<ptrdiff_t>(xStride) -
                 static_cast<ptrdiff_t>(window.min.y) * static_cast<ptrdiff_t>(yStride);
    Imf::FrameBuffer frame;
    for (int c = 0; c < 3; ++c) {
      const char* name = grey ? "Y" : c == 0 ? "R" : c == 1 ? "G" : "B";
      if (grey && c > 0) continue;
      frame.insert(name, Imf::Slice(Imf::FLOAT, base + c * sizeof(float), xStride, yStride,
                                    1, 1, 0.0));
    }
    in.setFrameBuffer(frame);
    in.readPixels(window.min.y, window.max.y);
    if (grey) {
      std::span<float> d = image.data();
      for (size_t p = 0; p < image.pixelCount(); ++p) d[3 * p + 1] = d[3 * p + 2] = d[3 * p];
    }
    return image;
  } catch (const InputError&) {
    throw;
  } catch (const std::exception& e) {
    throw InputError("'" + path + "' is not a readable OpenEXR file: " + e.what());
  }
}

}  // namespace prt
