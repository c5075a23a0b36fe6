#include "scene/contained_readers.h"

#include <algorithm>
#include <cstring>
#include <filesystem>
#include <limits>
#include <system_error>
#include <type_traits>

#include "core/byte_codec.h"
#include "core/contained_call.h"
#include "core/input_error.h"
#include "core/input_file.h"
#include "core/memory_budget.h"
#include "core/text.h"
#include "scene/asset_pack.h"
#include "scene/mesh_text_check.h"

namespace prt {
namespace {

static_assert(std::is_trivially_copyable_v<Light> && std::is_trivially_copyable_v<Camera>,
              "lights and cameras cross the pipe as bytes: the child is this same program");

template <typename T>
void putBytes(ByteWriter& w, const T& value) {
  w.raw(&value, sizeof value);
}

template <typename T>
T getBytes(ByteReader& r) {
  T value;
  r.raw(&value, sizeof value);
  return value;
}

void putLines(ByteWriter& w, const std::vector<std::string>& lines) {
  w.pod(static_cast<uint64_t>(lines.size()));
  for (const std::string& line : lines) w.text(line.substr(0, 4096));
}

std::vector<std::string> getLines(ByteReader& r) {
  const auto count = r.pod<uint64_t>();
  r.needItems(count, 2);
  std::vector<std::string> lines;
  for (uint64_t i = 0; i < count; ++i) lines.push_back(r.text());
  return lines;
}

// Appends the pack's bytes with their length, so that more can follow.
void putPack(ByteWriter& w, const std::vector<uint8_t>& pack) {
  w.pod(static_cast<uint64_t>(pack.size()));
  w.raw(pack.data(), pack.size());
}

std::vector<uint8_t> getPack(ByteReader& r) {
  const auto size = r.pod<uint64_t>();
  r.needItems(size, 1);
  std::vector<uint8_t> pack(size);
  r.raw(pack.data(), size);
  return pack;
}

int lineOf(const std::exception& e) {
  const auto* mesh = dynamic_cast<const MeshFileError*>(&e);
  return mesh != nullptr ? mesh->line() : 0;
}

// What a failure of the child says, after "<what> FILE ".
std::string failureText(const ContainedFailure& f) {
  switch (f.cause()) {
    case ContainedFailure::Cause::Threw:
      return f.what();
    case ContainedFailure::Cause::OutOfMemory:
      return std::string("could not be read: it ") + f.what();
    case ContainedFailure::Cause::TimedOut:
    case ContainedFailure::Cause::Crashed:
      return std::string("could not be read: the model library (assimp) reading it ") +
             f.what() + "; the file is not one PRT can read (convert it to glTF, OBJ or PLY)";
  }
  return f.what();
}

// After assimp failed on an OBJ or PLY model file: the problem found by the line-by-line check
// of a mesh block's file (mesh_text_check.h), with its line and column, where assimp said
// "vertex index out of range" or crashed. Infinite and NaN coordinates are let through, as the
// model reader skips their triangles. Returns quietly when the check finds nothing, or cannot
// read the file: assimp's own message stands then. Run only after a failure: assimp reads
// files the check refuses (a PLY header with a line of its own, a short final record).
void throwLocatedTextError(const std::string& path) {
  const std::string extension = lowerExtension(path);
  if (extension != ".obj" && extension != ".ply") return;
  std::string text;
  try {
    text = readInputFile(path, "model file");
  } catch (const InputError&) {
    return;
  }
  try {
    checkMeshText(text, path, NonFinite::allowed);
  } catch (const MeshFileError& e) {
    throw ModelFileError(e.what());
  }
}

// The child's limits for reading `path` (its size as it is now: a file that is not there, or
// not regular, is the reader's own error).
ContainedLimits readerLimits(const std::string& path, uint64_t textureBudgetBytes) {
  std::error_code error;
  const uintmax_t size = std::filesystem::file_size(path, error);
  const uint64_t fileBytes = error ? 0 : static_cast<uint64_t>(size);
  ContainedLimits limits;
  limits.memoryBytes = foreignReaderMemoryBytes(fileBytes, textureBudgetBytes);
  limits.seconds = kForeignReaderSeconds;
  limits.memoryRule = "what reading a file of " + formatMemorySize(fileBytes) + " may take: " +
                      formatMemorySize(kForeignReaderBaseBytes) + " + " +
                      std::to_string(kForeignReaderBytesPerFileByte) + " times its size" +
                      (textureBudgetBytes > 0
                           ? " + " + formatMemorySize(textureBudgetBytes) + " for its textures"
                           : std::string()) +
                      ", at most the memory budget (--max-memory)";
  return limits;
}

}  // namespace

uint64_t foreignReaderMemoryBytes(uint64_t fileBytes, uint64_t textureBudgetBytes) {
  constexpr uint64_t kMax = std::numeric_limits<uint64_t>::max();
  uint64_t bytes = kForeignReaderBaseBytes;
  const uint64_t scaled = fileBytes > kMax / kForeignReaderBytesPerFileByte
                              ? kMax
                              : fileBytes * kForeignReaderBytesPerFileByte;
  bytes = scaled > kMax - bytes ? kMax : bytes + scaled;
  bytes = textureBudgetBytes > kMax - bytes ? kMax : bytes + textureBudgetBytes;
  return std::min(bytes, memoryBudgetBytes());
}

LoadedMesh loadMeshFileContained(const MeshSource& source) {
  std::vector<uint8_t> bytes;
  try {
    bytes = runContained(
        [&] {
          LoadedMesh loaded = loadMeshFileHere(source);
          Scene scene;
          scene.objects.push_back({MeshShape{loaded.mesh, source}, {}});
          ByteWriter w;
          putPack(w, packAssets(scene));
          putLines(w, loaded.warnings);
          return std::move(w.out);
        },
        readerLimits(source.file, 0), lineOf);
  } catch (const ContainedFailure& f) {
    if (f.cause() == ContainedFailure::Cause::Threw) throw MeshFileError(f.what(), f.line());
    throw MeshFileError("mesh file " + quote(source.file) + " " + failureText(f));
  }
  try {
    ByteReader r(bytes.data(), bytes.size(), "mesh from the reader");
    ShippedAssets assets = unpackAssets(getPack(r));
    LoadedMesh loaded;
    if (assets.meshBlocks.size() != 1) r.fail("no mesh");
    loaded.mesh = std::make_shared<TriangleMesh>(*assets.meshBlocks[0]);
    loaded.warnings = getLines(r);
    r.finish();
    return loaded;
  } catch (const std::bad_alloc&) {
    throw;
  } catch (const std::exception& e) {
    throw MeshFileError("mesh file " + quote(source.file) + " could not be read: " + e.what());
  }
}

ImportedModel readAssimpFileContained(const std::string& path, const ModelReadOptions& options,
                                      const std::string& text) {
  std::vector<uint8_t> bytes;
  try {
    bytes = runContained(
        [&] {
          const ImportedModel model = readAssimpFile(path, options, text);
          Scene scene;
          scene.objects = model.objects;
          scene.textures = model.textures;
          ImportSource import;
          import.file = path;
          import.objectCount = model.objects.size();
          import.textureCount = model.textures.size();
          scene.imports.push_back(import);
          ByteWriter w;
          putPack(w, packAssets(scene));
          w.pod(static_cast<uint64_t>(model.lights.size()));
          for (const Light& light : model.lights) putBytes(w, light);
          w.pod(static_cast<uint64_t>(model.cameras.size()));
          for (const ModelCamera& camera : model.cameras) {
            w.text(camera.name.substr(0, 4096));
            putBytes(w, camera.camera);
            w.pod(camera.aspectRatio);
          }
          putLines(w, model.warnings);
          w.text(model.format.substr(0, 4096));
          return std::move(w.out);
        },
        readerLimits(path, options.textureBudgetBytes));
  } catch (const ContainedFailure& f) {
    throwLocatedTextError(path);
    if (f.cause() == ContainedFailure::Cause::Threw) throw ModelFileError(f.what());
    throw ModelFileError("model file " + quote(path) + " " + failureText(f));
  }
  try {
    ByteReader r(bytes.data(), bytes.size(), "model from the reader");
    ShippedAssets assets = unpackAssets(getPack(r));
    if (assets.imports.size() != 1) r.fail("no model");
    ImportedModel model;
    model.objects = std::move(assets.imports[0].objects);
    model.textures = std::move(assets.imports[0].textures);
    const auto lights = r.pod<uint64_t>();
    r.needItems(lights, sizeof(Light));
    for (uint64_t i = 0; i < lights; ++i) model.lights.push_back(getBytes<Light>(r));
    const auto cameras = r.pod<uint64_t>();
    r.needItems(cameras, sizeof(Camera));
    for (uint64_t i = 0; i < cameras; ++i) {
      ModelCamera camera;
      camera.name = r.text();
      camera.camera = getBytes<Camera>(r);
      camera.aspectRatio = r.pod<double>();
      model.cameras.push_back(std::move(camera));
    }
    model.warnings = getLines(r);
    model.format = r.text();
    r.finish();
    return model;
  } catch (const std::bad_alloc&) {
    throw;
  } catch (const std::exception& e) {
    throw ModelFileError("model file " + quote(path) + " could not be read: " + e.what());
  }
}

}  // namespace prt
