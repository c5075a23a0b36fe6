#pragma once
// Model files: whole scenes made by other tools (glTF 2.0 read with tinygltf; glTF 1.0, OBJ+MTL,
// FBX, COLLADA, PLY, STL and the other formats assimp knows, read with assimp) translated into
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

#include "scene/animation.h"
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

// How a model file's animations move what it holds, in the file's coordinates (right-handed,
// before an import's placement): its node tree (only nodes with something placed below them;
// parents before children), the curves driving the nodes, and the node each object, light and
// camera hangs from with its place in that node's coordinates. The objects, lights and cameras
// of ImportedModel are at rest (the nodes' own transforms); SceneAnimation plays the rig.
// Empty when the file has no animation that moves anything placed.
struct ModelRig {
  std::vector<Curve> curves;
  std::vector<RigNode> nodes;          // their curve indices are into `curves`
  std::vector<int32_t> objectNodes;    // per ImportedModel::objects: its node, -1 for none
  std::vector<Transform> objectLocal;  // per object: its mesh in its node's coordinates
  std::vector<int32_t> lightNodes;     // per ImportedModel::lights
  std::vector<Light> lightLocal;       // per light: in its node's coordinates
  std::vector<int32_t> cameraNodes;    // per ImportedModel::cameras
  std::vector<Camera> cameraLocal;     // per camera: in its node's coordinates
  double duration = 0;                 // seconds: the last key of any curve

  bool empty() const { return curves.empty(); }
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
  ModelRig rig;                       // how they move; glTF files only
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

// The readers behind readModelFile, one per library. readGltfFile hands glTF 1.0 to assimp.
// `text`, when not empty, is what readAssimpFile reads in place of the file's own bytes (a
// glTF 1.0 file's JSON given the version it leaves out), the files it names found as the
// file's own would be.
ImportedModel readGltfFile(const std::string& path, const ModelReadOptions& options);
ImportedModel readAssimpFile(const std::string& path, const ModelReadOptions& options,
                             const std::string& text = {});

}  // namespace prt
