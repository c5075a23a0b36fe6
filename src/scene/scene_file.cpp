// loadSceneFile: reading a scene file and refusing, with one clear line, anything that is not
// a scene's text (a missing file, a directory, an empty file, a binary file) before parsing.

#include "scene/scene_file.h"

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <memory>

#include "core/input_file.h"
#include "core/text.h"
#include "scene/model_file.h"
#include "scene/source_text.h"

namespace prt {
namespace {

// Far beyond any hand-written scene; stops /dev/zero or a wrong huge file from eating memory.
constexpr size_t kMaxSceneFileBytes = size_t{64} << 20;

std::string readWholeFile(const std::string& path) {
  namespace fs = std::filesystem;
  if (path.empty()) throw InputError("no scene file name given");
  std::error_code error;
  const fs::file_status status = fs::status(path, error);
  if (status.type() == fs::file_type::not_found) {
    throw InputError("scene file " + quote(path, '\'') + " does not exist");
  }
  if (status.type() == fs::file_type::directory) {
    throw InputError(quote(path, '\'') + " is a directory, not a scene file");
  }
  // A FIFO would block until some writer comes, a device may never end (/dev/zero) or wait
  // for input (a terminal): only regular files are read.
  if (const std::string kind = specialFileKind(status.type()); !kind.empty()) {
    throw InputError(quote(path, '\'') + " is " + kind + ", not a regular file; give a scene file");
  }

  const std::unique_ptr<std::FILE, int (*)(std::FILE*)> file(std::fopen(path.c_str(), "rb"),
                                                             &std::fclose);
  if (!file) {
    throw InputError("cannot open scene file " + quote(path, '\'') + ": " + std::strerror(errno));
  }
  std::string text;
  char buffer[1 << 16];
  size_t count = 0;
  while ((count = std::fread(buffer, 1, sizeof buffer, file.get())) > 0) {
    text.append(buffer, count);
    if (text.size() > kMaxSceneFileBytes) {
      throw InputError("scene file " + quote(path, '\'') + " is too large (over " +
                       std::to_string(kMaxSceneFileBytes >> 20) + " MiB); is it a scene?");
    }
  }
  if (std::ferror(file.get())) {
    throw InputError("cannot read scene file " + quote(path, '\'') + ": " + std::strerror(errno));
  }
  return text;
}

// Length of the UTF-8 sequence starting at text[i], or 0 if it is not valid UTF-8 (stray
// continuation bytes, truncation, overlong forms, surrogates, beyond U+10FFFF).
size_t utf8Length(std::string_view text, size_t i) {
  const auto byte = [&](size_t k) { return static_cast<unsigned char>(text[k]); };
  const unsigned char lead = byte(i);
  size_t length = 0;
  unsigned lowest = 0;  // smallest second byte allowed, to reject overlong forms and such
  unsigned highest = 0xBF;
  if (lead < 0x80) return 1;
  if (lead >= 0xC2 && lead <= 0xDF) {
    length = 2, lowest = 0x80;
  } else if (lead >= 0xE0 && lead <= 0xEF) {
    length = 3, lowest = lead == 0xE0 ? 0xA0 : 0x80, highest = lead == 0xED ? 0x9F : 0xBF;
  } else if (lead >= 0xF0 && lead <= 0xF4) {
    length = 4, lowest = lead == 0xF0 ? 0x90 : 0x80, highest = lead == 0xF4 ? 0x8F : 0xBF;
  } else {
    return 0;
  }
  if (i + length > text.size()) return 0;
  if (byte(i + 1) < lowest || byte(i + 1) > highest) return 0;
  for (size_t k = 2; k < length; ++k) {
    if (byte(i + k) < 0x80 || byte(i + k) > 0xBF) return 0;
  }
  return length;
}

// Throws unless `text` is UTF-8 text without control characters other than white space.
void checkIsText(std::string_view text, const std::string& path) {
  int line = 1;
  for (size_t i = 0; i < text.size();) {
    const char c = text[i];
    const auto u = static_cast<unsigned char>(c);
    const std::string where = " (line " + std::to_string(line) + ")";
    if (u == 0) {
      throw InputError(quote(path, '\'') + " is a binary file, not a scene: it contains NUL bytes" +
                       where);
    }
    const bool whiteSpace = c == '\t' || c == '\n' || c == '\r' || c == '\f' || c == '\v';
    if ((u < 0x20 && !whiteSpace) || u == 0x7F) {
      char code[8];
      std::snprintf(code, sizeof code, "0x%02X", static_cast<unsigned>(u));
      throw InputError(quote(path, '\'') +
                       " is not a text scene file: it contains control character " + code + where);
    }
    const size_t length = utf8Length(text, i);
    if (length == 0) {
      throw InputError(quote(path, '\'') + " is not a text scene file: it is not valid UTF-8" +
                       where);
    }
    if (endsLine(text, i)) ++line;
    i += length;
  }
}

// True if there is anything besides white space and comments.
bool hasContent(std::string_view text) {
  bool inComment = false;
  for (const char c : text) {
    if (c == '\n' || c == '\r') {
      inComment = false;
    } else if (c == '#') {
      inComment = true;
    } else if (!inComment && c != ' ' && c != '\t' && c != '\r' && c != '\f' && c != '\v') {
      return true;
    }
  }
  return false;
}

}  // namespace

std::string modelSceneText(const std::string& path, const ImportedModel& model,
                           const SceneReadOptions& options) {
  const std::filesystem::path file = std::filesystem::absolute(path).lexically_normal();
  // The camera the render will look through decides the image's shape.
  double aspect = 0;
  if (!model.cameras.empty()) {
    aspect = model.cameras.front().aspectRatio;
    for (size_t i = 0; i < model.cameras.size(); ++i) {
      if (model.cameras[i].name == options.camera || std::to_string(i) == options.camera) {
        aspect = model.cameras[i].aspectRatio;
      }
    }
  }
  const int width = 640;
  const int height = aspect > 0 ? std::clamp(static_cast<int>(std::lround(width / aspect)), 1, 32768)
                                : 480;
  std::string text = "image { width " + std::to_string(width) + " height " +
                     std::to_string(height) + " output ";
  auto quoted = [](const std::string& s) {
    std::string q = "\"";
    for (const char c : s) {
      if (c == '"' || c == '\\') q += '\\';
      q += c;
    }
    return q + "\"";
  };
  text += quoted(file.stem().string() + ".png") + " }\n";
  // Blender's default world grey; a model file is path-traced, as the tool that made it renders.
  text += "environment { background 0.05 0.05 0.05 ambient 0.05 0.05 0.05 integrator path }\n";
  text += "import { file " + quoted(file.string()) + " }\n";
  return text;
}

Scene loadSceneFile(const std::string& path, const SceneReadOptions& options) {
  const std::string extension = std::filesystem::path(path).extension().string();
  if (!path.empty() && (isModelFileName(path) || (extension != ".scene" && looksLikeModelFile(path)))) {
    std::error_code error;
    const auto status = std::filesystem::status(path, error);
    if (status.type() == std::filesystem::file_type::not_found) {
      throw InputError("model file " + quote(path, '\'') + " does not exist");
    }
    if (status.type() != std::filesystem::file_type::regular) {
      throw InputError(quote(path, '\'') + " is not a regular file; give a scene or model file");
    }
    ModelCache local;
    ModelCache& models = options.models != nullptr ? *options.models : local;
    const std::string absolute = std::filesystem::absolute(path).lexically_normal().string();
    std::shared_ptr<const ImportedModel> model;
    try {
      model = std::make_shared<const ImportedModel>(readModelFile(absolute, {options.strict}));
    } catch (const ModelFileError& e) {
      const std::string message = e.what();
      throw InputError(message.find(path) != std::string::npos
                           ? message
                           : "model file " + quote(path, '\'') + ": " + message);
    }
    models[absolute] = model;
    SceneReadOptions read = options;
    read.models = &models;
    Scene scene;
    try {
      scene = parseScene(modelSceneText(absolute, *model, options), path, read);
    } catch (const InputError& e) {
      // A line and column would point into the scene text made for the model, which the user
      // never wrote: the message names the file, and is about it.
      const std::string message = e.what();
      throw InputError(message.find(path) != std::string::npos
                           ? message
                           : "model file " + quote(path, '\'') + ": " + message);
    }
    // The warnings name the generated text's line; the file itself is what they are about.
    for (std::string& w : scene.warnings) {
      const size_t at = w.find(": model file");
      if (at != std::string::npos) w.erase(0, at + 2);
    }
    return scene;
  }
  const std::string text = readWholeFile(path);
  std::string_view body = text;
  // Some editors start UTF-8 files with a byte order mark; it is not part of the scene.
  if (body.starts_with("\xEF\xBB\xBF")) body.remove_prefix(3);
  checkIsText(body, path);
  if (!hasContent(body)) {
    throw InputError("scene file " + quote(path, '\'') + " is empty" +
                     (body.empty() ? "" : " (it has only comments and white space)"));
  }
  return parseScene(body, path, options);
}

}  // namespace prt
