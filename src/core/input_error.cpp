#include "core/input_error.h"

#include <algorithm>

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
    // A line of a hundred kilobytes (a generated file, a binary) would flood the terminal:
    // show at most kShown bytes around the culprit, marking what is cut with "...".
    constexpr size_t kShown = 160;
    const std::string& text = where_.lineText;
    const size_t culprit = static_cast<size_t>(where_.column - 1);
    size_t begin = 0;
    size_t end = text.size();
    if (text.size() > kShown) {
      begin = culprit > kShown / 2 ? std::min(culprit - kShown / 2, text.size() - kShown) : 0;
      end = begin + kShown;
      // Never split a UTF-8 sequence: move off continuation bytes.
      const auto continuation = [&](size_t i) {
        return i < text.size() && (static_cast<unsigned char>(text[i]) & 0xC0) == 0x80;
      };
      while (begin > 0 && continuation(begin)) --begin;
      while (continuation(end)) ++end;
    }
    const std::string before = begin > 0 ? "..." : "";
    out += "\n  " + before + text.substr(begin, end - begin) + (end < text.size() ? "..." : "");
    out += "\n  " + std::string(before.size(), ' ');
    // Keep tabs so the caret lines up under tab-indented text.
    for (size_t i = begin; i < culprit && i < end; ++i) out += text[i] == '\t' ? '\t' : ' ';
    out += "^";
  }
  return out;
}

}  // namespace prt
