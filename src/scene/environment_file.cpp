#include "scene/environment_file.h"

#include <stb_image.h>

#include <algorithm>
#include <cmath>
#include <cctype>
#include <filesystem>
#include <limits>
#include <vector>

#include "core/input_error.h"
#include "image/image_formats.h"
#include "scene/texture_file.h"

namespace prt {
namespace {

std::string extensionOf(const std::string& path) {
  std::string e = std::filesystem::path(path).extension().string();
  for (char& c : e) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return e;
}

size_t pixelBudget(size_t budgetBytes) { return budgetBytes / (3 * sizeof(float)); }

std::string megabytes(size_t bytes) { return std::to_string((bytes + (1u << 20) - 1) >> 20) + " MiB"; }

Image readRadiance(const std::vector<uint8_t>& bytes, const std::string& path,
                   size_t budgetBytes) {
  if (bytes.size() > static_cast<size_t>(std::numeric_limits<int>::max())) {
    throw InputError("environment map '" + path + "' is too large");
  }
  const auto* data = reinterpret_cast<const stbi_uc*>(bytes.data());
  const int length = static_cast<int>(bytes.size());
  int w = 0, h = 0, channels = 0;
  if (!stbi_is_hdr_from_memory(data, length) ||
      stbi_info_from_memory(data, length, &w, &h, &channels) == 0) {
    throw InputError("environment map '" + path +
                     "' is not a Radiance HDR image (it lacks the #?RADIANCE or #?RGBE header)");
  }
  const uint64_t pixels = static_cast<uint64_t>(w) * static_cast<uint64_t>(h);
  if (w <= 0 || h <= 0 || pixels > pixelBudget(budgetBytes)) {
    throw InputError("environment map '" + path + "' of " + std::to_string(w) + "x" +
                     std::to_string(h) + " texels would take " +
                     megabytes(static_cast<size_t>(pixels * 12)) + " decoded, over the budget of " +
                     megabytes(budgetBytes));
  }
  int rw = 0, rh = 0, rc = 0;
  float* texels = stbi_loadf_from_memory(data, length, &rw, &rh, &rc, 3);
  if (texels == nullptr) {
    throw InputError("environment map '" + path + "' could not be decoded: " +
                     stbi_failure_reason());
  }
  Image image(rw, rh);
  std::copy(texels, texels + static_cast<size_t>(rw) * static_cast<size_t>(rh) * 3,
            image.data().begin());
  stbi_image_free(texels);
  return image;
}

}  // namespace

bool isEnvironmentMapPath(const std::string& path) {
  const std::string e = extensionOf(path);
  return e == ".hdr" || e == ".pic" || e == ".exr";
}

std::shared_ptr<const Image> readEnvironmentMap(const std::string& path, size_t budgetBytes) {
  if (!isEnvironmentMapPath(path)) {
    throw InputError("environment map '" + path +
                     "': not a kind of file read as one (.hdr or .pic: Radiance RGBE; .exr: "
                     "OpenEXR)");
  }
  std::error_code error;
  if (!std::filesystem::exists(path, error)) {
    throw InputError("environment map '" + path + "' does not exist");
  }
  std::vector<uint8_t> bytes;
  try {
    bytes = readTextureFile(path);
  } catch (const TextureError&) {
    throw InputError("environment map '" + path +
                     "' could not be read (not a regular file, unreadable, or over 1 GiB)");
  }
  Image image = extensionOf(path) == ".exr"
                    ? readExr(std::span<const unsigned char>(bytes.data(), bytes.size()), path,
                              pixelBudget(budgetBytes))
                    : readRadiance(bytes, path, budgetBytes);
  // Radiance cannot be negative or infinite: such texels (a broken file) read as black.
  for (float& v : image.data()) {
    if (!(v >= 0) || !std::isfinite(v)) v = 0;
  }
  return std::make_shared<const Image>(std::move(image));
}

}  // namespace prt
