// libFuzzer target: the line-by-line check of OBJ and PLY files (scene/mesh_text_check.h) on
// arbitrary bytes, named input.ply when they start with "ply" and input.obj otherwise (the
// check walks a PLY's binary records by the header's counts and types, so an out-of-bounds
// read is what it must never do). It must return, or throw a MeshFileError whose message
// starts with the file's name; where the message gives file:line:column, the line must be
// one of the text's (or the one after its end) and the column inside that line or just past it.

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <string>
#include <string_view>

#include "scene/mesh_file.h"
#include "scene/mesh_text_check.h"

namespace {

void check(bool ok) {
  if (!ok) std::abort();
}

// The digits at `at` of `text` as a number (advancing `at`), or -1 when there are none.
long digits(const std::string& text, size_t& at) {
  long value = -1;
  while (at < text.size() && text[at] >= '0' && text[at] <= '9' && value < 100000000) {
    value = (value < 0 ? 0 : value * 10) + (text[at] - '0');
    ++at;
  }
  return value;
}

void checkLocation(std::string_view text, const std::string& file, const std::string& message) {
  size_t at = file.size();
  if (at >= message.size() || message[at] != ':') return;
  ++at;
  const long line = digits(message, at);
  if (line < 0) return;  // "input.ply: vertex 3 of 4 (byte 120): ..."
  check(line >= 1);
  const long lines = static_cast<long>(std::count(text.begin(), text.end(), '\n')) + 1;
  check(line <= lines + 1);
  if (at >= message.size() || message[at] != ':') return;
  ++at;
  const long column = digits(message, at);
  if (column < 0) return;  // file:line: message
  check(column >= 1);
  // The line's length.
  size_t start = 0;
  for (long k = 1; k < line && start != std::string_view::npos; ++k) {
    start = text.find('\n', start);
    if (start != std::string_view::npos) ++start;
  }
  check(start != std::string_view::npos);
  const size_t end = std::min(text.find('\n', start), text.size());
  check(static_cast<size_t>(column) <= end - start + 1);
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  const std::string_view text(reinterpret_cast<const char*>(data), size);
  const std::string file = text.starts_with("ply") ? "input.ply" : "input.obj";
  for (const prt::NonFinite nonFinite : {prt::NonFinite::refused, prt::NonFinite::allowed}) {
    try {
      prt::checkMeshText(text, file, nonFinite);
    } catch (const prt::MeshFileError& e) {
      const std::string message = e.what();
      check(message.starts_with(file));
      checkLocation(text, file, message);
    }
  }
  return 0;
}
