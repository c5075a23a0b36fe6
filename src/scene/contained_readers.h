#pragma once
// The foreign readers, contained: assimp, on a user's file, can assert, crash, loop or grow
// without bound (an assertion in its pre-transform step on OpenGEX files with cameras;
// segfaults on RAW files with colours; a PLY header declaring billions of elements), and a
// render or a worker must not die of it. Every assimp read runs in a child process
// (core/contained_call.h) limited to the memory budget and kForeignReaderSeconds; what it
// read comes back in PRT's own binary form (the asset pack of scene/asset_pack.h, lights and
// cameras as they are), and every way it can fail becomes the reader's own located error
// (MeshFileError, ModelFileError: exit code 2). tinygltf, PRT's glTF reader, runs in the
// process: it is fuzzed with the rest of PRT's own code.
//
// The costs: a fork of the process (copy-on-write) and the model's bytes through a pipe once.

#include <string>

#include "scene/mesh_file.h"
#include "scene/model_file.h"

namespace prt {

inline constexpr double kForeignReaderSeconds = 600;

// loadMeshFileHere and readAssimpFile in a child process.
LoadedMesh loadMeshFileContained(const MeshSource& source);
ImportedModel readAssimpFileContained(const std::string& path, const ModelReadOptions& options);

}  // namespace prt
