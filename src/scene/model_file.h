#pragma once
// Model files: whole scenes made by other tools (glTF 2.0 read with tinygltf; OBJ+MTL, FBX,
// COLLADA, PLY, STL and the other formats assimp knows, read with assimp) translated into
// PRT's own terms — objects placing meshes by their node transforms (instances: a mesh used by
// several nodes is one TriangleMesh), materials mapped onto the Hall model
// (material_mapping.h), textures decoded (texture_file.h), lights and cameras. Everything
// after this layer (World, the exporter, the drivers) sees only those terms.
//
// What cannot be expressed is not dropped silently: each such thing gives one warning line
// (a material feature the Hall model lacks, a missing texture, skinning, a degenerate
// triangle skipped). What makes the file unusable throws ModelFileError: a file that is
// missing, not a regular file, too large, malformed, or holds nothing that can be traced.
// Pure apart from reading the file and the files it names; thread-safe.

#include <cstddef>
#include <stdexcept>
#include <string>
#include <vector>

#include "trace/scene.h"

namespace prt {

class ModelFileError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// A camera a model file defines, placed in the file's coordinates.
struct ModelCamera {
  std::string name;         // the camera's name, else its node's, else "camera N"
  Camera camera;
  double aspectRatio = 0;   // width / height the file asks for; 0: none given
};

struct ImportedModel {
  // Meshes as InstanceShapes placed in the file's coordinates; their TextureRefs index
  // `textures`.
  std::vector<Object> objects;
  std::vector<Light> lights;
  std::vector<ModelCamera> cameras;
  std::vector<Texture> textures;
  std::vector<std::string> warnings;  // one line each, naming the file
  std::string format;                 // "glTF 2.0", or the assimp importer's description
};

struct ModelReadOptions {
  bool strict = false;  // a missing or unreadable texture is an error, not a warning
  // Decoded texels allowed in all (bytes): images beyond it are left out with a warning.
  size_t textureBudgetBytes = size_t{1} << 30;
};

// Whether `path` names a model file by its extension (anything but .scene that a reader here
// knows); files without a known extension are told apart by content (looksLikeModelFile).
bool isModelFileName(const std::string& path);
// Whether the first bytes of a file are those of a glTF, a binary glTF or another format
// assimp recognises, rather than scene text.
bool looksLikeModelFile(const std::string& path);

ImportedModel readModelFile(const std::string& path, const ModelReadOptions& options = {});

// The readers behind readModelFile, one per library.
ImportedModel readGltfFile(const std::string& path, const ModelReadOptions& options);
ImportedModel readAssimpFile(const std::string& path, const ModelReadOptions& options);

}  // namespace prt
