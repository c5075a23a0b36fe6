#include "scene/texture_file.h"

#include <stb_image.h>

#include <algorithm>
#include <cctype>
#include <cstdint>
#include <fstream>
#include <limits>
#include <system_error>

namespace prt {
namespace {

constexpr uintmax_t kMaxTextureFileBytes = uintmax_t{1} << 30;

std::string lower(std::string text) {
  for (char& c : text) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return text;
}

bool isRegularFile(const std::filesystem::path& path) {
  std::error_code error;
  return std::filesystem::is_regular_file(path, error);
}

uint32_t bigEndian32(const uint8_t* p) {
  return (uint32_t{p[0]} << 24) | (uint32_t{p[1]} << 16) | (uint32_t{p[2]} << 8) | uint32_t{p[3]};
}

// Whether the bytes start with PNG's signature.
bool isPng(const uint8_t* bytes, size_t size) {
  static constexpr uint8_t kSignature[8] = {0x89, 'P', 'N', 'G', '\r', '\n', 0x1a, '\n'};
  return size >= 8 && std::equal(kSignature, kSignature + 8, bytes);
}

// A PNG header's width, height and channels (false when the bytes do not start one): stb's
// own reading refuses an image too large for its memory limit, and then says only that no
// format matched.
bool pngHeader(const uint8_t* bytes, size_t size, int& width, int& height, int& channels) {
  if (size < 33 || !isPng(bytes, size)) return false;
  if (!std::equal(bytes + 12, bytes + 16, reinterpret_cast<const uint8_t*>("IHDR"))) return false;
  const uint32_t w = bigEndian32(bytes + 16), h = bigEndian32(bytes + 20);
  if (w == 0 || h == 0 || w > (1u << 30) || h > (1u << 30)) return false;
  width = static_cast<int>(w);
  height = static_cast<int>(h);
  const uint8_t colorType = bytes[25];
  channels = colorType == 2 ? 3 : colorType == 4 ? 2 : colorType == 6 ? 4 : colorType == 3 ? 3 : 1;
  return true;
}

// A PNG whose compressed image data cannot inflate to the rows its header declares (deflate
// expands at most about 1,032 times): a decoder would size its buffer by the header and grow it
// while inflating, gigabytes for a file of kilobytes, before finding the data short. Returns
// the declared size of the rows in bytes when that is so, else 0.
uint64_t pngShortOfItsRows(const uint8_t* bytes, size_t size) {
  if (size < 33 || !isPng(bytes, size)) return 0;
  if (!std::equal(bytes + 12, bytes + 16, reinterpret_cast<const uint8_t*>("IHDR"))) return 0;
  const uint64_t width = bigEndian32(bytes + 16), height = bigEndian32(bytes + 20);
  if (width > (1u << 24) || height > (1u << 24)) return 0;  // refused by size before this
  const uint64_t depth = bytes[24], colorType = bytes[25];
  const uint64_t samples = colorType == 2 ? 3 : colorType == 4 ? 2 : colorType == 6 ? 4 : 1;
  // One filter byte a row, then its samples (interlaced images have more rows: more bytes).
  const uint64_t rows = height * (1 + (width * samples * depth + 7) / 8);
  uint64_t compressed = 0;
  for (size_t at = 8; at + 12 <= size;) {
    const uint64_t length = bigEndian32(bytes + at);
    if (std::equal(bytes + at + 4, bytes + at + 8, reinterpret_cast<const uint8_t*>("IDAT"))) {
      compressed += length;
    }
    if (length > size - at - 12) break;
    at += 12 + length;
  }
  return rows > 1100 * compressed + 4096 ? rows : 0;
}

// A PNG chunk before IEND that claims more bytes than the file has left (empty when none):
// stb_image grows its buffer for image data to a chunk's claimed length before reading it,
// gigabytes for a file of kilobytes.
std::string pngChunkPastTheEnd(const uint8_t* bytes, size_t size) {
  if (!isPng(bytes, size)) return {};
  for (size_t at = 8; at + 8 <= size;) {
    const uint64_t length = bigEndian32(bytes + at);
    const std::string type(reinterpret_cast<const char*>(bytes + at + 4), 4);
    if (size - at < 12 || length > size - at - 12) {
      std::string shown;
      for (const char c : type) shown += std::isalnum(static_cast<unsigned char>(c)) ? c : '?';
      return "its " + shown + " chunk at byte " + std::to_string(at) + " claims " +
             std::to_string(length) + " bytes, beyond the file's end";
    }
    if (type == "IEND") break;
    at += 12 + length;
  }
  return {};
}

}  // namespace

std::shared_ptr<const TextureImage> decodeTextureImage(const uint8_t* bytes, size_t size,
                                                       const std::string& name,
                                                       size_t& budgetBytes) {
  if (size == 0) throw TextureError("texture " + name + " is empty");
  if (size > static_cast<size_t>(std::numeric_limits<int>::max())) {
    throw TextureError("texture " + name + " is too large to decode");
  }
  int width = 0, height = 0, channels = 0;
  const int length = static_cast<int>(size);
  if (stbi_info_from_memory(bytes, length, &width, &height, &channels) == 0) {
    const std::string reason = stbi_failure_reason();
    // A PNG whose header stb refused for its size: refused below by that size, with it named.
    if (!pngHeader(bytes, size, width, height, channels) ||
        (width <= kMaxTextureSide && height <= kMaxTextureSide &&
         static_cast<size_t>(width) * static_cast<size_t>(height) *
                 static_cast<size_t>(channels) <= budgetBytes)) {
      throw TextureError("texture " + name + " is not an image PRT can read (" + reason +
                         "; PNG, JPEG, BMP, TGA and GIF are read)");
    }
  }
  if (width <= 0 || height <= 0 || width > kMaxTextureSide || height > kMaxTextureSide ||
      channels < 1 || channels > 4) {
    throw TextureError("texture " + name + " is " + std::to_string(width) + " x " +
                       std::to_string(height) + " pixels; at most " +
                       std::to_string(kMaxTextureSide) + " on a side are read");
  }
  const size_t decoded = static_cast<size_t>(width) * static_cast<size_t>(height) *
                         static_cast<size_t>(channels);
  if (decoded > budgetBytes) {
    throw TextureError("texture " + name + " (" + std::to_string(width) + " x " +
                       std::to_string(height) + ") would take " +
                       std::to_string(decoded >> 20) + " MiB decoded, beyond what is left of " +
                       "the textures' memory budget (" + std::to_string(budgetBytes >> 20) +
                       " MiB)");
  }
  if (const std::string why = pngChunkPastTheEnd(bytes, size); !why.empty()) {
    throw TextureError("texture " + name + " is truncated or not a valid PNG: " + why);
  }
  if (const uint64_t rows = pngShortOfItsRows(bytes, size)) {
    throw TextureError("texture " + name + " declares " + std::to_string(width) + " x " +
                       std::to_string(height) + " pixels (" + std::to_string(rows >> 20) +
                       " MiB of rows) but its " + std::to_string(size) +
                       " bytes cannot hold them: it is truncated or not a valid PNG");
  }
  int w = 0, h = 0, c = 0;
  stbi_uc* pixels = stbi_load_from_memory(bytes, length, &w, &h, &c, channels);
  if (pixels == nullptr) {
    throw TextureError("texture " + name + " could not be decoded: " + stbi_failure_reason());
  }
  auto image = std::make_shared<TextureImage>();
  image->width = w;
  image->height = h;
  image->channels = channels;
  image->name = name;
  image->texels.assign(pixels, pixels + decoded);
  stbi_image_free(pixels);
  budgetBytes -= decoded;
  return image;
}

std::vector<uint8_t> readTextureFile(const std::filesystem::path& path) {
  std::error_code error;
  const auto status = std::filesystem::status(path, error);
  if (status.type() != std::filesystem::file_type::regular) {
    throw TextureError("texture file \"" + path.string() + "\" is not a regular file");
  }
  const uintmax_t size = std::filesystem::file_size(path, error);
  if (error || size > kMaxTextureFileBytes) {
    throw TextureError("texture file \"" + path.string() + "\" is too large (over 1 GiB)");
  }
  std::ifstream in(path, std::ios::binary);
  std::vector<uint8_t> bytes(static_cast<size_t>(size));
  if (!in || !in.read(reinterpret_cast<char*>(bytes.data()), static_cast<std::streamsize>(size))) {
    throw TextureError("texture file \"" + path.string() + "\" could not be read");
  }
  return bytes;
}

std::filesystem::path findTextureFile(const std::filesystem::path& modelDirectory,
                                      const std::string& written) {
  namespace fs = std::filesystem;
  std::string text = written;
  if (text.rfind("file://", 0) == 0) text.erase(0, 7);
  std::replace(text.begin(), text.end(), '\\', '/');
  // Leading and trailing blanks come from hand-edited MTL files.
  while (!text.empty() && std::isspace(static_cast<unsigned char>(text.back()))) text.pop_back();
  while (!text.empty() && std::isspace(static_cast<unsigned char>(text.front()))) text.erase(0, 1);
  if (text.empty()) return {};
  // A drive letter ("C:/Users/...") means an absolute path on another machine.
  const bool windowsAbsolute =
      text.size() > 2 && std::isalpha(static_cast<unsigned char>(text[0])) && text[1] == ':';
  const fs::path given(windowsAbsolute ? text.substr(2) : text);
  std::vector<fs::path> tries;
  if (given.is_absolute() && !windowsAbsolute) tries.push_back(given);
  if (given.is_relative()) tries.push_back(modelDirectory / given);
  if (text.find('%') != std::string::npos) {  // a URI's escapes: "my%20texture.png"
    std::string decoded;
    for (size_t i = 0; i < text.size(); ++i) {
      if (text[i] == '%' && i + 2 < text.size() && std::isxdigit(static_cast<unsigned char>(text[i + 1])) &&
          std::isxdigit(static_cast<unsigned char>(text[i + 2]))) {
        decoded += static_cast<char>(std::stoi(text.substr(i + 1, 2), nullptr, 16));
        i += 2;
      } else {
        decoded += text[i];
      }
    }
    tries.push_back(fs::path(decoded).is_relative() ? modelDirectory / decoded : fs::path(decoded));
  }
  const fs::path base = given.filename();
  tries.push_back(modelDirectory / base);
  tries.push_back(modelDirectory / "textures" / base);
  for (const fs::path& p : tries) {
    if (isRegularFile(p)) return p.lexically_normal();
  }
  // Files made on systems whose names ignore case.
  const std::string wanted = lower(base.string());
  std::error_code error;
  for (const fs::path& dir : {modelDirectory, modelDirectory / "textures"}) {
    for (fs::directory_iterator it(dir, error), end; !error && it != end; it.increment(error)) {
      if (lower(it->path().filename().string()) == wanted && isRegularFile(it->path())) {
        return it->path().lexically_normal();
      }
    }
  }
  return {};
}

}  // namespace prt
