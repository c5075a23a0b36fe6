#pragma once
// The meshes of a scene in a compact binary form, for the master to send with the scene text
// so that workers need no copy of the mesh files: writeScene writes each `mesh` block as it
// was read (file, transform, surface), and a worker parses that text with the meshes from
// here in place of the files (parseScene's `shipped`), the same doubles bit for bit.
//
// Layout (little-endian, as the hosts of a cluster are): the count of meshes; per mesh the
// counts of vertices, triangles and normals (0 or the vertices'), then the vertices as three
// doubles each, the triangles as three uint32 each, the normals as three doubles each. About
// 36 bytes per triangle of a closed mesh with normals, against some 80 as scene text.
// Pure functions; thread-safe.

#include <cstdint>
#include <memory>
#include <vector>

#include "trace/scene.h"

namespace prt {

using ShippedMeshes = std::vector<std::shared_ptr<const TriangleMesh>>;

// The meshes of the scene's `mesh` blocks (not its `triangle` blocks, which travel as text),
// in the order of its objects.
std::vector<uint8_t> packMeshes(const Scene& scene);
// Throws std::runtime_error for bytes that are not such a packing (truncated, inconsistent
// counts, indices out of range).
ShippedMeshes unpackMeshes(const std::vector<uint8_t>& bytes);

}  // namespace prt
