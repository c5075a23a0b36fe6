#include "scene/texture_file.h"

#include <stb_image.h>

#include <algorithm>
#include <cctype>
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
    throw TextureError("texture " + name + " is not an image PRT can read (" +
                       stbi_failure_reason() + "; PNG, JPEG, BMP, TGA and GIF are read)");
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
