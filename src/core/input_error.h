#pragma once
// InputError: bad user input (a scene file, a flag value). Carries where it happened, when
// known, so the message reads "file:line:col: error: ...", then the offending line with a '^'
// under the culprit. The CLI catches it and exits with code 2.

#include <stdexcept>
#include <string>

namespace prt {

struct SourceLocation {
  std::string file;      // path as the user gave it; empty when there is no file
  int line = 0;          // 1-based; 0 when unknown
  int column = 0;        // 1-based; 0 when unknown
  std::string lineText;  // the whole offending line, for the caret display
};

class InputError : public std::runtime_error {
 public:
  explicit InputError(const std::string& message) : std::runtime_error(message) {}
  InputError(const std::string& message, SourceLocation where)
      : std::runtime_error(message), where_(std::move(where)) {}

  const SourceLocation& where() const { return where_; }
  bool hasLocation() const { return where_.line > 0; }

  // "file:line:col: error: message\n  <line>\n  ^" (or "error: message" without a location).
  std::string format() const;

 private:
  SourceLocation where_;
};

}  // namespace prt
