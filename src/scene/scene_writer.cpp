// writeScene: a Scene as .scene text. Numbers are written in their shortest round-trip form,
// so parsing the text gives back the very same doubles; every field of the scene-wide blocks
// is written, while surfaces list only the fields that differ from Material's defaults.

#include <bit>
#include <cmath>
#include <cstdint>
#include <string>
#include <type_traits>
#include <variant>

#include "core/check.h"
#include "scene/key_frames.h"
#include "scene/number_text.h"
#include "scene/scene_file.h"

namespace prt {
namespace {

// Bitwise, so that -0.0 is not taken for a default 0.0 and dropped.
bool sameBits(double a, double b) {
  return std::bit_cast<uint64_t>(a) == std::bit_cast<uint64_t>(b);
}
bool sameBits(const Vec3& a, const Vec3& b) {
  return sameBits(a.x, b.x) && sameBits(a.y, b.y) && sameBits(a.z, b.z);
}

class Writer {
 public:
  std::string take() { return std::move(out_); }

  void open(const std::string& header) { out_ += header + " {"; }
  void close() { out_ += " }\n"; }

  void number(const char* name, double value) {
    out_ += ' ';
    out_ += name;
    out_ += ' ';
    out_ += formatDouble(value);
  }
  void integer(const char* name, int value) {
    out_ += ' ';
    out_ += name;
    out_ += ' ';
    out_ += std::to_string(value);
  }
  void vector(const char* name, const Vec3& value) {
    out_ += ' ';
    out_ += name;
    for (int axis = 0; axis < 3; ++axis) {
      out_ += ' ';
      out_ += formatDouble(value[axis]);
    }
  }
  void string(const char* name, const std::string& value) {
    out_ += ' ';
    out_ += name;
    out_ += " \"";
    for (const char c : value) {
      if (c == '"' || c == '\\') out_ += '\\';
      out_ += c;
    }
    out_ += '"';
  }

  void numberUnlessDefault(const char* name, double value, double defaultValue) {
    if (!sameBits(value, defaultValue)) number(name, value);
  }
  void raw(const std::string& text) { out_ += text; }

 private:
  std::string out_;
};

// The block's `key` entries, if it is animated.
void writeKeys(Writer& out, const Scene& scene, FieldTrack::Target target, size_t index) {
  for (const KeyGroup& group : keyGroupsOf(scene, target, static_cast<uint32_t>(index))) {
    out.raw(" key " + formatDouble(group.time) + " {");
    for (size_t i = 0; i < group.tracks.size(); ++i) {
      const Curve& curve = group.tracks[i]->curve;
      const double* v = curve.values.data() + group.keyIndex[i] * curve.width;
      const char* name = group.tracks[i]->field.c_str();
      if (curve.width == 1) {
        out.number(name, v[0]);
      } else {
        out.vector(name, {v[0], v[1], v[2]});
      }
    }
    out.raw(" }");
  }
}

// The fields of `material` that differ from Material's defaults, as " name value ..." text.
std::string surfaceFields(const Material& material) {
  const Material defaults;
  Writer out;
  if (!sameBits(material.color, defaults.color)) out.vector("color", material.color);
  out.numberUnlessDefault("ambient", material.ambient, defaults.ambient);
  out.numberUnlessDefault("diffuse", material.diffuse, defaults.diffuse);
  out.numberUnlessDefault("specular", material.specular, defaults.specular);
  out.numberUnlessDefault("phong", material.phongExponent, defaults.phongExponent);
  out.numberUnlessDefault("reflect", material.reflectivity, defaults.reflectivity);
  out.numberUnlessDefault("transmit", material.transmissivity, defaults.transmissivity);
  out.numberUnlessDefault("ior", material.ior, defaults.ior);
  out.numberUnlessDefault("gloss", material.glossDegrees, defaults.glossDegrees);
  out.numberUnlessDefault("translucency", material.translucencyDegrees,
                          defaults.translucencyDegrees);
  out.numberUnlessDefault("metallic", material.metallic, defaults.metallic);
  if (!sameBits(material.emission, defaults.emission)) out.vector("emission", material.emission);
  const PbrSurface& pbr = material.pbr;
  if (pbr.given) {
    out.number("roughness", pbr.roughness);
    out.number("transmission", pbr.transmission);
    out.number("specular_level", pbr.specularLevel);
    out.number("coverage", pbr.coverage);
    if (!sameBits(pbr.attenuationColor, defaults.pbr.attenuationColor)) {
      out.vector("attenuation_color", pbr.attenuationColor);
    }
    if (std::isfinite(pbr.attenuationDistance)) {
      out.number("attenuation_distance", pbr.attenuationDistance);
    }
    if (pbr.thinWalled) out.raw(" thin_walled");
    out.numberUnlessDefault("specular_weight", pbr.specularWeight, defaults.pbr.specularWeight);
    if (!sameBits(pbr.specularColor, defaults.pbr.specularColor)) {
      out.vector("specular_color", pbr.specularColor);
    }
    out.numberUnlessDefault("clearcoat", pbr.clearcoat, defaults.pbr.clearcoat);
    out.numberUnlessDefault("clearcoat_roughness", pbr.clearcoatRoughness,
                            defaults.pbr.clearcoatRoughness);
  }
  // `ior` above sets both indices; the path tracer's own is written when it differs from what
  // reading that back gives.
  const double readIor = sameBits(material.ior, defaults.ior) ? defaults.pbr.ior : material.ior;
  if (!sameBits(pbr.ior, readIor)) out.number("pbr_ior", pbr.ior);
  return out.take();
}

void writeLight(Writer& out, const Scene& scene, size_t index) {
  const Light& light = scene.lights[index];
  std::visit(
      [&](const auto& shape) {
        using T = std::decay_t<decltype(shape)>;
        if constexpr (std::is_same_v<T, PointLight>) {
          out.open("light point");
          out.vector("position", shape.position);
        } else if constexpr (std::is_same_v<T, SphereLight>) {
          out.open("light sphere");
          out.vector("center", shape.center);
          out.number("radius", shape.radius);
        } else if constexpr (std::is_same_v<T, SpotLight>) {
          out.open("light spot");
          out.vector("position", shape.position);
          out.vector("direction", shape.direction);
          out.number("inner", shape.innerDegrees);
          out.number("outer", shape.outerDegrees);
        } else if constexpr (std::is_same_v<T, DirectionalLight>) {
          out.open("light directional");
          out.vector("direction", shape.direction);
        } else {
          static_assert(std::is_same_v<T, RectLight>);
          out.open("light rect");
          out.vector("corner", shape.corner);
          out.vector("edge1", shape.edge1);
          out.vector("edge2", shape.edge2);
        }
      },
      light.shape);
  out.vector("color", light.color);
  if (light.falloff == Falloff::inverseSquare) out.raw(" falloff inverse_square");
  writeKeys(out, scene, FieldTrack::Target::light, index);
  out.close();
}

void writeImport(Writer& out, const Scene& scene, size_t index) {
  const ImportSource& import = scene.imports[index];
  out.open("import");
  out.string("file", import.file);
  out.vector("scale", import.scale);
  out.vector("rotate", import.rotateDegrees);
  out.vector("translate", import.translate);
  // Its lights were written with the others, as light blocks.
  out.raw(" no_lights");
  writeKeys(out, scene, FieldTrack::Target::import, index);
  out.close();
}

void writeObject(Writer& out, const Scene& scene, size_t index) {
  const Object& object = scene.objects[index];
  std::visit(
      [&](const auto& shape) {
        using T = std::decay_t<decltype(shape)>;
        if constexpr (std::is_same_v<T, SphereShape>) {
          out.open("sphere");
          out.vector("center", shape.center);
          out.number("radius", shape.radius);
        } else if constexpr (std::is_same_v<T, BoxShape>) {
          out.open("box");
          out.vector("min", shape.min);
          out.vector("max", shape.max);
        } else if constexpr (std::is_same_v<T, PlaneShape>) {
          out.open("plane");
          out.vector("point", shape.point);
          out.vector("normal", shape.normal);
        } else if constexpr (std::is_same_v<T, InstanceShape>) {
          PRT_CHECK(false);  // an instance is written by the import block that placed it
        } else {
          static_assert(std::is_same_v<T, MeshShape>);
          const MeshSource& source = shape.source;
          if (source.file.empty()) {  // a `triangle` block: one triangle, three vertices
            out.open("triangle");
            out.vector("vertices", shape.mesh->vertices[0]);
            out.vector("", shape.mesh->vertices[1]);
            out.vector("", shape.mesh->vertices[2]);
          } else {
            out.open("mesh");
            out.string("file", source.file);
            out.vector("scale", source.scale);
            out.vector("rotate", source.rotateDegrees);
            out.vector("translate", source.translate);
            if (source.smooth) out.raw(" smooth");
          }
        }
      },
      object.shape);
  const std::string fields = surfaceFields(object.material);
  if (!fields.empty()) out.raw(" surface {" + fields + " }");
  writeKeys(out, scene, FieldTrack::Target::object, index);
  out.close();
}

}  // namespace

std::string writeScene(const Scene& scene) {
  Writer out;
  const Camera& camera = scene.camera;
  out.open("camera");
  out.vector("eye", camera.eye);
  out.vector("look_at", camera.lookAt);
  out.vector("up", camera.up);
  out.number("fov", camera.fovDegrees);
  if (camera.orthoHeight > 0) out.number("ortho_height", camera.orthoHeight);
  writeKeys(out, scene, FieldTrack::Target::camera, 0);
  out.close();

  out.open("image");
  out.integer("width", scene.image.width);
  out.integer("height", scene.image.height);
  out.string("output", scene.image.output);
  out.close();

  out.open("environment");
  out.vector("background", scene.environment.background);
  out.vector("ambient", scene.environment.ambient);
  out.integer("max_depth", scene.environment.maxDepth);
  if (scene.environment.integrator == Integrator::path) out.raw(" integrator path");
  if (scene.environment.maxBounces != Environment{}.maxBounces) {
    out.integer("max_bounces", scene.environment.maxBounces);
  }
  if (const EnvironmentMap& map = scene.environment.map; map.image) {
    out.string("map", map.file);
    if (map.strength != 1) out.number("map_strength", map.strength);
    if (map.rotateDegrees != 0) out.number("map_rotate", map.rotateDegrees);
  }
  out.close();

  out.open("sampling");
  out.integer("samples", scene.sampling.samplesPerPixel);
  out.integer("drt", scene.sampling.drtRate);
  out.close();

  for (size_t i = 0; i < scene.lights.size(); ++i) writeLight(out, scene, i);
  // Each import where its objects began, in place of them.
  auto import = scene.imports.begin();
  for (size_t i = 0; i < scene.objects.size(); ++i) {
    if (import != scene.imports.end() && import->firstObject == i) {
      writeImport(out, scene, static_cast<size_t>(import - scene.imports.begin()));
      i += import->objectCount - 1;
      ++import;
      continue;
    }
    writeObject(out, scene, i);
  }
  return out.take();
}

}  // namespace prt
