#pragma once
// The foreign readers, contained: assimp, on a user's file, can assert, crash, loop or grow
// without bound (an assertion in its pre-transform step on OpenGEX files with cameras;
// segfaults on RAW files with colours; a PLY header declaring billions of elements), and a
// render or a worker must not die of it. Every assimp read runs in a child process
// (core/contained_call.h) limited in memory (foreignReaderMemoryBytes) and to
// kForeignReaderSeconds; what it
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

// What a foreign reader may allocate, beyond what the process maps: 512 MiB, plus 64 times
// the file's size, plus the textures' budget (a model's reader decodes its textures), at most
// the memory budget. A limit tied to the file's size, because assimp allocates what a header
// declares: a 1 kB PLY, OFF, ASE or X file declaring a billion vertices grew to 12 GB before
// this rule. Measured on real files: assimp needs about 7 times an OBJ's size and 20 times a
// binary PLY's (a 19 MB PLY: 372 MB at the peak, with the render's own memory).
inline constexpr uint64_t kForeignReaderBaseBytes = uint64_t{512} << 20;
inline constexpr uint64_t kForeignReaderBytesPerFileByte = 64;
uint64_t foreignReaderMemoryBytes(uint64_t fileBytes, uint64_t textureBudgetBytes);

// loadMeshFileHere and readAssimpFile in a child process.
LoadedMesh loadMeshFileContained(const MeshSource& source);
ImportedModel readAssimpFileContained(const std::string& path, const ModelReadOptions& options,
                                      const std::string& text = {});

}  // namespace prt
