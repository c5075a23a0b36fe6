#include "image/image_io.h"

#include <array>
#include <cctype>
#include <cerrno>
#include <cstdio>
#include <filesystem>
#include <system_error>

#include "core/input_error.h"
#include "core/input_file.h"
#include "image/atomic_file.h"
#include "image/image_formats.h"

namespace prt {
namespace {

// The registry: adding a format means one line here plus its writer and reader.
constexpr std::array<ImageFormat, 6> kFormats = {{
    {".png", writePng, readPng},
    {".ppm", writePpm, readPpm},
    {".pfm", writePfm, readPfm},
    {".exr", writeExr, readExr},
    {".jpg", writeJpeg, readJpeg},
    {".jpeg", writeJpeg, readJpeg},
}};

std::string lowerCaseExtension(const std::string& path) {
  std::string ext = std::filesystem::path(path).extension().string();
  for (char& c : ext) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return ext;
}

const ImageFormat* findFormat(const std::string& path) {
  const std::string ext = lowerCaseExtension(path);
  for (const ImageFormat& format : kFormats) {
    if (ext == format.extension) return &format;
  }
  return nullptr;
}

std::string validExtensionList() {
  std::string list;
  for (const ImageFormat& format : kFormats) {
    if (!list.empty()) list += ", ";
    list += format.extension;
  }
  return list;
}

const ImageFormat& requireFormat(const std::string& path) {
  if (const ImageFormat* format = findFormat(path)) return *format;
  const std::string ext = std::filesystem::path(path).extension().string();
  const std::string what = ext.empty()
                               ? "image file '" + path + "' has no extension"
                               : "unsupported image file extension '" + ext + "' in '" + path + "'";
  throw InputError(what + " (valid: " + validExtensionList() + ")");
}

[[noreturn]] void throwCannotRead(const std::string& path, int err) {
  throw InputError("cannot read '" + path + "': " + std::generic_category().message(err));
}

std::vector<unsigned char> readFileBytes(const std::string& path) {
  checkInputFile(path, "image");
  std::FILE* file = std::fopen(path.c_str(), "rb");
  if (file == nullptr) throwCannotRead(path, errno);
  std::vector<unsigned char> bytes;
  std::array<unsigned char, 1 << 16> chunk;
  size_t n = 0;
  errno = 0;
  while ((n = std::fread(chunk.data(), 1, chunk.size(), file)) > 0) {
    bytes.insert(bytes.end(), chunk.begin(), chunk.begin() + static_cast<std::ptrdiff_t>(n));
  }
  // fread on a directory fails with EISDIR here, not at fopen.
  const int err = std::ferror(file) ? (errno != 0 ? errno : EIO) : 0;
  std::fclose(file);
  if (err != 0) throwCannotRead(path, err);
  return bytes;
}

}  // namespace

void writeImage(const Image& image, const std::string& path, const ImageWriteOptions& options) {
  const ImageFormat& format = requireFormat(path);
  writeFileAtomically(path, [&](std::FILE* file) { format.write(image, file, path, options); });
}

Image readImage(const std::string& path) {
  const ImageFormat& format = requireFormat(path);
  return format.read(readFileBytes(path), path);
}

bool isSupportedImagePath(const std::string& path) {
  return findFormat(path) != nullptr;
}

std::vector<std::string> supportedImageExtensions() {
  std::vector<std::string> extensions;
  extensions.reserve(kFormats.size());
  for (const ImageFormat& format : kFormats) extensions.emplace_back(format.extension);
  return extensions;
}

}  // namespace prt
