#pragma once
// Line-by-line checks of the text mesh formats, made before the mesh is read: every number
// parses and is finite, every face has at least three corners and every index refers to a
// vertex. The first problem is reported with its line (MeshFileError). Other formats, and
// binary PLY, are left to the reader. Thread-safe.

#include <string>
#include <string_view>

namespace prt {

// Checks `text`, the content of the mesh file named `file` (for messages), if it is an OBJ
// file (by extension) or an ASCII PLY file (by header); does nothing otherwise.
void checkMeshText(std::string_view text, const std::string& file);

}  // namespace prt
