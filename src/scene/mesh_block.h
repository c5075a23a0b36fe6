#pragma once
// The scene format's `mesh` and `triangle` blocks (docs/scene-format.md): their parameters,
// the mesh file they name (read by mesh_file.h, relative to the scene file's directory) or the
// meshes the master sent in its place (asset_pack.h), and the checks on the placed mesh. Used by
// the scene parser; errors are InputErrors at the offending token, as for every block.

#include <filesystem>
#include <vector>

#include "scene/asset_pack.h"
#include "scene/surface_parser.h"
#include "scene/token_stream.h"
#include "trace/scene.h"

namespace prt {

// What the blocks need from the parser, for the whole of one scene text.
struct MeshBlocks {
  TokenStream& in;
  const MaterialTable& materials;      // for `surface NAME`
  std::vector<std::string>& warnings;  // where skipped triangles are reported
  std::filesystem::path directory;     // of the scene file: mesh files are found from there
  const ShippedAssets* shipped;         // if not null, the meshes to take instead of the files
  size_t shippedUsed = 0;              // of them, so far
};

// A `scale` of one number (all axes) or three, none of them zero; `owner` names the block.
Vec3 readMeshScale(TokenStream& in, const std::string& name, const std::string& owner);

// Each reads one block after its keyword and returns the object it describes.
Object readMeshBlock(MeshBlocks& b, const Token& keyword);
Object readTriangleBlock(MeshBlocks& b, const Token& keyword);

}  // namespace prt
