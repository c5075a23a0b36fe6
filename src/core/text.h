#pragma once
// Small text helpers shared by the libraries' messages and file-type checks.

#include <string>
#include <string_view>

namespace prt {

// `text` between two `mark`s: quote("out.png") is "\"out.png\"", quote("radius", '\'') is
// "'radius'". Nothing inside is escaped.
std::string quote(std::string_view text, char mark = '"');

// The extension of `path` with its dot, in lower case: ".gltf" for "Model.GLTF"; empty when it
// has none.
std::string lowerExtension(const std::string& path);

}  // namespace prt
