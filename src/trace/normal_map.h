#pragma once
// Normal maps (glTF 2.0's normalTexture): the shading normal a tangent-space normal map gives
// at a point, and the guard that keeps it from facing away from the viewer.
//
// A texel (r, g, b) of a data texture (read as byte / 255: trace/texture.h) encodes the
// tangent-space vector x = (255 r - 128) / 127, likewise y and z, each held to [-1, 1]: byte
// 128 is exactly 0 and 255 is 1, so the mid-grey (128, 128, 255) writers use for "no tilt"
// is exactly the unperturbed normal. (glTF's text maps [0, 1] to [-1, 1] by 2 c - 1, which
// puts 0 between bytes 127 and 128 and tilts (128, 128, 255) by 0.3 degrees; the two differ
// by at most 1/255 in x and y.) `scale` multiplies x and y, as glTF's
// normalize((2 c - 1) * (scale, scale, 1)). The vector is expressed in the frame of the
// surface's outward shading normal N, its tangent T made perpendicular to N and the bitangent
// w cross(N, T): N' = normalize(x T + y B + z N).
//
// The guard: a bumped normal can face so far from the viewer that the mirror direction of the
// view about it points into the surface, which shows as black patches. keepReflectionAbove is
// Cycles' ensure_valid_reflection (Blender 3.x), applied as Cycles applies it to a normal
// map's result: when the reflection of wo about n falls below a threshold above the
// geometric surface (min(0.9 cos, 0.01) in cosine with its normal), n is turned towards the
// geometric normal, in the plane of the two, just enough to lift the reflection onto it.
//
// Plain double arithmetic and sqrt: the same bits everywhere.

#include "core/vec3.h"

namespace prt {

// The tangent-space vector of a normal-map texel (x and y times `scale`), not normalised.
Vec3 normalMapVector(const Color& texel, double scale);

// The shading normal of the map at a point: `normal` the outward unit shading normal, `tangent`
// and `handedness` the interpolated tangent (any length, not necessarily perpendicular) and
// its w. Returns `normal` itself (the same bits) where the map is flat (x = y = 0) or the
// tangent is unusable (zero, or along the normal).
Vec3 mappedNormal(const Vec3& normal, const Vec3& tangent, double handedness, const Vec3& mapVector);

// `n` (unit) or, where the mirror direction of `wo` about it would fall below the surface of
// unit geometric normal `ng` (on wo's side), n turned towards ng just enough (see above).
Vec3 keepReflectionAbove(const Vec3& ng, const Vec3& wo, const Vec3& n);

}  // namespace prt
