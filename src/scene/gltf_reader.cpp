// readGltfFile: glTF 2.0 (.gltf with its buffers and images, .glb, data: URIs) read with
// tinygltf and translated: the default scene's node tree with its transforms, each mesh
// primitive a TriangleMesh shared by every node that uses it, materials by mapPbrMaterial,
// textures with their samplers and KHR_texture_transform, cameras and KHR_lights_punctual,
// and, when the file's animations move any of those, the node tree they hang from as a ModelRig
// (its channels read by gltf_animation.h). glTF 1.0, which tinygltf does not read (a binary
// glTF of version 1; JSON whose asset.version says 1 and whose collections are not 2.0's
// arrays; JSON with no version and 1.0's collections keyed by id), is handed to assimp's
// reader, contained (readAssimpFileContained).
//
// tinygltf parses the JSON and loads buffers and images; every index and byte range it
// leaves unchecked is checked here before it is read, and every file it reads goes through
// readBoundedFile (a regular file of bounded size), so a hostile file cannot make this read
// out of bounds, read a FIFO or a device, or allocate without limit.

#include <nlohmann/json.hpp>
#include <tiny_gltf.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <limits>
#include <map>
#include <numbers>
#include <optional>
#include <set>
#include <string_view>
#include <tuple>

#include "scene/contained_readers.h"
#include "scene/gltf_accessor.h"
#include "scene/gltf_animation.h"
#include "scene/material_mapping.h"
#include "scene/model_file.h"
#include "scene/model_mesh.h"
#include "scene/model_notes.h"
#include "scene/texture_file.h"
#include "trace/tangents.h"

namespace prt {
namespace {

namespace fs = std::filesystem;

constexpr uintmax_t kMaxGltfFileBytes = uintmax_t{2} << 30;
// Photometric glTF units to PRT's: Blender writes 683 lm/W (its default, "Standard"
// lighting mode) and renders a Lambertian surface with 1/pi of the irradiance.
constexpr double kLightScale = 1.0 / (683.0 * std::numbers::pi);

// --- files, through tinygltf's callbacks -----------------------------------------------------

// What one reading may read in all (the file, its buffers and images; a file naming one buffer
// many times reads it many times).
constexpr uintmax_t kMaxBytesRead = uintmax_t{4} << 30;
// Deeper JSON than this is no glTF; nlohmann's parser recurses once a level.
constexpr int kMaxJsonDepth = 512;

bool readBoundedFile(std::vector<unsigned char>* out, std::string* err, const std::string& path,
                     void* budget) {
  std::error_code error;
  const auto status = fs::status(path, error);
  if (status.type() != fs::file_type::regular) {
    if (err) *err += "\"" + path + "\" is not a regular file\n";
    return false;
  }
  const uintmax_t size = fs::file_size(path, error);
  if (error || size > kMaxGltfFileBytes) {
    if (err) *err += "\"" + path + "\" is too large (over 2 GiB)\n";
    return false;
  }
  if (budget != nullptr) {
    auto& left = *static_cast<uintmax_t*>(budget);
    if (size > left) {
      if (err) *err += "the file's buffers and images together exceed 4 GiB at \"" + path + "\"\n";
      return false;
    }
    left -= size;
  }
  std::ifstream in(path, std::ios::binary);
  out->resize(static_cast<size_t>(size));
  if (!in || !in.read(reinterpret_cast<char*>(out->data()), static_cast<std::streamsize>(size))) {
    if (err) *err += "\"" + path + "\" could not be read\n";
    return false;
  }
  return true;
}
bool fileExists(const std::string& path, void*) {
  std::error_code error;
  return fs::exists(path, error);
}
std::string expandNothing(const std::string& path, void*) { return path; }
bool writeNothing(std::string*, const std::string&, const std::vector<unsigned char>&,
                  void*) {
  return false;
}

// The encoded bytes of a file's images, kept here (not in tinygltf's images) and decoded by
// decodeTextureImage within the budget once a texture uses them. Images of the same bytes (a
// file naming one image file many times) share one copy.
struct EncodedImages {
  static constexpr uintmax_t kMaxBytes = uintmax_t{1} << 30;  // of different images, in all
  std::map<int, std::shared_ptr<const std::vector<unsigned char>>> byImage;  // null: over budget
  std::multimap<uint64_t, std::shared_ptr<const std::vector<unsigned char>>> byHash;
  std::map<int, int> inView;  // images stored in buffer views: their view
  uintmax_t kept = 0;
};

bool keepEncoded(tinygltf::Image* image, const int index, std::string*, std::string*, int, int,
                 const unsigned char* bytes, int size, void* user) {
  auto& store = *static_cast<EncodedImages*>(user);
  // tinygltf hands an image in a buffer view over without checking the view's range against
  // its buffer: its bytes are taken from the buffer later, checked (GltfReader::viewBytes).
  if (image->bufferView >= 0) {
    image->as_is = true;
    store.inView[index] = image->bufferView;
    return true;
  }
  uint64_t hash = 14695981039346656037ull;
  for (int i = 0; i < size; ++i) hash = (hash ^ bytes[i]) * 1099511628211ull;
  image->as_is = true;
  const auto [first, last] = store.byHash.equal_range(hash);
  for (auto it = first; it != last; ++it) {
    if (it->second->size() == static_cast<size_t>(size) &&
        std::memcmp(it->second->data(), bytes, static_cast<size_t>(size)) == 0) {
      store.byImage[index] = it->second;
      return true;
    }
  }
  if (static_cast<uintmax_t>(size) > EncodedImages::kMaxBytes - store.kept) {
    store.byImage[index] = nullptr;
    return true;
  }
  auto copy = std::make_shared<const std::vector<unsigned char>>(bytes, bytes + size);
  store.kept += static_cast<uintmax_t>(size);
  store.byHash.emplace(hash, copy);
  store.byImage[index] = std::move(copy);
  return true;
}

// Why the bytes of a .glb are not one (its header or chunks lie about their lengths), or
// empty: tinygltf trusts some of them.
std::string glbProblem(const std::vector<unsigned char>& b) {
  auto u32 = [&](size_t at) {
    uint32_t v;
    std::memcpy(&v, b.data() + at, 4);
    return v;
  };
  if (b.size() < 20) return "it is shorter than a binary glTF's header";
  if (u32(4) != 2) return "its binary glTF version is " + std::to_string(u32(4)) + ", not 2";
  if (u32(8) != b.size()) {
    return "its header says " + std::to_string(u32(8)) + " bytes, the file has " + std::to_string(b.size());
  }
  size_t at = 12;
  for (int chunk = 0; at < b.size(); ++chunk) {
    if (b.size() - at < 8) return "a chunk header is cut off";
    const uint64_t length = u32(at), type = u32(at + 4);
    if (length > b.size() - at - 8) return "a chunk reaches past the end of the file";
    if (chunk == 0 && type != 0x4E4F534Au) return "its first chunk is not JSON";
    if (length % 4 != 0) return "a chunk's length is not a multiple of 4";
    at += 8 + length;
  }
  return {};
}

// Why the bytes of a binary glTF 1.0 (KHR_binary_glTF: a 20-byte header of magic, version 1,
// length, content length and content format 0 for JSON, then the JSON, then the binary body)
// are not one, or empty. assimp, which reads these, says only that no reader suits a file
// whose header lies.
std::string glbOneProblem(const std::vector<unsigned char>& b) {
  auto u32 = [&](size_t at) {
    uint32_t v;
    std::memcpy(&v, b.data() + at, 4);
    return v;
  };
  if (b.size() < 20) return "it is shorter than a binary glTF 1.0 header";
  if (u32(8) != b.size()) {
    return "its header says " + std::to_string(u32(8)) + " bytes, the file has " + std::to_string(b.size());
  }
  if (u32(12) > b.size() - 20) return "its JSON reaches past the end of the file";
  // The body starts at the next multiple of 4 (the JSON padded with spaces to it).
  if ((uint64_t{u32(12)} + 3) / 4 * 4 > b.size() - 20) return "its JSON is not padded to a multiple of 4 bytes";
  if (u32(16) != 0) return "its content is not JSON (format " + std::to_string(u32(16)) + ")";
  return {};
}

// The JSON text of a glTF file: the whole of a .gltf, the first chunk of a .glb (whose header
// glbProblem has checked).
std::string_view jsonText(const std::vector<unsigned char>& bytes, bool binary) {
  uint32_t size = static_cast<uint32_t>(bytes.size());
  if (binary) std::memcpy(&size, bytes.data() + 12, 4);
  return {reinterpret_cast<const char*>(bytes.data()) + (binary ? 20 : 0), size};
}

// What a data: URI says its bytes are: between "data:" and ';' or ',', at most 64 characters.
std::string mediaTypeOf(const std::string& uri) {
  return uri.substr(5, std::min(uri.find_first_of(";,"), size_t{69}) - 5);
}

// The names in a glTF's "extensionsRequired", read from its JSON text (empty when the text is
// not JSON or has none).
std::vector<std::string> requiredExtensions(std::string_view text) {
  const nlohmann::json json = nlohmann::json::parse(text, nullptr, false);
  std::vector<std::string> names;
  if (!json.is_object()) return names;
  const auto required = json.find("extensionsRequired");
  if (required == json.end() || !required->is_array()) return names;
  for (const nlohmann::json& name : *required) {
    if (name.is_string()) names.push_back(name.get<std::string>());
  }
  return names;
}

// The image tinygltf names in `error` as one whose data: URI it could not decode (a media type
// it does not know, such as image/webp or image/ktx2, or no data), or -1.
int undecodedImage(const std::string& error) {
  static const std::string kSays = "Failed to decode 'uri' for image[";
  const size_t at = error.find(kSays);
  if (at == std::string::npos) return -1;
  const char* digits = error.c_str() + at + kSays.size();
  char* end = nullptr;
  const long index = std::strtol(digits, &end, 10);
  return end != digits && *end == ']' && index >= 0 && index < (1L << 30) ? static_cast<int>(index) : -1;
}

// The glTF file `bytes` (the text of a .gltf, or a .glb) with image `index`'s URI replaced by
// "data:", which names no file and no data: what tinygltf then keeps as an image without
// bytes, so that one image it cannot decode does not refuse the whole file. `mediaType` is
// set to the URI's (what it said between "data:" and ';' or ','). Nothing when the JSON does
// not parse or has no such image with a data: URI.
std::optional<std::vector<unsigned char>> withoutImageUri(const std::vector<unsigned char>& bytes,
                                                          bool binary, int index,
                                                          std::string& mediaType) {
  const std::string_view original = jsonText(bytes, binary);
  nlohmann::json json = nlohmann::json::parse(original, nullptr, false);
  if (!json.is_object() || !json.contains("images") || !json["images"].is_array() ||
      static_cast<size_t>(index) >= json["images"].size()) {
    return std::nullopt;
  }
  nlohmann::json& image = json["images"][static_cast<size_t>(index)];
  if (!image.is_object() || !image.contains("uri") || !image["uri"].is_string()) return std::nullopt;
  const std::string uri = image["uri"].get<std::string>();
  if (uri.rfind("data:", 0) != 0) return std::nullopt;
  mediaType = mediaTypeOf(uri);
  image["uri"] = "data:";
  std::string text = json.dump();
  if (!binary) return std::vector<unsigned char>(text.begin(), text.end());
  while (text.size() % 4 != 0) text += ' ';  // a chunk's length is a multiple of 4
  const size_t rest = 20 + original.size();
  std::vector<unsigned char> out(bytes.begin(), bytes.begin() + 12);
  const auto u32 = [&out](size_t at, uint64_t value) {
    const auto v = static_cast<uint32_t>(value);
    std::memcpy(out.data() + at, &v, 4);
  };
  out.resize(20);
  u32(8, 20 + text.size() + (bytes.size() - rest));
  u32(12, text.size());
  u32(16, 0x4E4F534Au);  // "JSON"
  out.insert(out.end(), text.begin(), text.end());
  out.insert(out.end(), bytes.begin() + static_cast<std::ptrdiff_t>(rest), bytes.end());
  if (out.size() > std::numeric_limits<uint32_t>::max()) return std::nullopt;
  return out;
}

// Whether JSON text nests arrays and objects deeper than `limit` (strings skipped).
bool nestsDeeperThan(const unsigned char* text, size_t size, int limit) {
  int depth = 0;
  bool inString = false;
  for (size_t i = 0; i < size; ++i) {
    const unsigned char c = text[i];
    if (inString) {
      if (c == '\\') ++i;
      else if (c == '"') inString = false;
    } else if (c == '"') {
      inString = true;
    } else if (c == '[' || c == '{') {
      if (++depth > limit) return true;
    } else if (c == ']' || c == '}') {
      --depth;
    }
  }
  return false;
}

// Thrown by GltfReader when the file is glTF 1.0, which tinygltf does not read: readGltfFile
// then reads it with assimp, from `text` when that is not empty.
struct GltfVersionOne {
  std::string text;
};

// Whether an asset.version names glTF 1.0: "1", "1.0", "1.0.1" and the like.
bool versionOne(const std::string& version) {
  return version == "1" || version.rfind("1.", 0) == 0;
}

// Throws GltfVersionOne when the JSON text of a glTF file is glTF 1.0: its asset.version says
// so (a string, or the number 1 as some 1.0 exporters wrote it) and its collections are not
// 2.0's arrays (a 2.0 file that says 1.0 is read as what it is), or, with no version, its
// collections are 1.0's objects keyed by id. assimp reads 1.0 only with its version written:
// an unversioned file is given to it with "asset":{"version":"1.0"} added. The text has been
// checked against deep nesting (nestsDeeperThan) before it is parsed.
void throwIfVersionOne(std::string_view text) {
  nlohmann::json json = nlohmann::json::parse(text, nullptr, false);
  if (!json.is_object()) return;
  bool keyed = false, listed = false;
  for (const char* key : {"accessors", "bufferViews", "buffers", "meshes", "nodes", "materials", "scenes"}) {
    const auto found = json.find(key);
    if (found == json.end()) continue;
    keyed = keyed || found->is_object();
    listed = listed || found->is_array();
  }
  if (listed && !keyed) return;
  const auto asset = json.find("asset");
  if (asset != json.end() && asset->is_object()) {
    const auto version = asset->find("version");
    if (version != asset->end()) {
      if (version->is_string() ? versionOne(version->get<std::string>())
                               : version->is_number() && version->get<double>() >= 1 &&
                                     version->get<double>() < 2) {
        throw GltfVersionOne{};
      }
      return;
    }
  }
  if (keyed) {
    if (!json["asset"].is_object()) json["asset"] = nlohmann::json::object();
    json["asset"]["version"] = "1.0";
    throw GltfVersionOne{json.dump()};
  }
}

// --- the reader ------------------------------------------------------------------------------

double number(const tinygltf::Value& v, const std::string& key, double fallback) {
  if (!v.IsObject() || !v.Has(key) || !v.Get(key).IsNumber()) return fallback;
  return v.Get(key).GetNumberAsDouble();
}
const tinygltf::Value* extension(const tinygltf::ExtensionMap& map, const std::string& name) {
  const auto found = map.find(name);
  return found == map.end() ? nullptr : &found->second;
}
Vec3 vec3(const std::vector<double>& v, const Vec3& fallback) {
  return v.size() >= 3 ? Vec3(v[0], v[1], v[2]) : fallback;
}
// An extension's array of three numbers (a colour); `fallback` when it is not one.
Vec3 vec3(const tinygltf::Value& v, const std::string& key, const Vec3& fallback) {
  if (!v.IsObject() || !v.Has(key)) return fallback;
  const tinygltf::Value& a = v.Get(key);
  if (!a.IsArray() || a.ArrayLen() != 3) return fallback;
  for (int i = 0; i < 3; ++i) {
    if (!a.Get(i).IsNumber()) return fallback;
  }
  return {a.Get(0).GetNumberAsDouble(), a.Get(1).GetNumberAsDouble(), a.Get(2).GetNumberAsDouble()};
}
double degrees(double radians) { return radians * 180.0 / std::numbers::pi; }

class GltfReader {
 public:
  GltfReader(const std::string& path, const ModelReadOptions& options)
      : path_(path), budget_(options.textureBudgetBytes) {
    notes_.file = path;
    notes_.strict = options.strict;
  }

  ImportedModel read() {
    load();
    out_.format = "glTF 2.0";
    std::vector<int> roots;
    if (!model_.scenes.empty()) {
      const size_t scene = model_.defaultScene >= 0 &&
                                   static_cast<size_t>(model_.defaultScene) < model_.scenes.size()
                               ? static_cast<size_t>(model_.defaultScene)
                               : 0;
      roots = model_.scenes[scene].nodes;
    } else {  // no scene: every node that is no node's child
      std::vector<char> child(model_.nodes.size(), 0);
      for (const auto& n : model_.nodes) {
        for (const int c : n.children) {
          if (c >= 0 && static_cast<size_t>(c) < child.size()) child[static_cast<size_t>(c)] = 1;
        }
      }
      for (size_t i = 0; i < child.size(); ++i) {
        if (!child[i]) roots.push_back(static_cast<int>(i));
      }
    }
    onPath_.assign(model_.nodes.size(), 0);
    visited_.assign(model_.nodes.size(), 0);
    GltfAnimations animations(model_, notes_);
    rigging_ = animations.any();
    for (const int root : roots) visit(root, Transform::identity(), 0, -1);
    buildRig(animations);
    animations.warn(out_.warnings);
    notes_.warn(out_.warnings);
    if (out_.objects.empty()) {
      throw ModelFileError(noTrianglesMessage(
          path_, model_.meshes.empty() ? " (it holds no meshes)" : "", out_.warnings));
    }
    return std::move(out_);
  }

 private:
  void load() {
    tinygltf::TinyGLTF loader;
    loader.SetImageLoader(&keepEncoded, &encoded_);
    tinygltf::FsCallbacks files{};
    files.FileExists = &fileExists;
    files.ExpandFilePath = &expandNothing;
    files.ReadWholeFile = &readBoundedFile;
    files.WriteWholeFile = &writeNothing;
    files.user_data = &bytesLeft_;
    loader.SetFsCallbacks(files);
    std::string error, warning;
    std::vector<unsigned char> head;
    std::string headError;
    if (!readBoundedFile(&head, &headError, path_, &bytesLeft_)) {
      throw ModelFileError("model file " + headError.substr(0, headError.size() - 1));
    }
    const bool binary = head.size() >= 4 && std::memcmp(head.data(), "glTF", 4) == 0;
    // A binary glTF 1.0 (KHR_binary_glTF) says version 1 after its magic.
    if (binary && head.size() >= 8 && head[4] == 1 && head[5] == 0 && head[6] == 0 && head[7] == 0) {
      if (const std::string why = glbOneProblem(head); !why.empty()) {
        throw ModelFileError("model file \"" + path_ + "\" is not a binary glTF 1.0 file: " + why);
      }
      throw GltfVersionOne{};
    }
    if (binary) {
      if (const std::string why = glbProblem(head); !why.empty()) {
        throw ModelFileError("model file \"" + path_ + "\" is not a binary glTF file: " + why);
      }
    }
    const std::string_view json = jsonText(head, binary);
    if (nestsDeeperThan(reinterpret_cast<const unsigned char*>(json.data()), json.size(), kMaxJsonDepth)) {
      throw ModelFileError("model file \"" + path_ + "\" nests its JSON deeper than " +
                           std::to_string(kMaxJsonDepth) + " levels: no glTF does");
    }
    const std::string base = fs::path(path_).parent_path().string();
    if (head.size() > std::numeric_limits<unsigned int>::max()) {
      throw ModelFileError("model file \"" + path_ + "\" is too large");
    }
    const uintmax_t bytesLeft = bytesLeft_;
    auto parse = [&] {
      return binary ? loader.LoadBinaryFromMemory(&model_, &error, &warning, head.data(),
                                                  static_cast<unsigned int>(head.size()), base)
                    : loader.LoadASCIIFromString(&model_, &error, &warning,
                                                 reinterpret_cast<const char*>(head.data()),
                                                 static_cast<unsigned int>(head.size()), base);
    };
    bool ok = parse();
    // An image whose data: URI tinygltf cannot decode fails the whole file there: read again
    // without that URI, the image then missing (a warning, or with --strict an error), up to
    // a few such images.
    for (int image = undecodedImage(error); !ok && image >= 0 && undecodable_.size() < 64 &&
                                            !undecodable_.count(image);
         image = undecodedImage(error)) {
      std::string mediaType;
      auto rewritten = withoutImageUri(head, binary, image, mediaType);
      if (!rewritten || rewritten->size() > std::numeric_limits<unsigned int>::max()) break;
      undecodable_[image] = mediaType;
      head = std::move(*rewritten);
      model_ = tinygltf::Model();
      encoded_ = EncodedImages();
      bytesLeft_ = bytesLeft;
      error.clear();
      warning.clear();
      ok = parse();
    }
    static const std::set<std::string> kUnderstood = {
        "KHR_lights_punctual",       "KHR_materials_emissive_strength", "KHR_materials_ior",
        "KHR_materials_transmission", "KHR_materials_unlit",            "KHR_materials_volume",
        "KHR_texture_transform",     "KHR_mesh_quantization",           "KHR_materials_pbrSpecularGlossiness",
        "KHR_materials_specular", "KHR_materials_clearcoat"};
    if (!binary && (!ok || versionOne(model_.asset.version))) throwIfVersionOne(jsonText(head, binary));
    if (!ok) {
      // A file that needs an extension PRT does not read (Draco's compressed meshes, whose
      // accessors have no buffer views) fails in tinygltf first: name the extension.
      // (The JSON as last read: a read without an image's URI rewrote it.)
      for (const std::string& name : requiredExtensions(jsonText(head, binary))) {
        if (!kUnderstood.count(name)) {
          throw ModelFileError("model file \"" + path_ + "\" requires the glTF extension " +
                               name + ", which PRT does not read");
        }
      }
      while (!error.empty() && (error.back() == '\n' || error.back() == ' ')) error.pop_back();
      std::replace(error.begin(), error.end(), '\n', ';');
      throw ModelFileError("model file \"" + path_ + "\" could not be read as glTF: " +
                           (error.empty() ? "malformed" : error));
    }
    for (const std::string& name : model_.extensionsRequired) {
      if (!kUnderstood.count(name)) {
        throw ModelFileError("model file \"" + path_ + "\" requires the glTF extension " + name +
                             ", which PRT does not read");
      }
    }
    for (const std::string& name : model_.extensionsUsed) {
      if (!kUnderstood.count(name)) notes_.notUsed.insert("the extension " + name);
    }
  }

  // `parentRig`: the parent's node in out_.rig while the file is rigged, else -1.
  void visit(int index, const Transform& parent, int depth, int32_t parentRig) {
    if (index < 0 || static_cast<size_t>(index) >= model_.nodes.size()) {
      throw ModelFileError("model file \"" + path_ + "\": node " + std::to_string(index) +
                           " does not exist");
    }
    const size_t i = static_cast<size_t>(index);
    if (onPath_[i]) {
      throw ModelFileError("model file \"" + path_ + "\": node " + std::to_string(index) +
                           " is its own ancestor (a cycle in the node tree)");
    }
    // glTF's nodes form trees: a node met twice has two parents (or is a root and a child),
    // and a file sharing nodes so could make the walk take exponential time.
    if (visited_[i]) {
      throw ModelFileError("model file \"" + path_ + "\": node " + std::to_string(index) +
                           " has more than one parent (glTF's nodes form trees)");
    }
    visited_[i] = 1;
    if (depth > kMaxModelNodeDepth) {
      throw ModelFileError("model file \"" + path_ + "\": the node tree is deeper than " +
                           std::to_string(kMaxModelNodeDepth));
    }
    const tinygltf::Node& node = model_.nodes[i];
    const Transform world = parent * localTransform(node);
    if (!world.isUsable()) {
      ++notes_.hiddenNodes;  // a zero scale hides a subtree (animations do that); nothing to trace
      return;
    }
    onPath_[i] = 1;
    int32_t rigNode = -1;
    const size_t objects = out_.objects.size(), lights = out_.lights.size(),
                 cameras = out_.cameras.size();
    if (rigging_) {
      rigNode = static_cast<int32_t>(out_.rig.nodes.size());
      RigNode r = rigNodeOf(node);
      r.parent = parentRig;
      out_.rig.nodes.push_back(r);
      rigGltfNodes_.push_back(index);
    }
    if (node.mesh >= 0) placeMesh(node, world);
    if (node.skin >= 0) ++notes_.skinned;
    if (node.camera >= 0) addCamera(node, world);
    if (const tinygltf::Value* light = extension(node.extensions, "KHR_lights_punctual")) {
      if (light->IsObject() && light->Has("light") && light->Get("light").IsInt()) {
        addLight(light->Get("light").GetNumberAsInt(), world);
      }
    }
    if (rigging_) bindToNode(rigNode, objects, lights, cameras);
    for (const int child : node.children) visit(child, world, depth + 1, rigNode);
    onPath_[i] = 0;
  }

  // What this node placed (out_'s objects, lights and cameras from those counts on), bound to
  // its rig node in the node's own coordinates, where glTF puts lights and cameras at the
  // origin looking down -z, up +y.
  void bindToNode(int32_t rigNode, size_t objects, size_t lights, size_t cameras) {
    ModelRig& rig = out_.rig;
    for (size_t o = objects; o < out_.objects.size(); ++o) {
      rig.objectNodes.push_back(rigNode);
      rig.objectLocal.push_back(Transform::identity());  // glTF places meshes by nodes alone
    }
    for (size_t l = lights; l < out_.lights.size(); ++l) {
      Light local = out_.lights[l];
      std::visit(
          [](auto& shape) {
            using T = std::decay_t<decltype(shape)>;
            if constexpr (std::is_same_v<T, PointLight>) shape.position = {0, 0, 0};
            if constexpr (std::is_same_v<T, SpotLight>) shape.position = {0, 0, 0}, shape.direction = {0, 0, -1};
            if constexpr (std::is_same_v<T, DirectionalLight>) shape.direction = {0, 0, -1};
          },
          local.shape);
      rig.lightNodes.push_back(rigNode);
      rig.lightLocal.push_back(local);
    }
    for (size_t c = cameras; c < out_.cameras.size(); ++c) {
      const Camera& rest = out_.cameras[c].camera;
      Camera local;
      local.eye = {0, 0, 0};
      local.lookAt = {0, 0, -1};
      local.up = {0, 1, 0};
      local.fovDegrees = rest.fovDegrees;
      // The node's scale at rest sizes an orthographic view (as read); an animated one does not.
      local.orthoHeight = rest.orthoHeight;
      rig.cameraNodes.push_back(rigNode);
      rig.cameraLocal.push_back(local);
    }
  }

  // The rig once the tree is walked: only the nodes with something placed at or below them,
  // with the curves that move them; nothing when no curve moves any of those.
  void buildRig(GltfAnimations& animations) {
    ModelRig& rig = out_.rig;
    if (!rigging_) return;
    std::vector<char> keep(rig.nodes.size(), 0);
    const auto mark = [&](int32_t n) {
      while (n >= 0 && !keep[static_cast<size_t>(n)]) {
        keep[static_cast<size_t>(n)] = 1;
        n = rig.nodes[static_cast<size_t>(n)].parent;
      }
    };
    for (const auto* bound : {&rig.objectNodes, &rig.lightNodes, &rig.cameraNodes}) {
      for (const int32_t n : *bound) mark(n);
    }
    std::vector<int32_t> moved(rig.nodes.size(), -1);
    std::vector<RigNode> nodes;
    std::vector<int> gltfNodes;
    for (size_t n = 0; n < rig.nodes.size(); ++n) {
      if (!keep[n]) continue;
      moved[n] = static_cast<int32_t>(nodes.size());
      RigNode r = rig.nodes[n];
      if (r.parent >= 0) r.parent = moved[static_cast<size_t>(r.parent)];  // parents come first
      nodes.push_back(r);
      gltfNodes.push_back(rigGltfNodes_[n]);
    }
    for (auto* bound : {&rig.objectNodes, &rig.lightNodes, &rig.cameraNodes}) {
      for (int32_t& n : *bound) n = n >= 0 ? moved[static_cast<size_t>(n)] : -1;
    }
    rig.nodes = std::move(nodes);
    const std::vector<std::array<int32_t, 3>> curves = animations.read(gltfNodes, rig.curves);
    for (size_t n = 0; n < rig.nodes.size(); ++n) {
      rig.nodes[n].translationCurve = curves[n][0];
      rig.nodes[n].rotationCurve = curves[n][1];
      rig.nodes[n].scaleCurve = curves[n][2];
    }
    if (rig.curves.empty()) {
      rig = {};
      return;
    }
    for (const Curve& c : rig.curves) rig.duration = std::max(rig.duration, c.times.back());
  }

  static RigNode rigNodeOf(const tinygltf::Node& node) {
    RigNode r;
    if (node.matrix.size() == 16) {
      r.hasMatrix = true;
      r.matrix = Transform::fromColumnMajor(node.matrix.data());
      return r;
    }
    if (node.translation.size() == 3) {
      r.translation = {node.translation[0], node.translation[1], node.translation[2]};
    }
    if (node.rotation.size() == 4) {
      r.rotation = {node.rotation[0], node.rotation[1], node.rotation[2], node.rotation[3]};
    }
    if (node.scale.size() == 3) r.scale = {node.scale[0], node.scale[1], node.scale[2]};
    return r;
  }

  // The same function as a rig node's at any time (animation.h), so that a node at rest gives
  // the same doubles read here and played.
  static Transform localTransform(const tinygltf::Node& node) {
    const RigNode r = rigNodeOf(node);
    return r.hasMatrix ? r.matrix : nodeTransform(r.translation, r.rotation, r.scale);
  }

  void placeMesh(const tinygltf::Node& node, const Transform& world) {
    if (static_cast<size_t>(node.mesh) >= model_.meshes.size()) {
      throw ModelFileError("model file \"" + path_ + "\": mesh " + std::to_string(node.mesh) +
                           " does not exist");
    }
    const tinygltf::Mesh& mesh = model_.meshes[static_cast<size_t>(node.mesh)];
    // Morph target weights: the node's, else the mesh's (glTF 2.0, 3.7.2.2), else none.
    const std::vector<double>& weights = !node.weights.empty() ? node.weights : mesh.weights;
    for (size_t p = 0; p < mesh.primitives.size(); ++p) {
      const tinygltf::Primitive& primitive = mesh.primitives[p];
      std::shared_ptr<const TriangleMesh> triangles =
          primitiveMesh(node.mesh, p, primitive, usedWeights(primitive, weights));
      if (triangles == nullptr) continue;
      if (out_.objects.size() >= kMaxModelObjects) {
        throw ModelFileError("model file \"" + path_ + "\" places meshes more than " +
                             std::to_string(kMaxModelObjects) + " times");
      }
      out_.objects.push_back({InstanceShape{std::move(triangles), world}, material(primitive.material)});
    }
  }

  // The weights of a primitive's morph targets that change its shape: those the file gives,
  // as many as there are targets, trailing zeros left out (so none at all for the shape as
  // stored, and never longer than the weights the JSON spells out).
  static std::vector<double> usedWeights(const tinygltf::Primitive& primitive,
                                         const std::vector<double>& weights) {
    size_t used = std::min(weights.size(), primitive.targets.size());
    while (used > 0 && weights[used - 1] == 0) --used;
    return {weights.begin(), weights.begin() + static_cast<std::ptrdiff_t>(used)};
  }
  // What a copy of the primitive holds, as its accessors declare: vertices and indices.
  size_t copiedElements(const tinygltf::Primitive& primitive) const {
    auto countOf = [&](int accessor) -> size_t {
      if (accessor < 0 || static_cast<size_t>(accessor) >= model_.accessors.size()) return 0;
      return model_.accessors[static_cast<size_t>(accessor)].count;
    };
    const auto position = primitive.attributes.find("POSITION");
    const size_t vertices = position == primitive.attributes.end() ? 0 : countOf(position->second);
    return vertices + countOf(primitive.indices);
  }

  // The mesh of one primitive with one set of morph weights, read once however many nodes
  // use it; null if it has nothing to trace (points, lines, only degenerate triangles, an
  // accessor PRT cannot read).
  std::shared_ptr<const TriangleMesh> primitiveMesh(int mesh, size_t p,
                                                    const tinygltf::Primitive& primitive,
                                                    std::vector<double> weights) {
    auto key = std::make_tuple(mesh, p, std::move(weights));
    if (const auto found = meshes_.find(key); found != meshes_.end()) return found->second;
    if (!std::get<2>(key).empty()) {
      // Each distinct set of weights is a mesh of its own: past a budget of vertices and
      // indices (and weights, which the key holds), the rest are rendered in their stored
      // shape (a warning), so a file of many nodes cannot make PRT copy a large mesh for each.
      const size_t cost = copiedElements(primitive) + std::get<2>(key).size();
      if (cost > kMorphedCopyBudget - morphedCopies_) {
        ++notes_.morphsOverBudget;
        return primitiveMesh(mesh, p, primitive, {});
      }
      morphedCopies_ += cost;
    }
    const std::vector<double>& w = std::get<2>(key);
    std::shared_ptr<const TriangleMesh> result;
    try {
      result = readPrimitive(primitive, w,
                             "mesh " + std::to_string(mesh) + " primitive " + std::to_string(p));
    } catch (const ModelFileError& e) {
      out_.warnings.push_back("model file \"" + path_ + "\": " + e.what() + "; skipped");
    }
    meshes_[std::move(key)] = result;
    return result;
  }

  // Adds each morph target's POSITION and NORMAL displacements, times its weight (glTF 2.0,
  // 3.7.2.2), to the mesh's (cleanMesh makes the normals unit again). A target that cannot be
  // read leaves the mesh in its stored shape, with a warning.
  void applyMorphTargets(const tinygltf::Primitive& primitive, const std::vector<double>& weights,
                         RawMesh& raw, const std::string& what) {
    if (weights.empty()) return;
    // Moved on copies: a target that fails leaves the stored shape whole.
    std::vector<Vec3> positions = raw.positions, normals = raw.normals;
    try {
      for (size_t k = 0; k < weights.size(); ++k) {
        if (weights[k] != 0) {
          addMorphTarget(primitive.targets[k], k, weights[k], positions, normals, what);
        }
      }
    } catch (const ModelFileError& e) {
      out_.warnings.push_back("model file \"" + path_ + "\": " + e.what() +
                              "; rendered in its stored shape");
      return;
    }
    raw.positions = std::move(positions);
    raw.normals = std::move(normals);
  }
  void addMorphTarget(const std::map<std::string, int>& target, size_t k, double w,
                      std::vector<Vec3>& positions, std::vector<Vec3>& normals,
                      const std::string& what) {
    const size_t n = positions.size();
    auto add = [&](const std::string& name, std::vector<Vec3>& to) {
      const auto found = target.find(name);
      if (found == target.end()) return;
      const std::string which = what + " morph target " + std::to_string(k) + " " + name;
      // Its count must be the mesh's, which bounds what it costs: no cap on zeros.
      const GltfAccessor d(model_, found->second, which, GltfAccessor::kMaxElements);
      if (d.count() != n) throw ModelFileError(which + " has a count unlike POSITION's");
      if (d.components() != 3) throw ModelFileError(which + " is not 3-vectors");
      // A few bytes of JSON can name one target thousands of times: the vertices moved in
      // all are bounded, as the copies are. Sparse values over zeros move only those named.
      const std::vector<uint32_t>* only = d.onlySparse() ? &d.sparseIndices() : nullptr;
      const size_t moves = only != nullptr ? only->size() : d.hasData() ? n : 0;
      if (moves > kMorphMoves - morphMoves_) {
        throw ModelFileError(which + " would take the vertices morph targets move past the " +
                             std::to_string(kMorphMoves) + " PRT moves for one file");
      }
      morphMoves_ += moves;
      auto move = [&](size_t i) { to[i] += w * Vec3(d.get(i, 0), d.get(i, 1), d.get(i, 2)); };
      if (only != nullptr) {
        for (const uint32_t i : *only) move(i);
      } else if (d.hasData()) {
        for (size_t i = 0; i < n; ++i) move(i);
      }
    };
    add("POSITION", positions);
    if (!normals.empty()) add("NORMAL", normals);
  }

  std::shared_ptr<const TriangleMesh> readPrimitive(const tinygltf::Primitive& primitive,
                                                    const std::vector<double>& weights,
                                                    const std::string& what) {
    const int mode = primitive.mode < 0 ? TINYGLTF_MODE_TRIANGLES : primitive.mode;
    if (mode != TINYGLTF_MODE_TRIANGLES && mode != TINYGLTF_MODE_TRIANGLE_STRIP &&
        mode != TINYGLTF_MODE_TRIANGLE_FAN) {
      ++notes_.skips.notTriangles;
      return nullptr;
    }
    const auto position = primitive.attributes.find("POSITION");
    if (position == primitive.attributes.end()) throw ModelFileError(what + " has no POSITION");
    const GltfAccessor positions(model_, position->second, what + " POSITION");
    if (positions.components() != 3) throw ModelFileError(what + ": POSITION is not 3-vectors");
    // Without a buffer view an accessor is all zeros: every triangle would be a point, and its
    // count, which no buffer bounds, could ask for any amount of memory.
    if (!positions.hasData()) throw ModelFileError(what + ": POSITION has no data (all zeros)");
    RawMesh raw;
    const size_t n = positions.count();
    raw.positions.resize(n);
    for (size_t i = 0; i < n; ++i) {
      raw.positions[i] = {positions.get(i, 0), positions.get(i, 1), positions.get(i, 2)};
    }
    auto attribute = [&](const std::string& name) -> std::optional<GltfAccessor> {
      const auto found = primitive.attributes.find(name);
      if (found == primitive.attributes.end()) return std::nullopt;
      // Its count must be POSITION's, which bounds what it costs: no cap on zeros.
      GltfAccessor a(model_, found->second, what + " " + name, GltfAccessor::kMaxElements);
      if (a.count() != n) throw ModelFileError(what + ": " + name + " has a count unlike POSITION's");
      if (!a.hasData()) return std::nullopt;  // all zeros: as good as none
      return a;
    };
    if (const auto normals = attribute("NORMAL"); normals && normals->components() == 3) {
      raw.normals.resize(n);
      for (size_t i = 0; i < n; ++i) {
        raw.normals[i] = {normals->get(i, 0), normals->get(i, 1), normals->get(i, 2)};
      }
    }
    const int uvSet = uvSetOf(primitive.material);
    if (const auto uvs = attribute("TEXCOORD_" + std::to_string(uvSet)); uvs && uvs->components() == 2) {
      raw.uvs.resize(n);
      for (size_t i = 0; i < n; ++i) {
        raw.uvs[i] = {static_cast<float>(uvs->get(i, 0)), static_cast<float>(uvs->get(i, 1))};
      }
    }
    // Tangents matter only to a normal map: the file's when it gives them (3.7.2.1: xyz unit,
    // w the handedness), computed below otherwise.
    const tinygltf::Material* surface = materialAt(primitive.material);
    const bool normalMapped = surface != nullptr && surface->normalTexture.index >= 0 && !raw.uvs.empty();
    if (const auto tangents = attribute("TANGENT"); normalMapped && tangents && tangents->components() == 4) {
      raw.tangents.resize(n);
      for (size_t i = 0; i < n; ++i) {
        raw.tangents[i] = {tangents->get(i, 0), tangents->get(i, 1), tangents->get(i, 2), tangents->get(i, 3)};
      }
    }
    if (const auto colors = attribute("COLOR_0");
        colors && (colors->components() == 3 || colors->components() == 4)) {
      raw.colors.resize(n);
      for (size_t i = 0; i < n; ++i) {
        raw.colors[i] = {static_cast<float>(colors->get(i, 0)), static_cast<float>(colors->get(i, 1)),
                         static_cast<float>(colors->get(i, 2))};
      }
    }
    applyMorphTargets(primitive, weights, raw, what);
    std::vector<uint64_t> order;
    if (primitive.indices >= 0) {
      const GltfAccessor indices(model_, primitive.indices, what + " indices");
      if (!indices.isIndexType()) throw ModelFileError(what + ": indices are not unsigned integers");
      if (!indices.hasData()) throw ModelFileError(what + ": its indices have no data (all zeros)");
      order.resize(indices.count());
      for (size_t i = 0; i < order.size(); ++i) order[i] = indices.index(i);
    } else {
      order.resize(n);
      for (size_t i = 0; i < n; ++i) order[i] = i;
    }
    auto add = [&](uint64_t a, uint64_t b, uint64_t c) {
      if (a >= n || b >= n || c >= n) {
        ++notes_.skips.outOfRange;
        return;
      }
      raw.triangles.push_back({static_cast<uint32_t>(a), static_cast<uint32_t>(b),
                               static_cast<uint32_t>(c)});
    };
    if (mode == TINYGLTF_MODE_TRIANGLES) {
      for (size_t i = 0; i + 2 < order.size(); i += 3) add(order[i], order[i + 1], order[i + 2]);
    } else if (mode == TINYGLTF_MODE_TRIANGLE_STRIP) {
      for (size_t i = 0; i + 2 < order.size(); ++i) {
        if (i % 2 == 0) add(order[i], order[i + 1], order[i + 2]);
        else add(order[i + 1], order[i], order[i + 2]);
      }
    } else {
      for (size_t i = 1; i + 1 < order.size(); ++i) add(order[0], order[i], order[i + 1]);
    }
    std::shared_ptr<TriangleMesh> mesh = cleanMesh(std::move(raw), notes_.skips);
    if (mesh != nullptr && normalMapped && mesh->tangents.empty()) mesh->tangents = computeTangents(*mesh);
    return mesh;
  }

  const tinygltf::Material* materialAt(int index) const {
    if (index < 0 || static_cast<size_t>(index) >= model_.materials.size()) return nullptr;
    return &model_.materials[static_cast<size_t>(index)];
  }

  // The texture coordinate set the material's textures read (PRT reads one per primitive).
  int uvSetOf(int index) const {
    const tinygltf::Material* m = materialAt(index);
    if (m == nullptr) return 0;
    // The first of the textures that the material has, in this order.
    const tinygltf::TextureInfo& base = m->pbrMetallicRoughness.baseColorTexture;
    const tinygltf::TextureInfo& data = m->pbrMetallicRoughness.metallicRoughnessTexture;
    int set = 0;
    const tinygltf::ExtensionMap* extensions = nullptr;
    for (const tinygltf::TextureInfo* info : {&base, &m->emissiveTexture, &data}) {
      if (info->index >= 0) {
        set = info->texCoord, extensions = &info->extensions;
        break;
      }
    }
    if (extensions == nullptr && m->normalTexture.index >= 0) {
      set = m->normalTexture.texCoord, extensions = &m->normalTexture.extensions;
    }
    if (extensions == nullptr) return 0;
    if (const tinygltf::Value* t = extension(*extensions, "KHR_texture_transform")) {
      const double given = number(*t, "texCoord", set);
      set = given >= 0 && given <= 7 ? static_cast<int>(given) : 0;
    }
    return std::clamp(set, 0, 7);
  }

  Material material(int index) {
    if (const auto found = materials_.find(index); found != materials_.end()) return found->second;
    const tinygltf::Material* m = materialAt(index);
    PbrMaterialInputs in;
    if (m == nullptr) {  // no material: grey and rough, as Blender's default, not glTF's metal
      in.baseColor = Color(0.8);
      in.metallic = 0;
      in.roughness = 0.5;
    } else {
      const std::string name = m->name.empty() ? "material " + std::to_string(index) : "'" + m->name + "'";
      const auto& pbr = m->pbrMetallicRoughness;
      if (pbr.baseColorFactor.size() == 4) {
        in.baseColor = {pbr.baseColorFactor[0], pbr.baseColorFactor[1], pbr.baseColorFactor[2]};
        in.alpha = pbr.baseColorFactor[3];
      }
      in.baseColorTexture = textureRef(pbr.baseColorTexture, name);
      in.metallic = pbr.metallicFactor;
      in.roughness = pbr.roughnessFactor;
      in.metallicRoughnessTexture = textureRef(pbr.metallicRoughnessTexture, name, true);
      in.normalTexture = textureRef(m->normalTexture, name, true);
      in.normalScale = m->normalTexture.scale;
      in.emissive = vec3(m->emissiveFactor, Color());
      in.emissiveTexture = textureRef(m->emissiveTexture, name);
      if (m->alphaMode == "MASK") in.alphaMode = PbrMaterialInputs::AlphaMode::mask;
      if (m->alphaMode == "BLEND") in.alphaMode = PbrMaterialInputs::AlphaMode::blend;
      in.alphaCutoff = m->alphaCutoff;
      if (const auto* e = extension(m->extensions, "KHR_materials_emissive_strength")) {
        in.emissiveStrength = number(*e, "emissiveStrength", 1);
      }
      if (const auto* e = extension(m->extensions, "KHR_materials_transmission")) {
        in.transmission = number(*e, "transmissionFactor", 0);
        in.transmissionTexture = textureRef(textureInfo(*e, "transmissionTexture"), name, true);
      }
      if (const auto* e = extension(m->extensions, "KHR_materials_ior")) in.ior = number(*e, "ior", 1.5);
      if (const auto* e = extension(m->extensions, "KHR_materials_volume")) {
        in.volume = true;
        in.thickness = number(*e, "thicknessFactor", 0);
        in.attenuationColor = vec3(*e, "attenuationColor", Color(1));
        in.attenuationDistance = number(*e, "attenuationDistance", in.attenuationDistance);
      }
      if (const auto* e = extension(m->extensions, "KHR_materials_specular")) {
        in.specular = true;
        in.specularFactor = number(*e, "specularFactor", 1);
        in.specularColorFactor = vec3(*e, "specularColorFactor", Color(1));
        if (e->Has("specularTexture") || e->Has("specularColorTexture")) {
          notes_.notUsed.insert("KHR_materials_specular's textures (" + name + ")");
        }
      }
      if (extension(m->extensions, "KHR_materials_unlit")) in.unlit = true;
      if (const auto* e = extension(m->extensions, "KHR_materials_pbrSpecularGlossiness")) {
        specularGlossiness(*e, in, name);
      }
      if (const auto* e = extension(m->extensions, "KHR_materials_clearcoat")) {
        in.clearcoat = number(*e, "clearcoatFactor", 0);
        in.clearcoatRoughness = number(*e, "clearcoatRoughnessFactor", 0);
        for (const char* texture : {"clearcoatTexture", "clearcoatRoughnessTexture", "clearcoatNormalTexture"}) {
          if (e->Has(texture)) notes_.notUsed.insert(std::string("KHR_materials_clearcoat's ") + texture + " (" + name + ")");
        }
      }
      for (const char* other : {"KHR_materials_sheen",
                                "KHR_materials_iridescence",
                                "KHR_materials_anisotropy"}) {
        if (extension(m->extensions, other)) notes_.notUsed.insert(std::string(other) + " (" + name + ")");
      }
      if (m->occlusionTexture.index >= 0) notes_.notUsed.insert("occlusion maps (" + name + ")");
      if (in.alphaMode != PbrMaterialInputs::AlphaMode::opaque && in.baseColorTexture.texture >= 0 &&
          out_.textures[static_cast<size_t>(in.baseColorTexture.texture)].image->channels % 2 == 0) {
        notes_.notUsed.insert("a texture's alpha, the factor's is (" + name + ")");
      }
      for (const std::string& v : pbrValuesOutOfRange(in)) notes_.outOfRange.insert(name + ": " + v);
    }
    const Material mapped = mapPbrMaterial(in);
    materials_[index] = mapped;
    return mapped;
  }

  void specularGlossiness(const tinygltf::Value& e, PbrMaterialInputs& in, const std::string& name) {
    in.metallic = 0;
    in.metallicRoughnessTexture = {};  // the fallback's, not this model's
    in.roughness = 1 - number(e, "glossinessFactor", 1);
    if (e.Has("diffuseFactor") && e.Get("diffuseFactor").IsArray() &&
        e.Get("diffuseFactor").ArrayLen() == 4) {
      const auto& f = e.Get("diffuseFactor");
      in.baseColor = {f.Get(0).GetNumberAsDouble(), f.Get(1).GetNumberAsDouble(),
                      f.Get(2).GetNumberAsDouble()};
      in.alpha = f.Get(3).GetNumberAsDouble();
    } else {
      in.baseColor = Color(1);
      in.alpha = 1;
    }
    in.baseColorTexture = textureRef(textureInfo(e, "diffuseTexture"), name);
  }

  // A textureInfo held in an extension's object (tinygltf parses only the core ones): its
  // index and its KHR_texture_transform; index -1 when there is none.
  static tinygltf::TextureInfo textureInfo(const tinygltf::Value& e, const char* key) {
    tinygltf::TextureInfo info;
    if (!e.Has(key) || !e.Get(key).IsObject()) return info;
    const tinygltf::Value& v = e.Get(key);
    const double index = number(v, "index", -1);
    info.index = index >= 0 && index < 1e9 ? static_cast<int>(index) : -1;
    if (v.Has("extensions") && v.Get("extensions").IsObject() &&
        v.Get("extensions").Has("KHR_texture_transform")) {
      info.extensions["KHR_texture_transform"] = v.Get("extensions").Get("KHR_texture_transform");
    }
    return info;
  }

  // `linear`: a data texture (metallic-roughness, normals, transmission), read without the
  // sRGB curve.
  template <typename Info>
  TextureRef textureRef(const Info& info, const std::string& material, bool linear = false) {
    TextureRef ref;
    if (info.index < 0) return ref;
    ref.texture = texture(info.index, material, linear);
    if (ref.texture < 0) return {};
    if (const tinygltf::Value* t = extension(info.extensions, "KHR_texture_transform")) {
      double ox = 0, oy = 0, sx = 1, sy = 1;
      if (t->Has("offset") && t->Get("offset").ArrayLen() == 2) {
        ox = t->Get("offset").Get(0).GetNumberAsDouble();
        oy = t->Get("offset").Get(1).GetNumberAsDouble();
      }
      if (t->Has("scale") && t->Get("scale").ArrayLen() == 2) {
        sx = t->Get("scale").Get(0).GetNumberAsDouble();
        sy = t->Get("scale").Get(1).GetNumberAsDouble();
      }
      const double r = number(*t, "rotation", 0);
      const double c = std::cos(r), s = std::sin(r);
      // Translation * rotation * scale, as the extension defines it.
      ref.uv.m = {c * sx, s * sy, ox, -s * sx, c * sy, oy};
      for (const double v : ref.uv.m) {
        if (!std::isfinite(v)) ref.uv = {};
      }
    }
    return ref;
  }

  // The index in out_.textures of glTF texture `index`, or -1 when its image is missing or
  // unreadable (a warning, or an error with --strict).
  int texture(int index, const std::string& material, bool linear) {
    const std::pair<int, bool> key{index, linear};
    if (const auto found = textures_.find(key); found != textures_.end()) return found->second;
    int result = -1;
    if (static_cast<size_t>(index) < model_.textures.size()) {
      const tinygltf::Texture& t = model_.textures[static_cast<size_t>(index)];
      if (auto image = textureImage(t.source, material)) {
        Texture texture;
        texture.image = std::move(image);
        texture.linear = linear;
        if (t.sampler >= 0 && static_cast<size_t>(t.sampler) < model_.samplers.size()) {
          const tinygltf::Sampler& s = model_.samplers[static_cast<size_t>(t.sampler)];
          texture.wrapU = wrapOf(s.wrapS);
          texture.wrapV = wrapOf(s.wrapT);
          texture.nearest = s.magFilter == TINYGLTF_TEXTURE_FILTER_NEAREST;
        }
        result = static_cast<int>(out_.textures.size());
        out_.textures.push_back(std::move(texture));
      }
    } else {
      notes_.problem(out_.warnings, "material " + material + " names texture " + std::to_string(index) +
              ", which does not exist");
    }
    textures_[key] = result;
    return result;
  }

  static TextureWrap wrapOf(int mode) {
    if (mode == TINYGLTF_TEXTURE_WRAP_CLAMP_TO_EDGE) return TextureWrap::clamp;
    if (mode == TINYGLTF_TEXTURE_WRAP_MIRRORED_REPEAT) return TextureWrap::mirror;
    return TextureWrap::repeat;
  }

  std::shared_ptr<const TextureImage> textureImage(int index, const std::string& material) {
    if (const auto found = images_.find(index); found != images_.end()) return found->second;
    std::shared_ptr<const TextureImage> result;
    if (index < 0 || static_cast<size_t>(index) >= model_.images.size()) {
      notes_.problem(out_.warnings, "a texture of material " + material + " names image " + std::to_string(index) +
              ", which does not exist");
    } else {
      const tinygltf::Image& image = model_.images[static_cast<size_t>(index)];
      const std::string name = !image.uri.empty() && image.uri.rfind("data:", 0) != 0
                                   ? image.uri
                                   : fs::path(path_).filename().string() + " image " +
                                         std::to_string(index) +
                                         (image.name.empty() ? "" : " '" + image.name + "'");
      if (const auto view = encoded_.inView.find(index); view != encoded_.inView.end()) {
        const auto [data, size] = viewBytes(view->second);
        if (data == nullptr) {
          notes_.problem(out_.warnings, "texture image " + name + "'s buffer view reaches past its buffer");
        } else {
          try {
            result = decodeTextureImage(data, size, name, budget_);
          } catch (const TextureError& e) {
            notes_.problem(out_.warnings, e.what());
          }
        }
        images_[index] = result;
        return result;
      }
      const auto bytes = encoded_.byImage.find(index);
      if (bytes == encoded_.byImage.end()) {
        // Not where the URI says: found as the other readers find textures (an absolute or
        // file:// path, backslashes, a drive letter, another letter case, beside the model or
        // in its textures/ folder).
        if (image.uri.rfind("data:", 0) == 0) {
          // One tinygltf could not decode (kept as a file name), or whose URI it was read
          // without (undecodable_).
          const auto dropped = undecodable_.find(index);
          const std::string type = dropped != undecodable_.end()
                                       ? dropped->second
                                       : mediaTypeOf(image.uri);
          notes_.problem(out_.warnings, "texture image " + name + " is a data: URI" +
                                            (type.empty() ? "" : " of type " + type) +
                                            " that holds no image PRT decodes");
        } else if (const fs::path file =
                       image.uri.empty() ? fs::path()
                                         : findTextureFile(fs::path(path_).parent_path(), image.uri);
                   file.empty()) {
          notes_.problem(out_.warnings, "texture image " + name + " was not found");
        } else {
          try {
            const std::vector<uint8_t> read = readTextureFile(file);
            result = decodeTextureImage(read.data(), read.size(), name, budget_);
          } catch (const TextureError& e) {
            notes_.problem(out_.warnings, e.what());
          }
        }
      } else if (bytes->second == nullptr) {
        notes_.problem(out_.warnings, "texture image " + name + " is beyond the 1 GiB its file's images may take encoded");
      } else {
        try {
          result = decodeTextureImage(bytes->second->data(), bytes->second->size(), name, budget_);
        } catch (const TextureError& e) {
          notes_.problem(out_.warnings, e.what());
        }
      }
    }
    images_[index] = result;
    return result;
  }

  void addCamera(const tinygltf::Node& node, const Transform& world) {
    if (static_cast<size_t>(node.camera) >= model_.cameras.size()) return;
    const tinygltf::Camera& c = model_.cameras[static_cast<size_t>(node.camera)];
    ModelCamera camera;
    camera.name = !c.name.empty() ? c.name
                  : !node.name.empty() ? node.name
                                       : "camera " + std::to_string(out_.cameras.size());
    Camera& view = camera.camera;
    view.eye = world.point({});
    const Vec3 forward = world.vector({0, 0, -1});
    view.up = world.vector({0, 1, 0});
    if (!(length(forward) > 0) || !(length(cross(forward, view.up)) > 0)) return;
    view.lookAt = view.eye + normalize(forward);
    if (c.type == "orthographic") {
      const double ymag = std::abs(c.orthographic.ymag), xmag = std::abs(c.orthographic.xmag);
      view.orthoHeight = 2 * ymag * length(view.up);
      const double aspect = xmag / ymag;
      if (!(view.orthoHeight > 0 && view.orthoHeight <= 1e9)) return unusableCamera(camera.name);
      if (aspect > 1e-3 && aspect < 1e3) camera.aspectRatio = aspect;
    } else if (c.type == "perspective") {
      const double fov = degrees(c.perspective.yfov);
      if (!(fov > 0 && fov <= 179)) return unusableCamera(camera.name);
      view.fovDegrees = fov;
      const double aspect = c.perspective.aspectRatio;
      if (aspect > 1e-3 && aspect < 1e3) camera.aspectRatio = aspect;
    } else {
      return unusableCamera(camera.name);
    }
    out_.cameras.push_back(std::move(camera));
  }

  // The bytes of buffer view `index`, or null when it or its buffer does not exist or the
  // view reaches past the buffer.
  std::pair<const uint8_t*, size_t> viewBytes(int index) const {
    if (index < 0 || static_cast<size_t>(index) >= model_.bufferViews.size()) return {nullptr, 0};
    const tinygltf::BufferView& view = model_.bufferViews[static_cast<size_t>(index)];
    if (view.buffer < 0 || static_cast<size_t>(view.buffer) >= model_.buffers.size()) return {nullptr, 0};
    const std::vector<unsigned char>& buffer = model_.buffers[static_cast<size_t>(view.buffer)].data;
    if (view.byteOffset > buffer.size() || view.byteLength > buffer.size() - view.byteOffset) {
      return {nullptr, 0};
    }
    return {buffer.data() + view.byteOffset, view.byteLength};
  }

  void unusableCamera(const std::string& name) {
    notes_.notUsed.insert("camera '" + name + "', whose projection no camera can have");
  }

  void addLight(int index, const Transform& world) {
    if (index < 0 || static_cast<size_t>(index) >= model_.lights.size()) return;
    const tinygltf::Light& l = model_.lights[static_cast<size_t>(index)];
    if (l.intensity < 0) {  // a light that darkens: no scene light can
      notes_.notUsed.insert("light " + (l.name.empty() ? std::to_string(index) : "'" + l.name + "'") +
                            ", of negative intensity");
      return;
    }
    Light light;
    const Color color = l.color.size() == 3 ? Color(l.color[0], l.color[1], l.color[2]) : Color(1);
    light.color = color * (std::isfinite(l.intensity) ? l.intensity : 1.0) * kLightScale;
    const Vec3 position = world.point({});
    const Vec3 axis = world.vector({0, 0, -1});
    if (!(length(axis) > 0)) return;
    if (l.type == "directional") {
      light.shape = DirectionalLight{normalize(axis)};
    } else if (l.type == "spot") {
      const double outer = std::clamp(degrees(l.spot.outerConeAngle), 0.0, 90.0);
      const double inner = std::clamp(degrees(l.spot.innerConeAngle), 0.0, outer);
      light.shape = SpotLight{position, normalize(axis), inner, outer};
      light.falloff = Falloff::inverseSquare;
    } else {
      light.shape = PointLight{position};
      light.falloff = Falloff::inverseSquare;
    }
    if (!isFinite(light.color)) return;
    out_.lights.push_back(light);
  }

  const std::string path_;
  size_t budget_;
  tinygltf::Model model_;
  ImportedModel out_;
  EncodedImages encoded_;
  std::map<int, std::string> undecodable_;  // images whose data: URI was dropped: its media type
  std::vector<char> onPath_, visited_;
  bool rigging_ = false;           // whether the file has channels that may move its nodes
  std::vector<int> rigGltfNodes_;  // per node of out_.rig while walking the tree: its glTF node
  uintmax_t bytesLeft_ = kMaxBytesRead;
  // Meshes by (mesh, primitive, morph weights: none for the shape as stored).
  std::map<std::tuple<int, size_t, std::vector<double>>, std::shared_ptr<const TriangleMesh>> meshes_;
  size_t morphedCopies_ = 0;  // vertices, indices and weights of the morphed copies so far
  static constexpr size_t kMorphedCopyBudget = size_t{1} << 23;
  size_t morphMoves_ = 0;  // vertices moved by a target, each time one is
  static constexpr size_t kMorphMoves = size_t{1} << 26;
  std::map<int, Material> materials_;
  std::map<std::pair<int, bool>, int> textures_;  // (glTF index, linear) to out_.textures
  std::map<int, std::shared_ptr<const TextureImage>> images_;
  ModelNotes notes_;
};

}  // namespace

ImportedModel readGltfFile(const std::string& path, const ModelReadOptions& options) {
  std::string text;
  try {
    return GltfReader(path, options).read();
  } catch (GltfVersionOne& one) {
    text = std::move(one.text);
  }
  // glTF 1.0, which tinygltf does not read: assimp's reader, contained as for every other
  // format it reads, with what failed said to be glTF 1.0.
  try {
    ImportedModel model = readAssimpFileContained(path, options, text);
    model.format = "glTF 1.0 (assimp)";
    return model;
  } catch (const ModelFileError& e) {
    const std::string named = "model file \"" + path + "\" ", what = e.what();
    if (what.rfind(named, 0) != 0) throw ModelFileError(what + " (" + path + ": glTF 1.0, read with assimp)");
    throw ModelFileError(named + "(glTF 1.0, read with assimp) " + what.substr(named.size()));
  }
}

}  // namespace prt
