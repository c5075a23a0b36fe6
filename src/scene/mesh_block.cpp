#include "scene/mesh_block.h"

#include <cmath>
#include <memory>
#include <string>
#include <utility>

#include "scene/block_reader.h"
#include "scene/mesh_file.h"
#include "scene/number_text.h"
#include "scene/value_reader.h"

namespace prt {
namespace {

// The placed mesh checked, its warnings kept, as the object's shape.
Object withMesh(MeshBlocks& b, Object object, LoadedMesh loaded, MeshSource source,
                const Token& at) {
  for (const Vec3& v : loaded.mesh->vertices) {
    if (!(std::abs(v.x) <= kMaxCoordinate && std::abs(v.y) <= kMaxCoordinate &&
          std::abs(v.z) <= kMaxCoordinate)) {
      b.in.fail(at, "the mesh reaches beyond " + formatDouble(kMaxCoordinate) +
                        " world units once placed (a vertex at " + formatDouble(v.x) + " " +
                        formatDouble(v.y) + " " + formatDouble(v.z) + ")");
    }
  }
  for (std::string& w : loaded.warnings) {
    b.warnings.push_back(b.in.source().fileName() + ":" + std::to_string(at.line) + ": " + w);
  }
  object.shape = MeshShape{std::move(loaded.mesh), std::move(source)};
  return object;
}

}  // namespace

Vec3 readMeshScale(TokenStream& in, const std::string& name, const std::string& owner) {
  size_t at[3];
  double value[3];
  int given = 0;
  do {
    at[given] = in.position();
    value[given] = readNumber(in, name, kCoordinate);
    ++given;
  } while (given < 3 && (given > 1 || in.peek().kind == TokenKind::Number));
  for (int i = 0; i < given; ++i) {
    if (value[i] == 0) {
      in.fail(in.at(at[i]), "the " + owner + "'s 'scale' must not be zero: it would flatten the " +
                                (owner == "mesh" ? "mesh" : "model"));
    }
  }
  return given == 1 ? Vec3(value[0]) : Vec3(value[0], value[1], value[2]);
}

Object readMeshBlock(MeshBlocks& b, const Token& keyword) {
  Object object{MeshShape{}, Material{}};
  MeshSource source;
  BlockReader block(b.in, keyword, "mesh",
                    {"file", "scale", "rotate", "translate", "smooth", "surface"});
  while (const Token* param = block.next()) {
    const std::string& name = param->text;
    if (name == "file") source.file = readString(b.in, name);
    if (name == "scale") source.scale = readMeshScale(b.in, name, "mesh");
    if (name == "rotate")
      source.rotateDegrees = readVector(b.in, name, Range::closed(-36000, 36000));
    if (name == "translate") source.translate = readVector(b.in, name, kCoordinate);
    if (name == "smooth") source.smooth = true;
    if (name == "surface") object.material = readSurface(b.in, *param, "surface", b.materials);
  }
  block.require({"file"});
  const Token& fileToken = block.valueToken("file");
  if (source.file.empty()) b.in.fail(fileToken, "the mesh's 'file' must not be empty");
  // Relative to the scene file's directory.
  std::filesystem::path path(source.file);
  if (path.is_relative()) path = b.directory / path;
  source.file = std::filesystem::absolute(path).lexically_normal().string();
  LoadedMesh loaded;
  if (b.shipped != nullptr) {
    if (b.shippedUsed == b.shipped->meshBlocks.size()) {
      b.in.fail(fileToken, "the scene has more meshes than were sent with it (" +
                               std::to_string(b.shipped->meshBlocks.size()) + ")");
    }
    // Sent as read: a copy would be the same doubles (and the same warnings, given already).
    loaded.mesh = std::const_pointer_cast<TriangleMesh>(b.shipped->meshBlocks[b.shippedUsed++]);
  } else {
    try {
      loaded = loadMeshFile(source);
    } catch (const MeshFileError& e) {
      b.in.fail(fileToken, e.what());
    }
  }
  return withMesh(b, std::move(object), std::move(loaded), std::move(source), fileToken);
}

Object readTriangleBlock(MeshBlocks& b, const Token& keyword) {
  Object object{MeshShape{}, Material{}};
  std::vector<Vec3> corners;
  BlockReader block(b.in, keyword, "triangle", {"vertices", "surface"});
  while (const Token* param = block.next()) {
    const std::string& name = param->text;
    if (name == "vertices") {
      for (int i = 0; i < 3; ++i) corners.push_back(readVector(b.in, name, kCoordinate));
    }
    if (name == "surface") object.material = readSurface(b.in, *param, "surface", b.materials);
  }
  block.require({"vertices"});
  const Token& at = block.valueToken("vertices");
  LoadedMesh loaded;
  try {
    loaded = placeMesh(corners, {{0, 1, 2}}, {}, MeshSource{});
  } catch (const MeshFileError&) {
    b.in.fail(at, "the triangle's three vertices lie on one line (or coincide): it has no area");
  }
  return withMesh(b, std::move(object), std::move(loaded), MeshSource{}, at);
}

}  // namespace prt
