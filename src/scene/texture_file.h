#pragma once
// Texture images for model files: decoding with stb_image (PNG, JPEG, BMP, TGA, GIF's first
// frame; from files and from bytes a glTF buffer or data: URI holds), within a budget of
// decoded bytes, and finding the file a model names in the forms real files contain: relative
// to the model, absolute, with Windows backslashes, spaces or a different letter case, or
// moved beside the model. Pure apart from reading files; thread-safe.
//
// Why stb_image: one packaged library (Debian's libstb) decodes both of glTF's formats, PNG
// and JPEG, from memory, and tells an image's size before decoding it, so that an absurd one
// is refused before any allocation; libpng would need libjpeg beside it, and OpenImageIO
// brings dozens of libraries and a slow start for the same two formats.

#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

#include "trace/texture.h"

namespace prt {

class TextureError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// Sides beyond this are refused whatever the budget (a 32768 x 32768 RGBA image is 4 GiB).
inline constexpr int kMaxTextureSide = 32768;

// Decodes an encoded image (8 bits per channel; 16-bit images are reduced to 8). `name` labels
// messages and the image. Takes the decoded size off `budgetBytes`; throws TextureError for
// bytes that are not an image, a side beyond kMaxTextureSide or a size beyond the budget.
std::shared_ptr<const TextureImage> decodeTextureImage(const uint8_t* bytes, size_t size,
                                                       const std::string& name,
                                                       size_t& budgetBytes);

// Reads an image file: a regular file of at most 1 GiB. Throws TextureError.
std::vector<uint8_t> readTextureFile(const std::filesystem::path& path);

// The file a model at `modelDirectory` means by `written` (a path as the model file wrote
// it), or an empty path when no such file exists.
std::filesystem::path findTextureFile(const std::filesystem::path& modelDirectory,
                                      const std::string& written);

}  // namespace prt
