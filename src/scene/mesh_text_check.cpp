#include "scene/mesh_text_check.h"

#include <cctype>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <vector>

#include "core/text.h"
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
    line_ = line;
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
  size_t offset() const { return pos_; }  // of the next line's first byte
  // The column, from 1, of a word of the current line; of the line's end without a word.
  int column(std::string_view word) const {
    if (word.data() < line_.data() || word.data() > line_.data() + line_.size()) return end();
    return static_cast<int>(word.data() - line_.data()) + 1;
  }
  int end() const {
    std::string_view line = line_;
    while (!line.empty() && std::isspace(static_cast<unsigned char>(line.back()))) {
      line.remove_suffix(1);
    }
    return static_cast<int>(line.size()) + 1;
  }

 private:
  std::string_view text_;
  bool comments_;
  size_t pos_ = 0;
  int number_ = 0;
  std::string_view line_;  // the current line, without its comment
};

[[noreturn]] void fail(const std::string& file, int line, const std::string& message) {
  throw MeshFileError(file + ":" + std::to_string(line) + ": " + message, line);
}
// At `word` of the current line (its end for a null view): file:line:column.
[[noreturn]] void fail(const std::string& file, const Lines& lines, std::string_view word,
                       const std::string& message) {
  const int column = word.data() == nullptr ? lines.end() : lines.column(word);
  throw MeshFileError(
      file + ":" + std::to_string(lines.number()) + ":" + std::to_string(column) + ": " + message,
      lines.number());
}

// A finite number, the whole word.
double number(std::string_view word, const std::string& file, const Lines& lines, const char* what,
              NonFinite nonFinite) {
  const std::string text(word);
  char* end = nullptr;
  const double value = std::strtod(text.c_str(), &end);
  if (end == text.c_str() || *end != '\0') {
    fail(file, lines, word,
         std::string("expected a number for ") + what + ", found " + quote(word, '\''));
  }
  if (!std::isfinite(value) && nonFinite == NonFinite::refused) {
    fail(file, lines, word,
         std::string(what) + " is " + quote(word, '\'') + ", not a finite number");
  }
  return value;
}

// An integer, the whole word (leading sign allowed).
long long integer(std::string_view word, const std::string& file, const Lines& lines,
                  const char* what) {
  const std::string text(word);
  char* end = nullptr;
  errno = 0;
  const long long value = std::strtoll(text.c_str(), &end, 10);
  if (end == text.c_str() || *end != '\0' || errno == ERANGE) {
    fail(file, lines, word,
         std::string("expected an integer for ") + what + ", found " + quote(word, '\''));
  }
  return value;
}

void checkObj(std::string_view text, const std::string& file, NonFinite nonFinite) {
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
    const std::string_view key = words[0];
    if (key == "v" || key == "vn" || key == "vt") {
      const size_t least = key == "vt" ? 1 : 3;
      const char* what = key == "v"    ? "a vertex coordinate"
                         : key == "vn" ? "a normal component"
                                       : "a texture coordinate";
      if (words.size() < least + 1) {
        fail(file, lines, {},
             quote(key, '\'') + " needs " + std::to_string(least) + " numbers, found " +
                 std::to_string(words.size() - 1));
      }
      for (size_t i = 1; i < words.size(); ++i) number(words[i], file, lines, what, nonFinite);
      ++seen[key == "v" ? 0 : key == "vt" ? 1 : 2];
    } else if (key == "f" || key == "l" || key == "p") {
      // Faces, and the lines and points a mesh skips, whose indices must still be in range.
      const size_t least = key == "f" ? 3 : key == "l" ? 2 : 1;
      if (words.size() < least + 1) {
        fail(file, lines, {},
             std::string(key == "f"   ? "a face"
                         : key == "l" ? "a line"
                                      : "a point") +
                 " needs at least " + std::to_string(least) + " corners, found " +
                 std::to_string(words.size() - 1));
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
          const long long k = integer(index, file, lines, kWhat[part]);
          const long long resolved = k < 0 ? seen[part] + 1 + k : k;
          if (k == 0 || resolved < 1 || resolved > counts[part]) {
            fail(file, lines, index,
                 std::string(kWhat[part]) + " " + quote(index, '\'') +
                     " is out of range: the file has " + std::to_string(counts[part]) + " " +
                     kNoun[part] +
                     (k < 0 ? " (" + std::to_string(seen[part]) + " before this line)" : ""));
          }
        }
      }
    }
  }
}

struct PlyProperty {
  std::string_view name;
  bool list = false;
  std::string_view type, countType;  // a list's items are `type`, its length `countType`
};
struct PlyElement {
  std::string_view name;
  long long count = 0;
  std::vector<PlyProperty> properties;
};
struct PlyHeader {
  std::vector<PlyElement> elements;
  std::string_view format;  // ascii, binary_little_endian or binary_big_endian
  long long vertices = 0;
};

bool isFaceCorners(const PlyElement& e, const PlyProperty& p) {
  return e.name == "face" && (p.name == "vertex_indices" || p.name == "vertex_index");
}

// Reads the header; `lines` is left at the first line (or byte) after `end_header`.
PlyHeader readPlyHeader(Lines& lines, const std::string& file) {
  PlyHeader h;
  std::vector<std::string_view> words;
  bool ended = false;
  while (!ended && lines.next(words)) {
    if (words.empty() || words[0] == "comment" || words[0] == "obj_info" || words[0] == "ply") {
      continue;
    }
    if (words[0] == "format" && words.size() == 3) {
      h.format = words[1];
      if (h.format != "ascii" && h.format != "binary_little_endian" &&
          h.format != "binary_big_endian") {
        fail(file, lines, words[1], "unknown PLY format " + quote(h.format, '\''));
      }
    } else if (words[0] == "end_header") {
      ended = true;
    } else if (words[0] == "element" && words.size() == 3) {
      const long long count = integer(words[2], file, lines, "an element count");
      if (count < 0)
        fail(file, lines, words[2], "element " + quote(words[1], '\'') + " has a negative count");
      h.elements.push_back({words[1], count, {}});
      if (words[1] == "vertex") h.vertices = count;
    } else if (words[0] == "property" && !h.elements.empty() && words.size() >= 3) {
      const bool list = words[1] == "list";
      if (list && words.size() != 5) fail(file, lines, words[0], "malformed list property");
      if (!list && words.size() != 3) fail(file, lines, words[0], "malformed property");
      PlyProperty p{words.back(), list, list ? words[3] : words[1], list ? words[2] : ""};
      h.elements.back().properties.push_back(p);
    } else {
      fail(file, lines, words[0], "malformed PLY header line starting " + quote(words[0], '\''));
    }
  }
  if (!ended) fail(file, lines.number(), "the PLY header has no 'end_header'");
  return h;
}

void checkAsciiPly(Lines& lines, const PlyHeader& header, const std::string& file,
                   NonFinite nonFinite) {
  const std::vector<PlyElement>& elements = header.elements;
  std::vector<std::string_view> words;
  const long long vertices = header.vertices;
  for (const PlyElement& e : elements) {
    for (long long i = 0; i < e.count; ++i) {
      if (!lines.next(words)) {
        fail(file, lines.number() + 1,
             "the file ends after " + std::to_string(i) + " of the " + std::to_string(e.count) +
                 " " + std::string(e.name) + " lines its header promises");
      }
      size_t w = 0;
      for (const PlyProperty& p : e.properties) {
        const bool corners = isFaceCorners(e, p);
        if (!p.list) {
          if (w >= words.size())
            fail(file, lines, {}, "too few values on this " + std::string(e.name) + " line");
          number(words[w++], file, lines, "a property value", nonFinite);
          continue;
        }
        if (w >= words.size())
          fail(file, lines, {}, "too few values on this " + std::string(e.name) + " line");
        const long long n = integer(words[w++], file, lines, "a list length");
        if (n < 0 || static_cast<size_t>(n) > words.size() - w) {
          fail(file, lines, words[w - 1],
               "the list promises " + std::to_string(n) + " values, the line has " +
                   std::to_string(words.size() - w));
        }
        if (corners && n < 3)
          fail(file, lines, words[w - 1],
               "a face needs at least 3 corners, found " + std::to_string(n));
        for (long long k = 0; k < n; ++k) {
          if (!corners) {
            number(words[w++], file, lines, "a list value", nonFinite);
            continue;
          }
          const long long index = integer(words[w], file, lines, "a vertex index");
          if (index < 0 || index >= vertices) {
            fail(file, lines, words[w],
                 "vertex index " + quote(words[w], '\'') + " is out of range: the file has " +
                     std::to_string(vertices) + " vertices (indices 0 to " +
                     std::to_string(vertices - 1) + ")");
          }
          ++w;
        }
      }
      if (w != words.size()) {
        fail(file, lines, words[w],  // w < words.size(): no value is read past the line
             "this " + std::string(e.name) + " line has " + std::to_string(words.size()) +
                 " values, its header declares " + std::to_string(w));
      }
    }
  }
}

// Bytes of a PLY scalar type; 0 for an unknown name.
int plySize(std::string_view type) {
  if (type == "char" || type == "uchar" || type == "int8" || type == "uint8") return 1;
  if (type == "short" || type == "ushort" || type == "int16" || type == "uint16") return 2;
  if (type == "int" || type == "uint" || type == "int32" || type == "uint32" || type == "float" ||
      type == "float32") {
    return 4;
  }
  if (type == "double" || type == "float64") return 8;
  return 0;
}

bool plyIsFloat(std::string_view type) {
  return type == "float" || type == "float32" || type == "double" || type == "float64";
}
bool plyIsSigned(std::string_view type) {
  return type == "char" || type == "int8" || type == "short" || type == "int16" || type == "int" ||
         type == "int32";
}

// Walks a binary body record by record: every record fits in the file, every list length is
// sane, every corner index refers to a vertex. The reader (assimp 5.2) trusts all three and
// crashes on a file that breaks them.
void checkBinaryPly(std::string_view text, size_t at, const PlyHeader& header,
                    const std::string& file) {
  const bool big = header.format == "binary_big_endian";
  auto where = [&](const PlyElement& e, long long i) {
    return file + ": " + std::string(e.name) + " " + std::to_string(i + 1) + " of " +
           std::to_string(e.count) + " (byte " + std::to_string(at) + "): ";
  };
  auto integerAt = [&](size_t offset, std::string_view type) {
    const int size = plySize(type);
    uint64_t bits = 0;
    for (int k = 0; k < size; ++k) {
      const auto byte = static_cast<uint8_t>(text[offset + static_cast<size_t>(k)]);
      bits |= static_cast<uint64_t>(byte) << (8 * (big ? size - 1 - k : k));
    }
    if (plyIsSigned(type) && size < 8 && (bits >> (8 * size - 1)) != 0) {
      return static_cast<long long>(bits) - (1LL << (8 * size));  // sign-extended
    }
    return static_cast<long long>(bits);
  };
  for (const PlyElement& e : header.elements) {
    for (const PlyProperty& p : e.properties) {
      if (plySize(p.type) == 0 ||
          (p.list && (plySize(p.countType) == 0 || plyIsFloat(p.countType)))) {
        throw MeshFileError(file + ": unknown PLY type in property " + quote(p.name, '\''));
      }
    }
  }
  for (const PlyElement& e : header.elements) {
    for (long long i = 0; i < e.count; ++i) {
      for (const PlyProperty& p : e.properties) {
        const auto size = static_cast<size_t>(plySize(p.type));
        if (!p.list) {
          if (text.size() - at < size) {
            throw MeshFileError(where(e, i) + "the file ends inside this record");
          }
          at += size;
          continue;
        }
        const auto countSize = static_cast<size_t>(plySize(p.countType));
        if (text.size() - at < countSize) {
          throw MeshFileError(where(e, i) + "the file ends inside this record");
        }
        const long long n = integerAt(at, p.countType);
        const bool corners = isFaceCorners(e, p);
        if (n < 0 || (corners && n < 3)) {
          throw MeshFileError(where(e, i) + "a list of " + std::to_string(n) +
                              (corners ? " corners (a face needs at least 3)" : " values"));
        }
        at += countSize;
        if (static_cast<unsigned long long>(n) > (text.size() - at) / size) {
          throw MeshFileError(where(e, i) + "the file ends inside this record's list of " +
                              std::to_string(n));
        }
        if (corners) {
          for (long long k = 0; k < n; ++k) {
            const long long index = integerAt(at + static_cast<size_t>(k) * size, p.type);
            if (plyIsFloat(p.type) || index < 0 || index >= header.vertices) {
              throw MeshFileError(where(e, i) + "vertex index " + std::to_string(index) +
                                  " is out of range: the file has " +
                                  std::to_string(header.vertices) + " vertices");
            }
          }
        }
        at += static_cast<size_t>(n) * size;
      }
    }
  }
}

}  // namespace

void checkMeshText(std::string_view text, const std::string& file, NonFinite nonFinite) {
  const std::string extension = lowerExtension(file);
  if (extension == ".obj") return checkObj(text, file, nonFinite);
  if (!text.starts_with("ply")) return;
  Lines lines(text, false);
  const PlyHeader header = readPlyHeader(lines, file);
  if (header.format == "ascii") {
    checkAsciiPly(lines, header, file, nonFinite);
  } else {
    checkBinaryPly(text, lines.offset(), header, file);
  }
}

}  // namespace prt
