#pragma once
// The rig part of a scene's animation (animation.h: curves, nodes, the bindings of objects,
// lights and the camera, the duration) in the asset pack's binary layout (asset_pack.h), for the
// master to send with the scene text: the text carries only the scene's own `key` entries.
//
// Layout (little-endian, core/byte_codec.h): the curves (interpolation, width, rotation, then
// times and values as counted arrays of doubles), the nodes (parent, matrix or translation,
// rotation and scale, three curve indices), the object, light and camera bindings, the
// duration. Reading checks every count against the bytes left before allocating, and the rig
// as addRig would (rigProblem), and that each binding's import is among `imports`.

#include <cstddef>

#include "core/byte_codec.h"
#include "scene/animation.h"

namespace prt {

// Writes the rig part of `animation` (nothing of its fields).
void putRig(ByteWriter& out, const SceneAnimation& animation);
// Reads what putRig wrote; fails `in` (std::runtime_error) for anything else.
SceneAnimation getRig(ByteReader& in, size_t imports);

}  // namespace prt
