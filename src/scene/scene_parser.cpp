// parseScene: the directives of the .scene format and the checks that relate several values
// (a camera looking somewhere, a box with positive extent, an image that fits in memory).
// Single values are read and range-checked by value_reader, blocks by block_reader.

#include <algorithm>
#include <cctype>
#include <cstdint>
#include <filesystem>
#include <stdexcept>

#include "image/image_io.h"
#include "scene/block_reader.h"
#include "scene/environment_file.h"
#include "scene/key_frames.h"
#include "scene/keywords.h"
#include "scene/mesh_block.h"
#include "scene/number_text.h"
#include "scene/scene_file.h"
#include "scene/surface_parser.h"
#include "scene/value_reader.h"

namespace prt {
namespace {

constexpr int kMaxImageSide = 32768;
// An RGBA float image of 2^28 pixels already takes 4 GiB; larger ones do not fit in memory.
constexpr int64_t kMaxImagePixels = int64_t{1} << 28;

const Range kSize = Range{0, kMaxCoordinate, true, false};  // in (0, kMaxCoordinate]

bool isName(const std::string& word) {
  return std::all_of(word.begin(), word.end(), [](char c) {
    return std::isalnum(static_cast<unsigned char>(c)) != 0 || c == '_';
  });  // the lexer has already made sure the first character is a letter or '_'
}

// Keeps a vector that is already unit length (to rounding) exactly as written, so that a
// written and re-read scene is bit-identical: normalising twice can change the last bit.
Vec3 unitLength(const Vec3& v) {
  return std::abs(length(v) - 1.0) <= 1e-12 ? v : normalize(v);
}

int put(const Vec3& v, double* out) {
  out[0] = v.x, out[1] = v.y, out[2] = v.z;
  return 3;
}
int put(double v, double* out) {
  out[0] = v;
  return 1;
}

class SceneParser {
 public:
  SceneParser(const SourceText& source, const ShippedAssets* shipped,
              const SceneReadOptions& options)
      : in_(source),
        shipped_(shipped),
        meshes_{in_, materials_, scene_.warnings,
                std::filesystem::path(source.fileName()).parent_path(), shipped},
        options_(options),
        imports_{in_, scene_, std::filesystem::path(source.fileName()).parent_path(), shipped,
                 options.models != nullptr ? *options.models : models_,
                 ModelReadOptions{options.strict}} {}

  Scene run() {
    while (!in_.atEnd()) directive(in_.next());
    chooseCamera();
    requireBlock(image_, "image", "image { width 320 height 240 }");
    // A scene of imported models that brought no light gets one at the eye, so that it shows;
    // not one with emissive surfaces, its lights for the path tracer (a Cornell box's lamp).
    const bool emits = std::any_of(scene_.objects.begin(), scene_.objects.end(),
                                   [](const Object& o) { return o.material.emission != Color(); });
    if (scene_.lights.empty() && !scene_.imports.empty() && !emits) {
      scene_.lights.push_back(Light{PointLight{scene_.camera.eye}, Color(1), Falloff::none});
    }
    return std::move(scene_);
  }

 private:
  void directive(const Token& keyword) {
    if (keyword.kind == TokenKind::Word) {
      const std::string& name = keyword.text;
      if (name == "camera") return camera(keyword);
      if (name == "image") return image(keyword);
      if (name == "environment") return environment(keyword);
      if (name == "sampling") return sampling(keyword);
      if (name == "material") return material();
      if (name == "light") return light();
      if (name == "sphere") return sphere(keyword);
      if (name == "box") return box(keyword);
      if (name == "plane") return plane(keyword);
      if (name == "mesh") return mesh(keyword);
      if (name == "triangle") return triangle(keyword);
      if (name == "import") return readImportBlock(imports_, keyword);
      const std::vector<std::string_view> directives(std::begin(kDirectives),
                                                     std::end(kDirectives));
      in_.fail(keyword, "unknown directive " + describe(keyword) + didYouMean(name, directives) +
                            "; valid directives: " + joinNames(kDirectives));
    }
    if (keyword.kind == TokenKind::RightBrace) {
      in_.fail(keyword, "unexpected '}': no block is open here");
    }
    in_.fail(keyword,
             "expected a directive (" + joinNames(kDirectives) + "), found " + describe(keyword));
  }

  // Blocks that describe the whole scene may appear once.
  void once(const Token& keyword, const Token*& seen) {
    if (seen != nullptr) {
      in_.fail(keyword, "duplicate '" + keyword.text + "' block; the scene already has one at " +
                            lineAndColumn(*seen));
    }
    seen = &keyword;
  }

  void requireBlock(const Token* seen, const std::string& name, const std::string& example) {
    if (seen == nullptr) {
      throw InputError("the scene has no " + name + " block; it needs one, e.g. " + example,
                       in_.source().wholeFile());
    }
  }

  void camera(const Token& keyword) {
    once(keyword, camera_);
    Camera& camera = scene_.camera;
    BlockReader block(in_, keyword, "camera",
                      {"eye", "look_at", "up", "fov", "ortho_height", "from", "name", "index", "key"});
    KeyFrames keys("camera", FieldTrack::Target::camera, {"eye", "look_at", "up", "fov"});
    const ValueReader read = [&](const std::string& name, double* out) {
      if (name == "fov") return put(readNumber(in_, name, Range::open(0, 180)), out);
      return put(readVector(in_, name, kCoordinate), out);
    };
    const ValueReader base = [&](const std::string& name, double* out) {
      if (name == "eye") return put(camera.eye, out);
      if (name == "look_at") return put(camera.lookAt, out);
      if (name == "up") return put(camera.up, out);
      return put(camera.fovDegrees, out);
    };
    while (const Token* param = block.next()) {
      const std::string& name = param->text;
      if (name == "key") keys.read(in_, *param, read);
      if (name == "eye") camera.eye = readVector(in_, name, kCoordinate);
      if (name == "look_at") camera.lookAt = readVector(in_, name, kCoordinate);
      if (name == "up") camera.up = readVector(in_, name, kCoordinate);
      if (name == "fov") camera.fovDegrees = readNumber(in_, name, Range::open(0, 180));
      if (name == "ortho_height") camera.orthoHeight = readNumber(in_, name, kSize);
      if (name == "from") cameraFrom_ = readString(in_, name);
      if (name == "name") cameraName_ = readString(in_, name);
      if (name == "index") cameraIndex_ = readInteger(in_, name, 0, 1 << 20);
    }
    if (block.has("from")) {
      for (const char* other : {"eye", "look_at", "up", "fov", "ortho_height", "key"}) {
        if (block.has(other)) {
          in_.fail(block.valueToken(other), std::string("a camera taken 'from' a model file has no '") +
                                                other + "' of its own");
        }
      }
      if (block.has("name") && block.has("index")) {
        in_.fail(block.valueToken("index"), "give the camera's 'name' or its 'index', not both");
      }
      cameraFromToken_ = &block.valueToken("from");
      std::filesystem::path path(cameraFrom_);
      if (path.is_relative()) path = imports_.directory / path;
      cameraFrom_ = std::filesystem::absolute(path).lexically_normal().string();
      return;
    }
    for (const char* only : {"name", "index"}) {
      if (block.has(only)) {
        in_.fail(block.valueToken(only), std::string("'") + only +
                                             "' picks a camera of a model file: give 'from' too");
      }
    }
    block.require({"eye", "look_at"});
    checkCamera(camera, block, keyword);
    keys.finish(scene_, 0, base);
  }

  void checkCamera(const Camera& camera, const BlockReader& block, const Token& keyword) {
    // Lengths are tested with !(x > 0) so that vectors too short to square (1e-300) fail too.
    const Vec3 view = camera.lookAt - camera.eye;
    if (!(length(view) > 0)) {
      in_.fail(block.valueToken("look_at"),
               "the camera's 'look_at' equals its 'eye'; it must be the point looked at");
    }
    const Token& upToken = block.has("up") ? block.valueToken("up") : keyword;
    if (!(length(camera.up) > 0)) {
      in_.fail(upToken,
               "the camera's 'up' must not be zero, nor so short that its length underflows "
               "to zero");
    }
    // sin of the angle between them; below this the image's orientation is undefined.
    if (!(length(cross(normalize(view), normalize(camera.up))) >= 1e-6)) {
      in_.fail(upToken, std::string("the camera's ") +
                            (block.has("up") ? "'up'" : "default 'up' (0 1 0)") +
                            " is parallel to its view direction (look_at - eye); give an 'up' "
                            "that is not");
    }
  }

  // The camera: --camera's choice among the imported files' cameras, the block's (given, or
  // taken 'from' a file), the first imported camera, or one that frames the imported models.
  void chooseCamera() {
    const std::vector<OfferedCamera>& offered = imports_.cameras;
    auto names = [&] {
      std::string list;
      for (size_t i = 0; i < offered.size(); ++i) {
        list += (i ? ", " : "") + std::to_string(i) + " '" + offered[i].camera.name + "'";
      }
      return list.empty() ? std::string("none") : list;
    };
    if (!options_.camera.empty()) {
      const std::string& wanted = options_.camera;
      const bool number = !wanted.empty() && std::all_of(wanted.begin(), wanted.end(), [](char c) {
        return std::isdigit(static_cast<unsigned char>(c)) != 0;
      });
      for (size_t i = 0; i < offered.size(); ++i) {
        if (offered[i].camera.name == wanted || (number && wanted.size() < 9 && std::stoul(wanted) == i)) {
          return useCamera(offered[i]);
        }
      }
      throw InputError("--camera " + wanted + ": no imported camera has that name or index; the " +
                       "imported cameras are: " + names());
    }
    if (cameraFromToken_ != nullptr) {
      std::vector<const OfferedCamera*> ofFile;
      for (const OfferedCamera& c : offered) {
        if (c.file == cameraFrom_) ofFile.push_back(&c);
      }
      bool imported = false;
      for (const ImportSource& i : scene_.imports) imported = imported || i.file == cameraFrom_;
      if (!imported) {
        in_.fail(*cameraFromToken_, "the camera is taken from \"" + cameraFrom_ +
                                        "\", which the scene does not import; import it first");
      }
      for (size_t i = 0; i < ofFile.size(); ++i) {
        if ((!cameraName_.empty() && ofFile[i]->camera.name == cameraName_) ||
            (cameraName_.empty() && static_cast<int>(i) == cameraIndex_)) {
          return useCamera(*ofFile[i]);
        }
      }
      std::string list;
      for (size_t i = 0; i < ofFile.size(); ++i) {
        list += (i ? ", " : "") + std::to_string(i) + " '" + ofFile[i]->camera.name + "'";
      }
      in_.fail(*cameraFromToken_,
               "\"" + cameraFrom_ + "\" has no camera " +
                   (cameraName_.empty() ? std::to_string(cameraIndex_) : "'" + cameraName_ + "'") +
                   "; its cameras: " + (list.empty() ? "none" : list));
    }
    if (camera_ != nullptr) return;
    if (!offered.empty()) return useCamera(offered.front());
    if (!scene_.imports.empty()) {
      scene_.camera = framingCamera(scene_);
      return;
    }
    requireBlock(camera_, "camera", "camera { eye 0 1 -5  look_at 0 0 0 }");
  }

  // A camera of an animated file follows its node: the scene's animation places it at each time.
  void useCamera(const OfferedCamera& c) {
    scene_.camera = c.camera.camera;
    if (c.binding) editAnimation(scene_).camera = {*c.binding};
  }

  void image(const Token& keyword) {
    once(keyword, image_);
    ImageSpec& image = scene_.image;
    BlockReader block(in_, keyword, "image", {"width", "height", "output"});
    while (const Token* param = block.next()) {
      const std::string& name = param->text;
      if (name == "width") image.width = readInteger(in_, name, 1, kMaxImageSide);
      if (name == "height") image.height = readInteger(in_, name, 1, kMaxImageSide);
      if (name == "output") {
        image.output = readString(in_, name);
        checkOutput(image.output, block.valueToken("output"));
      }
    }
    block.require({"width", "height"});

    const int64_t pixels = int64_t{image.width} * image.height;
    if (pixels > kMaxImagePixels) {
      const size_t later = std::max(block.valueIndex("width"), block.valueIndex("height"));
      in_.fail(in_.at(later), "image too large: " + std::to_string(image.width) + " x " +
                                  std::to_string(image.height) + " = " + std::to_string(pixels) +
                                  " pixels; at most " + std::to_string(kMaxImagePixels) +
                                  " (2^28) fit in memory");
    }
  }

  void checkOutput(const std::string& output, const Token& token) {
    if (isSupportedImagePath(output)) return;
    std::string list;
    for (const std::string& e : supportedImageExtensions()) list += (list.empty() ? "" : ", ") + e;
    in_.fail(token, "'output' must be a file name ending in " + list + ", found " +
                        describe(token));
  }

  void environment(const Token& keyword) {
    once(keyword, environment_);
    Environment& environment = scene_.environment;
    BlockReader block(in_, keyword, "environment",
                      {"background", "ambient", "max_depth", "integrator", "max_bounces", "map",
                       "map_strength", "map_rotate"});
    while (const Token* param = block.next()) {
      const std::string& name = param->text;
      if (name == "background") environment.background = readColor(in_, name);
      if (name == "ambient") environment.ambient = readColor(in_, name);
      if (name == "max_depth") environment.maxDepth = readInteger(in_, name, 0, 64);
      if (name == "max_bounces") environment.maxBounces = readInteger(in_, name, 0, 1024);
      if (name == "map") environmentMap(*param);
      if (name == "map_strength") {
        environment.map.strength = readNumber(in_, name, Range::closed(0, 1e6));
      }
      if (name == "map_rotate") {
        environment.map.rotateDegrees = readNumber(in_, name, Range::closed(-1e6, 1e6));
      }
      if (name == "integrator") {
        const Token& value = in_.next();
        if (value.kind == TokenKind::Word && value.text == "hall") {
          environment.integrator = Integrator::hall;
        } else if (value.kind == TokenKind::Word && value.text == "path") {
          environment.integrator = Integrator::path;
        } else {
          in_.fail(value, "'integrator' must be hall (the paper's ray tracer) or path (the "
                          "physically based path tracer), found " + describe(value));
        }
      }
    }
  }

  // An environment map: read from its file (relative to the scene's), or taken from what the
  // master sent.
  void environmentMap(const Token& param) {
    const Token& value = in_.peek();
    std::string file = readString(in_, param.text);
    EnvironmentMap& map = scene_.environment.map;
    if (shipped_ != nullptr) {
      if (!shipped_->environmentMap) in_.fail(value, "no environment map was sent with the scene");
      map.image = shipped_->environmentMap;
      map.file = file;
      return;
    }
    std::filesystem::path path(file);
    if (path.is_relative()) path = imports_.directory / path;
    map.file = std::filesystem::absolute(path).lexically_normal().string();
    try {
      map.image = readEnvironmentMap(map.file);
    } catch (const InputError& e) {
      in_.fail(value, e.what());
    }
  }

  void sampling(const Token& keyword) {
    once(keyword, sampling_);
    Sampling& sampling = scene_.sampling;
    BlockReader block(in_, keyword, "sampling", {"samples", "drt"});
    while (const Token* param = block.next()) {
      const std::string& name = param->text;
      if (name == "samples") sampling.samplesPerPixel = readInteger(in_, name, 1, 4096);
      if (name == "drt") sampling.drtRate = readInteger(in_, name, 1, 64);
    }
  }

  void material() {
    const Token& name = in_.next();
    if (name.kind != TokenKind::Word) {
      in_.fail(name, "expected a material name after 'material', found " + describe(name));
    }
    if (!isName(name.text)) {
      in_.fail(name, "malformed material name " + describe(name) +
                         "; names consist of letters, digits and '_' and start with a letter "
                         "or '_'");
    }
    if (const auto found = materials_.find(name.text); found != materials_.end()) {
      in_.fail(name, "material '" + name.text + "' is already defined at " +
                         lineAndColumn(*found->second.name));
    }
    Material material = readSurface(in_, name, "material " + name.text, materials_);
    materials_.emplace(name.text, NamedMaterial{material, &name});
  }

  void light() {
    const Token& kind = in_.next();
    const std::string kinds = "point, sphere, rect, spot, directional";
    if (kind.kind != TokenKind::Word) {
      in_.fail(kind,
               "expected the kind of light (" + kinds + ") after 'light', found " + describe(kind));
    }
    Light light;
    // The keyed parameters of each kind of light, and how their values are read.
    const std::string title = "light " + kind.text;
    KeyFrames keys(title, FieldTrack::Target::light, {"position", "center", "direction",
                                                      "corner", "radius", "color"});
    const ValueReader read = [&](const std::string& name, double* out) {
      if (!isKeyedField(FieldTrack::Target::light, title, name)) {
        in_.fail(in_.at(in_.position() - 1), "'" + name + "' cannot be keyed in the '" + title +
                                                 "' block");
      }
      if (name == "color") return put(readColor(in_, name), out);
      if (name == "radius") return put(readNumber(in_, name, kSize), out);
      return put(readVector(in_, name, kCoordinate), out);
    };
    if (kind.text == "point") {
      PointLight point;
      BlockReader block(in_, kind, "light point", {"position", "color", "falloff", "key"});
      while (const Token* param = block.next()) {
        const std::string& name = param->text;
        if (name == "key") keys.read(in_, *param, read);
        if (name == "position") point.position = readVector(in_, name, kCoordinate);
        if (name == "color") light.color = readColor(in_, name);
        if (name == "falloff") light.falloff = readFalloff();
      }
      block.require({"position"});
      light.shape = point;
    } else if (kind.text == "sphere") {
      SphereLight sphere;
      BlockReader block(in_, kind, "light sphere", {"center", "radius", "color", "falloff", "key"});
      while (const Token* param = block.next()) {
        const std::string& name = param->text;
        if (name == "key") keys.read(in_, *param, read);
        if (name == "center") sphere.center = readVector(in_, name, kCoordinate);
        if (name == "radius") sphere.radius = readNumber(in_, name, kSize);
        if (name == "color") light.color = readColor(in_, name);
        if (name == "falloff") light.falloff = readFalloff();
      }
      block.require({"center", "radius"});
      light.shape = sphere;
    } else if (kind.text == "rect") {
      light.shape = rectLight(kind, light, keys, read);
    } else if (kind.text == "spot") {
      light.shape = spotLight(kind, light, keys, read);
    } else if (kind.text == "directional") {
      DirectionalLight sun;
      BlockReader block(in_, kind, "light directional", {"direction", "color", "key"});
      while (const Token* param = block.next()) {
        const std::string& name = param->text;
        if (name == "key") keys.read(in_, *param, read);
        if (name == "direction") sun.direction = readVector(in_, name, kCoordinate);
        if (name == "color") light.color = readColor(in_, name);
      }
      block.require({"direction"});
      sun.direction = unitDirection(sun.direction, block, "direction", "directional light");
      light.shape = sun;
    } else {
      in_.fail(kind, "unknown kind of light " + describe(kind) +
                         didYouMean(kind.text, {"point", "sphere", "rect", "spot", "directional"}) +
                         "; valid kinds: " + kinds);
    }
    const ValueReader base = [&](const std::string& name, double* out) {
      if (name == "color") return put(light.color, out);
      return std::visit(
          [&](const auto& shape) {
            using T = std::decay_t<decltype(shape)>;
            if constexpr (std::is_same_v<T, SphereLight>) {
              return name == "radius" ? put(shape.radius, out) : put(shape.center, out);
            } else if constexpr (std::is_same_v<T, RectLight>) {
              return put(shape.corner, out);
            } else if constexpr (std::is_same_v<T, DirectionalLight>) {
              return put(shape.direction, out);
            } else if constexpr (std::is_same_v<T, SpotLight>) {
              return name == "direction" ? put(shape.direction, out) : put(shape.position, out);
            } else {
              return put(shape.position, out);
            }
          },
          light.shape);
    };
    keys.finish(scene_, static_cast<uint32_t>(scene_.lights.size()), base);
    scene_.lights.push_back(light);
  }

  Falloff readFalloff() {
    const Token& value = in_.next();
    if (value.kind == TokenKind::Word && value.text == "none") return Falloff::none;
    if (value.kind == TokenKind::Word && value.text == "inverse_square") return Falloff::inverseSquare;
    in_.fail(value, "'falloff' is 'none' or 'inverse_square', found " + describe(value));
  }

  Vec3 unitDirection(const Vec3& v, const BlockReader& block, const char* param, const char* what) {
    if (!(length(v) > 0)) {
      in_.fail(block.valueToken(param), std::string("the ") + what + "'s '" + param +
                                            "' must not be zero, nor so short that its length "
                                            "underflows to zero");
    }
    return unitLength(v);
  }

  SpotLight spotLight(const Token& kind, Light& light, KeyFrames& keys, const ValueReader& read) {
    SpotLight spot;
    BlockReader block(in_, kind, "light spot",
                      {"position", "direction", "inner", "outer", "color", "falloff", "key"});
    while (const Token* param = block.next()) {
      const std::string& name = param->text;
      if (name == "key") keys.read(in_, *param, read);
      if (name == "position") spot.position = readVector(in_, name, kCoordinate);
      if (name == "direction") spot.direction = readVector(in_, name, kCoordinate);
      if (name == "inner") spot.innerDegrees = readNumber(in_, name, Range::closed(0, 90));
      if (name == "outer") spot.outerDegrees = readNumber(in_, name, Range::closed(0, 90));
      if (name == "color") light.color = readColor(in_, name);
      if (name == "falloff") light.falloff = readFalloff();
    }
    block.require({"position", "direction", "outer"});
    spot.direction = unitDirection(spot.direction, block, "direction", "spot light");
    if (!block.has("inner")) spot.innerDegrees = spot.outerDegrees;
    if (spot.innerDegrees > spot.outerDegrees) {
      in_.fail(block.valueToken("inner"), "the spot light's 'inner' angle must not exceed its "
                                          "'outer' one, found " + formatDouble(spot.innerDegrees) +
                                              " > " + formatDouble(spot.outerDegrees));
    }
    return spot;
  }

  RectLight rectLight(const Token& kind, Light& light, KeyFrames& keys, const ValueReader& read) {
    RectLight rect;
    BlockReader block(in_, kind, "light rect",
                      {"corner", "edge1", "edge2", "color", "falloff", "key"});
    while (const Token* param = block.next()) {
      const std::string& name = param->text;
      if (name == "key") keys.read(in_, *param, read);
      if (name == "corner") rect.corner = readVector(in_, name, kCoordinate);
      if (name == "edge1") rect.edge1 = readVector(in_, name, kCoordinate);
      if (name == "edge2") rect.edge2 = readVector(in_, name, kCoordinate);
      if (name == "color") light.color = readColor(in_, name);
      if (name == "falloff") light.falloff = readFalloff();
    }
    block.require({"corner", "edge1", "edge2"});
    const double area = length(cross(rect.edge1, rect.edge2));
    if (!(area > 1e-12 * length(rect.edge1) * length(rect.edge2))) {
      in_.fail(block.valueToken("edge2"),
               "the rect light's 'edge1' and 'edge2' are parallel or zero, so it has no area");
    }
    return rect;
  }

  // The parameter `surface`, shared by all objects.
  void surface(const Token& param, Material& material) {
    material = readSurface(in_, param, "surface", materials_);
  }

  void sphere(const Token& keyword) {
    Object object{SphereShape{}, Material{}};
    SphereShape& sphere = std::get<SphereShape>(object.shape);
    BlockReader block(in_, keyword, "sphere", {"center", "radius", "surface", "key"});
    KeyFrames keys("sphere", FieldTrack::Target::object, {"center", "radius"});
    const ValueReader read = [&](const std::string& name, double* out) {
      if (name == "radius") return put(readNumber(in_, name, kSize), out);
      return put(readVector(in_, name, kCoordinate), out);
    };
    while (const Token* param = block.next()) {
      const std::string& name = param->text;
      if (name == "key") keys.read(in_, *param, read);
      if (name == "center") sphere.center = readVector(in_, name, kCoordinate);
      if (name == "radius") sphere.radius = readNumber(in_, name, kSize);
      if (name == "surface") surface(*param, object.material);
    }
    block.require({"center", "radius"});
    keys.finish(scene_, static_cast<uint32_t>(scene_.objects.size()),
                [&](const std::string& name, double* out) {
                  return name == "radius" ? put(sphere.radius, out) : put(sphere.center, out);
                });
    scene_.objects.push_back(object);
  }

  void box(const Token& keyword) {
    Object object{BoxShape{}, Material{}};
    BoxShape& box = std::get<BoxShape>(object.shape);
    BlockReader block(in_, keyword, "box", {"min", "max", "surface", "key"});
    KeyFrames keys("box", FieldTrack::Target::object, {"min", "max"});
    const ValueReader read = [&](const std::string& name, double* out) {
      return put(readVector(in_, name, kCoordinate), out);
    };
    while (const Token* param = block.next()) {
      const std::string& name = param->text;
      if (name == "key") keys.read(in_, *param, read);
      if (name == "min") box.min = readVector(in_, name, kCoordinate);
      if (name == "max") box.max = readVector(in_, name, kCoordinate);
      if (name == "surface") surface(*param, object.material);
    }
    block.require({"min", "max"});
    static constexpr const char* kAxis[] = {"x", "y", "z"};
    for (int axis = 0; axis < 3; ++axis) {
      if (!(box.max[axis] > box.min[axis])) {
        in_.fail(block.valueToken("max", axis),
                 std::string("the box's 'max' must exceed its 'min' on every axis, but on ") +
                     kAxis[axis] + " max is " + formatDouble(box.max[axis]) + " and min is " +
                     formatDouble(box.min[axis]));
      }
    }
    keys.finish(scene_, static_cast<uint32_t>(scene_.objects.size()),
                [&](const std::string& name, double* out) {
                  return name == "min" ? put(box.min, out) : put(box.max, out);
                });
    scene_.objects.push_back(object);
  }

  void plane(const Token& keyword) {
    Object object{PlaneShape{}, Material{}};
    PlaneShape& plane = std::get<PlaneShape>(object.shape);
    BlockReader block(in_, keyword, "plane", {"point", "normal", "surface"});
    while (const Token* param = block.next()) {
      const std::string& name = param->text;
      if (name == "point") plane.point = readVector(in_, name, kCoordinate);
      if (name == "normal") plane.normal = readVector(in_, name, kCoordinate);
      if (name == "surface") surface(*param, object.material);
    }
    block.require({"point", "normal"});
    if (!(length(plane.normal) > 0)) {
      // Components of 1e-162 or less square to zero: too short to normalise, zero in effect.
      in_.fail(block.valueToken("normal"),
               "the plane's 'normal' must not be zero, nor so short that its length "
               "underflows to zero");
    }
    plane.normal = unitLength(plane.normal);
    scene_.objects.push_back(object);
  }

  void mesh(const Token& keyword) {
    scene_.objects.push_back(readMeshBlock(meshes_, keyword));
  }
  void triangle(const Token& keyword) {
    scene_.objects.push_back(readTriangleBlock(meshes_, keyword));
  }

  TokenStream in_;
  const ShippedAssets* shipped_;  // what the master sent in place of files, or null
  Scene scene_;
  MaterialTable materials_;
  MeshBlocks meshes_;
  const SceneReadOptions& options_;
  ModelCache models_;  // when the options bring no cache of their own
  ImportBlocks imports_;
  // A camera block's 'from': the file (absolute), the camera's name or index in it.
  std::string cameraFrom_, cameraName_;
  int cameraIndex_ = 0;
  const Token* cameraFromToken_ = nullptr;
  const Token* camera_ = nullptr;  // where each once-only block was given, if it was
  const Token* image_ = nullptr;
  const Token* environment_ = nullptr;
  const Token* sampling_ = nullptr;
};

}  // namespace

Scene parseScene(std::string_view text, const std::string& fileName,
                 const SceneReadOptions& options) {
  const SourceText source(text, fileName);
  return SceneParser(source, nullptr, options).run();
}

Scene parseScene(std::string_view text, const std::string& fileName,
                 const ShippedAssets& shipped) {
  const SourceText source(text, fileName);
  const SceneReadOptions options;
  Scene scene = SceneParser(source, &shipped, options).run();
  size_t meshes = 0;
  for (const Object& o : scene.objects) {
    const auto* m = std::get_if<MeshShape>(&o.shape);
    meshes += m != nullptr && !m->source.file.empty() ? 1 : 0;
  }
  if (meshes != shipped.meshBlocks.size() || scene.imports.size() != shipped.imports.size()) {
    throw InputError("the scene has " + std::to_string(meshes) + " meshes and " +
                     std::to_string(scene.imports.size()) + " imports but " +
                     std::to_string(shipped.meshBlocks.size()) + " and " +
                     std::to_string(shipped.imports.size()) + " were sent with it");
  }
  // The imports' rigs came in the pack (the text has only its own keys): put back with them.
  try {
    addRig(scene, shipped.rig);
  } catch (const std::invalid_argument& e) {
    throw InputError(std::string("the animation sent with the scene does not fit it: ") + e.what());
  }
  return scene;
}

}  // namespace prt
