#pragma once
// The directive names of the .scene format, in the order the documentation lists them, and
// joining names into the lists that error messages offer ("valid parameters: a, b, c").

#include <algorithm>
#include <span>
#include <string>
#include <string_view>

namespace prt {

inline constexpr std::string_view kDirectives[] = {
    "camera", "image", "environment", "sampling", "material", "light", "sphere", "box", "plane"};

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

}  // namespace prt
