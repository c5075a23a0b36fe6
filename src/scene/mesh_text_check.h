#pragma once
// Checks of OBJ and PLY files made before the mesh is read. Text (OBJ, ASCII PLY), line by
// line: every number parses (and is finite, unless allowed), every face has at least three
// corners and every index refers to a vertex; the first problem is reported with its line and
// column, file:line:column (MeshFileError).
// Binary PLY, record by record: every record fits in the file, every face has at least three
// corners and every index refers to a vertex, reported with the record and its byte offset
// (assimp 5.2 trusts all three and crashes on a file that breaks them). Other formats are left
// to the reader. Thread-safe.

#include <string>
#include <string_view>

namespace prt {

// Whether a text file's numbers may be infinite or NaN: a mesh block's file refuses them; a
// model file's reader skips the triangles they make, with a warning.
enum class NonFinite { refused, allowed };

// Checks `text`, the content of the mesh file named `file` (for messages), if it is an OBJ
// file (by extension) or a PLY file (by its first bytes); does nothing otherwise.
void checkMeshText(std::string_view text, const std::string& file,
                   NonFinite nonFinite = NonFinite::refused);

}  // namespace prt
