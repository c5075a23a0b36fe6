#pragma once
// The .scene text format: parsing, loading from a file and writing back. The format and every
// check made on it are documented in docs/scene-format.md.
//
// Functions are pure apart from loadSceneFile's read, and thread-safe.

#include <string>
#include <string_view>

#include "core/input_error.h"
#include "trace/scene.h"

namespace prt {

// Parses scene text; `fileName` labels error locations only. Throws InputError pointing at the
// culprit token (file:line:col and the line's text) for anything malformed, missing, repeated
// or out of range, and (without a line) for a missing camera or image block.
Scene parseScene(std::string_view text, const std::string& fileName);

// Reads and parses the file at `path` (by convention named *.scene, but any name is read).
// Throws InputError naming the file if it is missing, unreadable, a directory, empty (or only
// comments), too large, or binary (NUL bytes, invalid UTF-8, control characters).
Scene loadSceneFile(const std::string& path);

// The scene as .scene text, such that parseScene(writeScene(s), ...) reproduces `s` bit for bit
// (every double, negative zeros included). This is how the master sends the scene to its
// workers. `scene` must satisfy the checks parseScene makes, as any parsed scene does;
// surfaces are written inline, as the names of materials are not kept in a Scene.
std::string writeScene(const Scene& scene);

}  // namespace prt
