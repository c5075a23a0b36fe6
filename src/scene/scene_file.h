#pragma once
// The .scene text format: parsing, loading from a file and writing back. The format and every
// check made on it are documented in docs/scene-format.md.
//
// Functions are pure apart from loadSceneFile's read, and thread-safe.

#include <string>
#include <string_view>

#include "core/input_error.h"
#include "scene/mesh_pack.h"
#include "trace/scene.h"

namespace prt {

// Parses scene text; `fileName` labels error locations only. Throws InputError pointing at the
// culprit token (file:line:col and the line's text) for anything malformed, missing, repeated
// or out of range, and (without a line) for a missing camera or image block.
// Mesh files named by `mesh` blocks are read relative to the directory of `fileName`.
Scene parseScene(std::string_view text, const std::string& fileName);
// The same with the meshes of the `mesh` blocks taken, in order, from `shipped`
// (unpackMeshes of the sender's packMeshes) instead of read from files: how a worker reads
// the scene its master sent.
Scene parseScene(std::string_view text, const std::string& fileName,
                 const ShippedMeshes& shipped);

// Reads and parses the file at `path` (by convention named *.scene, but any name is read).
// Throws InputError naming the file if it is missing, unreadable, a directory, empty (or only
// comments), too large, or binary (NUL bytes, invalid UTF-8, control characters).
Scene loadSceneFile(const std::string& path);

// The scene as .scene text, such that parseScene(writeScene(s), ...) reproduces `s` bit for bit
// (every double, negative zeros included). This is how the master sends the scene to its
// workers. `scene` must satisfy the checks parseScene makes, as any parsed scene does;
// surfaces are written inline, as the names of materials are not kept in a Scene. A `mesh`
// block is written as it was read (its file by absolute path; the triangles go separately,
// packMeshes), a `triangle` block with its vertices.
std::string writeScene(const Scene& scene);

}  // namespace prt
