#pragma once
// Mesh files: the triangles of a `mesh` block, read with the Open Asset Import Library
// (assimp: OBJ, PLY in ASCII and binary, STL, glTF and the other formats it knows), placed by
// the block's transform, and checked. OBJ and PLY files are first checked (mesh_text_check.h):
// text ones line by line, so that a malformed line is reported by its number, which assimp
// does not give and, for OBJ, often reads silently as zeros; binary PLY record by record,
// which assimp does not do before it reads out of bounds.
//
// What is refused and what is skipped:
//   - a missing, unreadable or malformed file, a malformed line, an index out of range in an
//     OBJ or PLY file, a non-finite number in a text file, a truncated binary PLY file, or no
//     usable triangle: MeshFileError;
//   - in a binary file, a triangle with a vertex that is not finite (or, in formats other than
//     OBJ and PLY, an index out of range),
//     and in any file a triangle of zero area (after the transform) or a face that is not a
//     triangle (points, lines): skipped, with one warning per kind saying how many.
// Pure apart from reading the file; thread-safe.

#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

#include "trace/triangle_mesh.h"

namespace prt {

class MeshFileError : public std::runtime_error {
 public:
  // `line` in the mesh file, 1-based; 0 when the problem has no line (binary files, the file
  // as a whole).
  MeshFileError(const std::string& message, int line = 0)
      : std::runtime_error(message), line_(line) {}
  int line() const { return line_; }

 private:
  int line_ = 0;
};

struct LoadedMesh {
  std::shared_ptr<TriangleMesh> mesh;
  std::vector<std::string> warnings;  // what was skipped, one line each
};

// Reads source.file (a path the caller has resolved) and places it as `source` says. The
// reading is contained in a child process (contained_readers.h); loadMeshFileHere does it in
// this one.
LoadedMesh loadMeshFile(const MeshSource& source);
LoadedMesh loadMeshFileHere(const MeshSource& source);

// Places raw triangles as `source` says (scale, rotations about x, y, z, translation; normals
// turned alike), computes vertex normals if `source.smooth` and `normals` is empty, and skips
// what cannot be traced (see above). `normals` is empty or one per vertex.
LoadedMesh placeMesh(std::vector<Vec3> vertices, std::vector<std::array<uint32_t, 3>> triangles,
                     std::vector<Vec3> normals, const MeshSource& source);

}  // namespace prt
