#pragma once
// Checks of OBJ and PLY files made before the mesh is read. Text (OBJ, ASCII PLY), line by
// line: every number parses and is finite, every face has at least three corners and every
// index refers to a vertex; the first problem is reported with its line (MeshFileError).
// Binary PLY, record by record: every record fits in the file, every face has at least three
// corners and every index refers to a vertex, reported with the record and its byte offset
// (assimp 5.2 trusts all three and crashes on a file that breaks them). Other formats are left
// to the reader. Thread-safe.

#include <string>
#include <string_view>

namespace prt {

// Checks `text`, the content of the mesh file named `file` (for messages), if it is an OBJ
// file (by extension) or a PLY file (by its first bytes); does nothing otherwise.
void checkMeshText(std::string_view text, const std::string& file);

}  // namespace prt
