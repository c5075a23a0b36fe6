#pragma once
// The scene format's `import` block (docs/scene-format.md): a whole model file (model_file.h)
// brought into the scene — its meshes with their materials and textures, its lights, and its
// cameras offered to the `camera` block — placed by the block's scale, rotations and
// translation on top of the file's own node transforms, after the file's right-handed
// coordinates are turned into PRT's left-handed ones (z negated). A worker takes what the master sent
// (asset_pack.h) in place of the file. Used by the scene parser; errors are InputErrors at the
// offending token, as for every block.

#include <filesystem>
#include <map>
#include <memory>
#include <optional>
#include <set>
#include <string>
#include <vector>

#include "scene/animation.h"
#include "scene/asset_pack.h"
#include "scene/model_file.h"
#include "scene/token_stream.h"
#include "trace/scene.h"

namespace prt {

// Model files already read, by absolute path: a file imported twice is read once.
using ModelCache = std::map<std::string, std::shared_ptr<const ImportedModel>>;

// A camera an imported file offers, placed as the import placed the file.
struct OfferedCamera {
  ModelCamera camera;
  std::string file;  // the import's file, absolute
  // When the file is animated: how the camera follows its node, for the scene's animation
  // once the camera is chosen (its node is the scene animation's).
  std::optional<CameraBinding> binding = {};
};

// What the blocks need from the parser, for the whole of one scene text.
struct ImportBlocks {
  TokenStream& in;
  Scene& scene;
  std::filesystem::path directory;  // of the scene file: model files are found from there
  const ShippedAssets* shipped;     // if not null, what to take instead of the files
  ModelCache& models;
  ModelReadOptions options;
  std::vector<OfferedCamera> cameras = {};  // every import's, in order
  std::set<std::string> warned = {};        // files whose warnings were given
};

// Reads one block after its keyword and adds what it brings to b.scene.
void readImportBlock(ImportBlocks& b, const Token& keyword);

// The affine map of a placement as `mesh` and `import` blocks give it: scale, then rotations
// about x, y and z (degrees), then the translation.
Transform placementTransform(const Vec3& scale, const Vec3& rotateDegrees, const Vec3& translate);

// A light carried by a placement `t` whose size factor is `scale`, its intensity times
// `lightScale`. Lights that fall with distance are made brighter by the square of the scale,
// so that a model scaled up looks as it did.
Light placeLight(Light light, const Transform& t, double scale, double lightScale);
// A camera carried by a placement (its orthographic height scaled by `scale`).
Camera placeCamera(Camera camera, const Transform& t, double scale);
// Model files are right-handed (glTF, and assimp makes every format so); PRT is left-handed:
// z is turned over before the import's placement.
Transform fromRightHanded();

// A camera that shows every bounded object of `scene` (or the origin, with none): from above
// and in front of the box around them (-z, the side imported models face), with 40 degrees of
// vertical field of view and the box's bounding sphere filling the height.
Camera framingCamera(const Scene& scene);

}  // namespace prt
