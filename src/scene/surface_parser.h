#pragma once
// Surfaces: the material of an object, written inline, as the name of a material defined
// earlier, or as a name followed by a block that overrides some of its fields:
//
//   surface { color 1 0 0 diffuse 0.9 }
//   surface glass
//   surface glass { ior 1.33 }

#include <map>
#include <string>

#include "scene/token_stream.h"
#include "trace/scene.h"

namespace prt {

struct NamedMaterial {
  Material material;
  const Token* name = nullptr;  // where it was defined, for "already defined at" messages
};

// Materials by name; std::map keeps them sorted, which reads well in "defined materials: ..."
// messages.
using MaterialTable = std::map<std::string, NamedMaterial, std::less<>>;

// Reads a surface: the tokens after `keyword`, which is `surface` or the NAME of `material NAME`.
// `title` names the block in messages. Unspecified fields keep the named base material's
// values, or Material's defaults without a base.
Material readSurface(TokenStream& in, const Token& keyword, const std::string& title,
                     const MaterialTable& materials);

}  // namespace prt
