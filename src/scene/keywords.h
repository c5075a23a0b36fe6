#pragma once
// Names in error messages: the directive names of the .scene format, in the order the
// documentation lists them; joining names into the lists that messages offer ("valid
// parameters: a, b, c"); and suggesting the intended name for a misspelt one.

#include <algorithm>
#include <initializer_list>
#include <iterator>
#include <string>
#include <string_view>
#include <vector>

namespace prt {

inline constexpr std::string_view kDirectives[] = {
    "camera", "image",  "environment", "sampling", "material", "light",
    "sphere", "box",    "plane",       "mesh",     "triangle", "import"};

inline bool isDirective(std::string_view word) {
  return std::find(std::begin(kDirectives), std::end(kDirectives), word) != std::end(kDirectives);
}

template <typename Names>
std::string joinNames(const Names& names) {
  std::string out;
  for (const auto& name : names) {
    if (!out.empty()) out += ", ";
    out += name;
  }
  return out;
}

// " (did you mean 'radius'?)" when one of `names` is a likely intended spelling of `word`
// (a few edits away), else "".
std::string didYouMean(std::string_view word, const std::vector<std::string_view>& names);

}  // namespace prt
