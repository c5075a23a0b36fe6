#include "scene/mesh_text_check.h"

#include <cctype>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <vector>

#include "scene/mesh_file.h"

namespace prt {
namespace {

// The lines of a text, numbered from 1, split into words; '#' starts a comment when asked.
class Lines {
 public:
  Lines(std::string_view text, bool comments) : text_(text), comments_(comments) {}

  // The next line's words; false at the end.
  bool next(std::vector<std::string_view>& words) {
    if (pos_ >= text_.size()) return false;
    size_t end = text_.find('\n', pos_);
    if (end == std::string_view::npos) end = text_.size();
    std::string_view line = text_.substr(pos_, end - pos_);
    pos_ = end + 1;
    ++number_;
    if (comments_) line = line.substr(0, line.find('#'));
    words.clear();
    size_t i = 0;
    while (i < line.size()) {
      while (i < line.size() && std::isspace(static_cast<unsigned char>(line[i]))) ++i;
      const size_t start = i;
      while (i < line.size() && !std::isspace(static_cast<unsigned char>(line[i]))) ++i;
      if (i > start) words.push_back(line.substr(start, i - start));
    }
    return true;
  }
  int number() const { return number_; }

 private:
  std::string_view text_;
  bool comments_;
  size_t pos_ = 0;
  int number_ = 0;
};

[[noreturn]] void fail(const std::string& file, int line, const std::string& message) {
  throw MeshFileError(file + ":" + std::to_string(line) + ": " + message, line);
}

// Built by appending: GCC 12 warns falsely (-Wrestrict) about "'" + std::string(...).
std::string quote(std::string_view word) {
  std::string out = "'";
  out += word;
  out += '\'';
  return out;
}

// A finite number, the whole word.
double number(std::string_view word, const std::string& file, int line, const char* what) {
  const std::string text(word);
  char* end = nullptr;
  const double value = std::strtod(text.c_str(), &end);
  if (end == text.c_str() || *end != '\0') {
    fail(file, line, std::string("expected a number for ") + what + ", found " + quote(word));
  }
  if (!std::isfinite(value)) {
    fail(file, line, std::string(what) + " is " + quote(word) + ", not a finite number");
  }
  return value;
}

// An integer, the whole word (leading sign allowed).
long long integer(std::string_view word, const std::string& file, int line, const char* what) {
  const std::string text(word);
  char* end = nullptr;
  errno = 0;
  const long long value = std::strtoll(text.c_str(), &end, 10);
  if (end == text.c_str() || *end != '\0' || errno == ERANGE) {
    fail(file, line, std::string("expected an integer for ") + what + ", found " + quote(word));
  }
  return value;
}

void checkObj(std::string_view text, const std::string& file) {
  // Counts first: an index may refer to any vertex of the file.
  long long counts[3] = {0, 0, 0};  // v, vt, vn
  std::vector<std::string_view> words;
  {
    Lines lines(text, true);
    while (lines.next(words)) {
      if (words.empty()) continue;
      if (words[0] == "v") ++counts[0];
      if (words[0] == "vt") ++counts[1];
      if (words[0] == "vn") ++counts[2];
    }
  }
  long long seen[3] = {0, 0, 0};  // so far, for negative (relative) indices
  Lines lines(text, true);
  while (lines.next(words)) {
    if (words.empty()) continue;
    const int line = lines.number();
    const std::string_view key = words[0];
    if (key == "v" || key == "vn" || key == "vt") {
      const size_t least = key == "vt" ? 1 : 3;
      const char* what = key == "v"    ? "a vertex coordinate"
                         : key == "vn" ? "a normal component"
                                       : "a texture coordinate";
      if (words.size() < least + 1) {
        fail(file, line,
             quote(key) + " needs " + std::to_string(least) + " numbers, found " +
                 std::to_string(words.size() - 1));
      }
      for (size_t i = 1; i < words.size(); ++i) number(words[i], file, line, what);
      ++seen[key == "v" ? 0 : key == "vt" ? 1 : 2];
    } else if (key == "f") {
      if (words.size() < 4) {
        fail(file, line,
             "a face needs at least 3 corners, found " + std::to_string(words.size() - 1));
      }
      for (size_t i = 1; i < words.size(); ++i) {
        // v, v/t, v//n or v/t/n
        std::string_view corner = words[i];
        for (int part = 0; part < 3 && !corner.empty(); ++part) {
          const size_t slash = corner.find('/');
          const std::string_view index = corner.substr(0, slash);
          corner = slash == std::string_view::npos ? std::string_view() : corner.substr(slash + 1);
          if (index.empty() && part > 0) continue;  // v//n leaves the texture out
          static constexpr const char* kWhat[] = {"a vertex index", "a texture index",
                                                  "a normal index"};
          static constexpr const char* kNoun[] = {"vertices", "texture coordinates", "normals"};
          const long long k = integer(index, file, line, kWhat[part]);
          const long long resolved = k < 0 ? seen[part] + 1 + k : k;
          if (k == 0 || resolved < 1 || resolved > counts[part]) {
            fail(file, line,
                 std::string(kWhat[part]) + " " + quote(index) + " is out of range: the file has " +
                     std::to_string(counts[part]) + " " + kNoun[part] +
                     (k < 0 ? " (" + std::to_string(seen[part]) + " before this line)" : ""));
          }
        }
      }
    }
  }
}

void checkAsciiPly(std::string_view text, const std::string& file) {
  struct Property {
    std::string_view name;
    bool list = false;
  };
  struct Element {
    std::string_view name;
    long long count = 0;
    std::vector<Property> properties;
  };
  std::vector<Element> elements;
  std::vector<std::string_view> words;
  Lines lines(text, false);
  bool ended = false;
  while (!ended && lines.next(words)) {
    const int line = lines.number();
    if (words.empty() || words[0] == "comment" || words[0] == "obj_info" || words[0] == "ply" ||
        words[0] == "format") {
      continue;
    }
    if (words[0] == "end_header") {
      ended = true;
    } else if (words[0] == "element" && words.size() == 3) {
      const long long count = integer(words[2], file, line, "an element count");
      if (count < 0) fail(file, line, "element " + quote(words[1]) + " has a negative count");
      elements.push_back({words[1], count, {}});
    } else if (words[0] == "property" && !elements.empty() && words.size() >= 3) {
      const bool list = words[1] == "list";
      if (list && words.size() != 5) fail(file, line, "malformed list property");
      elements.back().properties.push_back({words.back(), list});
    } else {
      fail(file, line, "malformed PLY header line starting " + quote(words[0]));
    }
  }
  if (!ended) fail(file, lines.number(), "the PLY header has no 'end_header'");
  long long vertices = 0;
  for (const Element& e : elements) {
    if (e.name == "vertex") vertices = e.count;
  }
  for (const Element& e : elements) {
    for (long long i = 0; i < e.count; ++i) {
      if (!lines.next(words)) {
        fail(file, lines.number() + 1,
             "the file ends after " + std::to_string(i) + " of the " + std::to_string(e.count) +
                 " " + std::string(e.name) + " lines its header promises");
      }
      const int line = lines.number();
      size_t w = 0;
      for (const Property& p : e.properties) {
        const bool corners =
            e.name == "face" && (p.name == "vertex_indices" || p.name == "vertex_index");
        if (!p.list) {
          if (w >= words.size())
            fail(file, line, "too few values on this " + std::string(e.name) + " line");
          number(words[w++], file, line, "a property value");
          continue;
        }
        if (w >= words.size())
          fail(file, line, "too few values on this " + std::string(e.name) + " line");
        const long long n = integer(words[w++], file, line, "a list length");
        if (n < 0 || static_cast<size_t>(n) > words.size() - w) {
          fail(file, line,
               "the list promises " + std::to_string(n) + " values, the line has " +
                   std::to_string(words.size() - w));
        }
        if (corners && n < 3)
          fail(file, line, "a face needs at least 3 corners, found " + std::to_string(n));
        for (long long k = 0; k < n; ++k) {
          if (!corners) {
            number(words[w++], file, line, "a list value");
            continue;
          }
          const long long index = integer(words[w], file, line, "a vertex index");
          if (index < 0 || index >= vertices) {
            fail(file, line,
                 "vertex index " + quote(words[w]) + " is out of range: the file has " +
                     std::to_string(vertices) + " vertices (indices 0 to " +
                     std::to_string(vertices - 1) + ")");
          }
          ++w;
        }
      }
      if (w != words.size()) {
        fail(file, line,
             "this " + std::string(e.name) + " line has " + std::to_string(words.size()) +
                 " values, its header declares " + std::to_string(w));
      }
    }
  }
}

std::string lowerExtension(const std::string& file) {
  std::string e = std::filesystem::path(file).extension().string();
  for (char& c : e) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return e;
}

}  // namespace

void checkMeshText(std::string_view text, const std::string& file) {
  const std::string extension = lowerExtension(file);
  if (extension == ".obj") return checkObj(text, file);
  if (text.starts_with("ply") && text.find("format ascii") != std::string_view::npos &&
      text.find("format ascii") < text.find("end_header")) {
    checkAsciiPly(text, file);
  }
}

}  // namespace prt
