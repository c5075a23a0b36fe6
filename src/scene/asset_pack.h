#pragma once
// The binary part of a scene, for the master to send with the scene text so that workers need
// no copy of any file: the triangles of `mesh` blocks, and what each `import` block brought in
// (its objects, placed, with their materials, and its textures' decoded texels). writeScene
// writes each such block as it was read (file, transform); a worker parses that text with the
// assets from here in place of the files (parseScene's `shipped`), the same doubles and texels
// bit for bit. A mesh or an image used by several objects or imports is packed once.
//
// Layout (little-endian, as the hosts of a cluster are; core/byte_codec.h): a tag and version;
// the meshes (counts of vertices, triangles, normals, texture coordinates, colours and
// tangents, then each array), the images (size, channels, name, texels), the mesh blocks (a
// mesh index each), then per import its textures (image index, wrap modes, filter, linear)
// and its objects (mesh index, transform, material with texture references local to the
// import), then the rig part of the scene's animation (rig_pack.h): what its imports' model
// files animate, which only the files hold (the scene's own `key` entries travel in the
// text); last, the environment map's size and linear RGB floats (0 x 0 without one).
// Pure functions; thread-safe.

#include <cstdint>
#include <memory>
#include <vector>

#include "scene/animation.h"
#include "trace/scene.h"

namespace prt {

struct ShippedImport {
  std::vector<Object> objects;    // placed; TextureRefs index `textures`
  std::vector<Texture> textures;
};

struct ShippedAssets {
  std::vector<std::shared_ptr<const TriangleMesh>> meshBlocks;  // one per `mesh` block, in order
  std::vector<ShippedImport> imports;                           // one per `import` block
  // The rigs of the scene's animation (no fields), its indices the scene's (addRig).
  SceneAnimation rig;
  std::shared_ptr<const Image> environmentMap;  // the environment's map, if it has one
};

// Empty for a scene with nothing to ship.
std::vector<uint8_t> packAssets(const Scene& scene);
// Throws std::runtime_error for bytes that are not such a packing (truncated, inconsistent
// counts, indices out of range, values no scene can hold).
ShippedAssets unpackAssets(const std::vector<uint8_t>& bytes);

}  // namespace prt
