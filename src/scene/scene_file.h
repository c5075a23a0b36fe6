#pragma once
// The .scene text format: parsing, loading from a file and writing back. The format and every
// check made on it are documented in docs/scene-format.md.
//
// Functions are pure apart from loadSceneFile's read, and thread-safe.

#include <string>
#include <string_view>

#include "core/input_error.h"
#include "scene/asset_pack.h"
#include "scene/import_block.h"
#include "trace/scene.h"

namespace prt {

// How scene and model files are read (the master's side; a worker reads what it was sent).
struct SceneReadOptions {
  bool strict = false;  // a model file's missing or unreadable texture is an error
  // --camera: the imported camera to render through, by name or by index (from 0, over the
  // cameras of every import in order); empty: the scene's own choice.
  std::string camera;
  // Model files read already, by absolute path; may be null.
  ModelCache* models = nullptr;
};

// Parses scene text; `fileName` labels error locations only. Throws InputError pointing at the
// culprit token (file:line:col and the line's text) for anything malformed, missing, repeated
// or out of range, and (without a line) for a missing camera or image block.
// Mesh files named by `mesh` blocks are read relative to the directory of `fileName`.
Scene parseScene(std::string_view text, const std::string& fileName,
                 const SceneReadOptions& options = {});
// The same with the meshes of the `mesh` blocks and what the `import` blocks bring taken, in
// order, from `shipped` (unpackAssets of the sender's packAssets) instead of read from files:
// how a worker reads the scene its master sent.
Scene parseScene(std::string_view text, const std::string& fileName,
                 const ShippedAssets& shipped);

// Reads and parses the file at `path`: a scene file (by convention named *.scene, but any
// name is read), or a model file (model_file.h: by its extension, or by its first bytes),
// which is rendered as the scene modelScene describes. Throws InputError naming the file if
// it is missing, unreadable, a directory, empty (or only comments), too large, binary (NUL
// bytes, invalid UTF-8, control characters) and not a model, or a model that cannot be read.
Scene loadSceneFile(const std::string& path, const SceneReadOptions& options = {});

// The scene text that renders model file `path` alone: the file imported whole, its camera
// (options.camera, else its first) or a framing one, an image of 640 pixels wide and as high
// as the camera's aspect ratio asks (else 480), written to the model's name with .png in the
// current directory, and an environment like Blender's default world (a dim grey background and
// ambient light of 0.05). `model` is the file as read.
std::string modelSceneText(const std::string& path, const ImportedModel& model,
                           const SceneReadOptions& options);

// The scene as .scene text, such that parseScene(writeScene(s), ...) reproduces `s` bit for bit
// (every double, negative zeros included). This is how the master sends the scene to its
// workers. `scene` must satisfy the checks parseScene makes, as any parsed scene does;
// surfaces are written inline, as the names of materials are not kept in a Scene. A `mesh`
// block is written as it was read (its file by absolute path; the triangles go separately,
// packMeshes), a `triangle` block with its vertices.
std::string writeScene(const Scene& scene);

}  // namespace prt
