#include "scene/source_text.h"

namespace prt {

bool endsLine(std::string_view text, size_t i) {
  return text[i] == '\n' || (text[i] == '\r' && (i + 1 == text.size() || text[i + 1] != '\n'));
}

SourceText::SourceText(std::string_view text, std::string fileName)
    : text_(text), fileName_(std::move(fileName)) {
  lineStarts_.push_back(0);
  for (size_t i = 0; i < text_.size(); ++i) {
    if (endsLine(text_, i)) lineStarts_.push_back(i + 1);
  }
}

std::string_view SourceText::lineText(int line) const {
  if (line < 1 || line > lineCount()) return {};
  const size_t begin = lineStarts_[static_cast<size_t>(line - 1)];
  size_t end = line < lineCount() ? lineStarts_[static_cast<size_t>(line)] : text_.size();
  // Drop the line end: "\n", "\r\n" (Windows) or "\r" (old Mac OS); no '\r' may reach the
  // terminal.
  while (end > begin && (text_[end - 1] == '\n' || text_[end - 1] == '\r')) --end;
  return text_.substr(begin, end - begin);
}

SourceLocation SourceText::locate(int line, int column) const {
  return SourceLocation{fileName_, line, column, std::string(lineText(line))};
}

void SourceText::fail(int line, int column, const std::string& message) const {
  throw InputError(message, locate(line, column));
}

}  // namespace prt
