#pragma once
// Textures: images that vary a material's colour over a mesh, looked up at the texture
// coordinates the mesh carries. A lookup is deterministic arithmetic on doubles (no fused
// operations, no library call), so every machine and every build of the kernels reads the
// same bits: bit-identical images need nothing else of them.
//
// Coordinates follow glTF: u runs across the image from its left edge, v down from its top
// row, one image width (height) per unit; readers of formats whose v runs up (OBJ, and every
// format through assimp) turn it over. Texels are 8-bit: sRGB-encoded for colours (base
// colour, emission), decoded to linear RGB on lookup; plain numbers for data (glTF's
// metallic-roughness, normal and transmission textures: a Texture marked `linear`), read as
// byte / 255 with no curve. A lookup filters bilinearly (between the four nearest texel
// centres, in linear values) unless the file asked for the nearest texel; a data texture
// blends as a + t (b - a), so that where its texels agree it reads their value exactly (a
// flat normal map is exactly flat). No mipmaps: a texture seen from far away aliases unless
// the pixel is supersampled.
//
// Plain data, shared read-only: safe to sample from many threads.

#include <array>
#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "core/vec3.h"

namespace prt {

// The decoded pixels of one image file (or one image embedded in a model file).
struct TextureImage {
  int width = 0, height = 0;
  int channels = 3;             // 1 grey, 2 grey + alpha, 3 RGB, 4 RGBA
  std::vector<uint8_t> texels;  // width * height * channels, row 0 at the top
  std::string name;             // where it came from, for messages and exports
  bool operator==(const TextureImage&) const = default;
};

enum class TextureWrap : uint8_t { repeat, clamp, mirror };

// An image and how it is sampled (a glTF texture: image + sampler).
struct Texture {
  std::shared_ptr<const TextureImage> image;  // never null
  TextureWrap wrapU = TextureWrap::repeat, wrapV = TextureWrap::repeat;
  bool nearest = false;  // the nearest texel instead of bilinear filtering
  bool linear = false;   // data: texels are byte / 255, not sRGB-encoded colours
  bool operator==(const Texture& o) const {
    return wrapU == o.wrapU && wrapV == o.wrapV && nearest == o.nearest && linear == o.linear &&
           (image == o.image || *image == *o.image);
  }
};

// An affine map of texture coordinates (glTF's KHR_texture_transform, OBJ's -o and -s):
// (u, v) -> (m[0] u + m[1] v + m[2], m[3] u + m[4] v + m[5]).
struct UvTransform {
  std::array<double, 6> m{1, 0, 0, 0, 1, 0};
  bool isIdentity() const { return m == std::array<double, 6>{1, 0, 0, 0, 1, 0}; }
  bool operator==(const UvTransform&) const = default;
};

// A material's use of a texture.
struct TextureRef {
  int32_t texture = -1;  // index into Scene::textures; -1: none
  UvTransform uv;
  bool operator==(const TextureRef&) const = default;
};

// sRGB-encoded 8-bit value to linear, exactly the same bits everywhere (a table computed with
// the portable power).
double srgbToLinear(uint8_t value);

// A data texel's value: byte / 255, no curve.
double linearFromByte(uint8_t value);

// The texture's linear RGB at (u, v) (a data texture's values). Coordinates that are not finite read as (0, 0).
Color sampleTexture(const Texture& texture, double u, double v);

}  // namespace prt
