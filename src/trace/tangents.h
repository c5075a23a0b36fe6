#pragma once
// Tangents of a mesh for its normal maps, when the file gave none: glTF 2.0 asks for
// MikkTSpace's (what Blender computes and bakes with), and this is its per-vertex rule in
// plain form. For each triangle the directions along which u grows and v falls (up the image:
// trace/texture.h's v runs down) are found from the texture coordinates' derivatives
// (Lengyel 2001); at each corner they are projected onto the plane of the vertex's normal,
// made unit, and added weighted by the corner's angle (the angle between the two edges,
// projected as well); per vertex the sum along u is made unit (Gram-Schmidt against the
// normal again) and the handedness w is the side of cross(normal, tangent) the v sum lies
// on. Vertices are a file's vertices: glTF writers split them where texture coordinates or
// normals part (at seams), which is how MikkTSpace groups corners too, so on such meshes the
// two agree up to rounding. Where they part: MikkTSpace splits a vertex whose triangles are
// mapped with opposite handedness (mirrored UVs) and gives each side its own tangent, here
// they are summed (the mirror line's vertices get one); and degenerate mappings (triangles of
// no UV area) are left out here where MikkTSpace borrows from neighbours.
//
// Plain double arithmetic, the portable arctangent for the angles: the same bits everywhere.

#include <array>
#include <vector>

#include "trace/triangle_mesh.h"

namespace prt {

// One tangent per vertex as TriangleMesh::tangents holds them (zero where no triangle with a
// mapping reaches the vertex); empty when the mesh has no texture coordinates. Without
// vertex normals, the triangles' own normals (angle-weighted per vertex) take their place.
std::vector<std::array<double, 4>> computeTangents(const TriangleMesh& mesh);

}  // namespace prt
