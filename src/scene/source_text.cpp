#include "scene/source_text.h"

namespace prt {

SourceText::SourceText(std::string_view text, std::string fileName)
    : text_(text), fileName_(std::move(fileName)) {
  lineStarts_.push_back(0);
  for (size_t i = 0; i < text_.size(); ++i) {
    if (text_[i] == '\n') lineStarts_.push_back(i + 1);
  }
}

std::string_view SourceText::lineText(int line) const {
  if (line < 1 || line > lineCount()) return {};
  const size_t begin = lineStarts_[static_cast<size_t>(line - 1)];
  size_t end = line < lineCount() ? lineStarts_[static_cast<size_t>(line)] - 1 : text_.size();
  // Files written on Windows end lines with "\r\n"; the '\r' must not reach the terminal.
  if (end > begin && text_[end - 1] == '\r') --end;
  return text_.substr(begin, end - begin);
}

SourceLocation SourceText::locate(int line, int column) const {
  return SourceLocation{fileName_, line, column, std::string(lineText(line))};
}

void SourceText::fail(int line, int column, const std::string& message) const {
  throw InputError(message, locate(line, column));
}

}  // namespace prt
