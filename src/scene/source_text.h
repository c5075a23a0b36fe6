#pragma once
// SourceText: the text of a scene being parsed, with its file name and an index of where each
// line starts, so that any token's (line, column) can become a SourceLocation carrying the
// whole line for the caret display. Columns are 1-based byte offsets within the line.

#include <string>
#include <string_view>
#include <vector>

#include "core/input_error.h"

namespace prt {

// Whether text[i] is the last character of a line end: "\n", the "\n" of "\r\n", or a "\r"
// alone (old Mac OS files). All three end a line, for line numbers and for comments.
bool endsLine(std::string_view text, size_t i);

class SourceText {
 public:
  // `text` must outlive this object; it is viewed, not copied.
  SourceText(std::string_view text, std::string fileName);

  std::string_view text() const { return text_; }
  const std::string& fileName() const { return fileName_; }
  int lineCount() const { return static_cast<int>(lineStarts_.size()); }

  // Line `line` (1-based) without its end-of-line characters.
  std::string_view lineText(int line) const;

  SourceLocation locate(int line, int column) const;

  // For problems that belong to the file as a whole (no line, no caret).
  SourceLocation wholeFile() const { return SourceLocation{fileName_, 0, 0, {}}; }

  [[noreturn]] void fail(int line, int column, const std::string& message) const;

 private:
  std::string_view text_;
  std::string fileName_;
  std::vector<size_t> lineStarts_;  // byte offset of the first character of each line
};

}  // namespace prt
