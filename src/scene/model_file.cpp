#include "scene/model_file.h"

#include "core/input_error.h"
#include "core/input_file.h"
#include "core/text.h"
#include "scene/contained_readers.h"

#include <assimp/Importer.hpp>
#include <cctype>
#include <cstring>
#include <filesystem>
#include <fstream>

namespace prt {
namespace {

bool isGltf(const std::string& path) {
  const std::string e = lowerExtension(path);
  if (e == ".gltf" || e == ".glb") return true;
  char head[4] = {};
  std::ifstream in(path, std::ios::binary);
  return in.read(head, 4) && std::memcmp(head, "glTF", 4) == 0;
}

}  // namespace

bool isModelFileName(const std::string& path) {
  const std::string e = lowerExtension(path);
  if (e.empty() || e == ".scene") return false;
  if (e == ".gltf" || e == ".glb") return true;
  return Assimp::Importer().IsExtensionSupported(e);
}

bool looksLikeModelFile(const std::string& path) {
  std::error_code error;
  if (std::filesystem::status(path, error).type() != std::filesystem::file_type::regular) {
    return false;
  }
  // Formats known by their first bytes: binary glTF, PLY, binary FBX ("Kaydara FBX Binary").
  // Text formats without a model extension are taken for scene text.
  char head[4] = {};
  std::ifstream in(path, std::ios::binary);
  if (!in.read(head, 4)) return false;
  for (const char* magic : {"glTF", "ply\n", "ply\r", "Kayd"}) {
    if (std::memcmp(head, magic, 4) == 0) return true;
  }
  return false;
}

ImportedModel readModelFile(const std::string& path, const ModelReadOptions& options) {
  std::error_code error;
  const auto status = std::filesystem::status(path, error);
  if (status.type() == std::filesystem::file_type::not_found) {
    throw ModelFileError("model file \"" + path + "\" does not exist");
  }
  if (status.type() != std::filesystem::file_type::regular) {
    throw ModelFileError("model file \"" + path + "\" is not a regular file");
  }
  try {
    checkInputFile(path, "model file");
  } catch (const InputError& e) {
    throw ModelFileError(e.what());
  }
  return isGltf(path) ? readGltfFile(path, options) : readAssimpFileContained(path, options);
}

}  // namespace prt
