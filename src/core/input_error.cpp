#include "core/input_error.h"

namespace prt {

std::string InputError::format() const {
  std::string out;
  if (!where_.file.empty()) out += where_.file + ":";
  if (where_.line > 0) {
    out += std::to_string(where_.line) + ":" + std::to_string(where_.column) + ":";
  }
  if (!out.empty()) out += " ";
  out += "error: ";
  out += what();
  if (where_.line > 0 && !where_.lineText.empty()) {
    out += "\n  " + where_.lineText + "\n  ";
    // Keep tabs so the caret lines up under tab-indented text.
    for (int i = 1; i < where_.column && i - 1 < static_cast<int>(where_.lineText.size()); ++i) {
      out += where_.lineText[static_cast<size_t>(i - 1)] == '\t' ? '\t' : ' ';
    }
    out += "^";
  }
  return out;
}

}  // namespace prt
