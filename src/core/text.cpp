#include "core/text.h"

#include <cctype>
#include <filesystem>

namespace prt {

// Built by appending: GCC 12 warns falsely (-Wrestrict) about "'" + std::string(...).
std::string quote(std::string_view text, char mark) {
  std::string out;
  out.reserve(text.size() + 2);
  out += mark;
  out += text;
  out += mark;
  return out;
}

std::string lowerExtension(const std::string& path) {
  std::string e = std::filesystem::path(path).extension().string();
  for (char& c : e) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return e;
}

}  // namespace prt
