#include "export/pov_exporter.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <functional>
#include <map>
#include <numbers>
#include <variant>

#include "core/check.h"
#include "core/overloaded.h"
#include "trace/shapes.h"

namespace prt {
namespace {

constexpr double kRadiansPerDegree = std::numbers::pi / 180.0;

// POV-Ray scales a transparent surface's ambient and diffuse terms by its opacity,
// 1 - transmit; PRT does not. The finish divides them back out, so the opacity must not
// reach 0 while there is ambient or diffuse light to show (docs/povray-mapping.md).
constexpr double kMaxTransmitWithLocalLight = 0.999;

// Twelve significant digits: differences far below a pixel or an 8-bit code, without the
// noise of 17 digits in every number.
std::string num(double v) {
  if (v == 0) return "0";  // also turns -0 into 0
  char buffer[32];
  std::snprintf(buffer, sizeof buffer, "%.12g", v);
  return buffer;
}

// Appended piece by piece: GCC 12 reports a false -Wrestrict for "<" + std::string&&.
std::string vec(const Vec3& v) {
  std::string s(1, '<');
  s += num(v.x);
  s += ", ";
  s += num(v.y);
  s += ", ";
  s += num(v.z);
  s += '>';
  return s;
}

std::string rgb(const Color& c) {
  return "rgb " + vec(c);
}

void line(std::string& out, int indent, const std::string& text) {
  out.append(static_cast<size_t>(indent) * 2, ' ');
  out += text;
  out += '\n';
}

void writeHeader(std::string& out, const Scene& scene, const RenderSettings& settings,
                 const PovOptions& options) {
  PovRun run;
  run.sceneFile = options.fileName;
  const size_t dot = options.fileName.rfind('.');
  run.imageFile = options.fileName.substr(0, dot == 0 ? std::string::npos : dot) + ".png";
  run.width = scene.image.width;
  run.height = scene.image.height;
  run.samplesPerPixel = settings.samplesPerPixel;
  std::string command = "povray";
  for (const std::string& argument : povrayArguments(run)) command += " " + argument;

  line(out, 0, "// Exported from a PRT scene for POV-Ray 3.7; see docs/povray-mapping.md.");
  std::string image = "// Image: " + std::to_string(scene.image.width) + " x ";
  image += std::to_string(scene.image.height) + " pixels (the camera's aspect ratio); PRT ";
  image += std::to_string(settings.samplesPerPixel) + " spp, DRT ";
  image += std::to_string(settings.drtRate) + ".";
  line(out, 0, image);
  const int depth = povAntialiasDepth(settings.samplesPerPixel);
  if (depth > 0) {
    const std::string n = std::to_string(depth);
    line(out, 0,
         "// POV-Ray antialiasing: " + n + " x " + n +
             " + 1 = " + std::to_string(depth * depth + 1) + " samples per pixel.");
  }
  line(out, 0, "// Render with:");
  line(out, 0, "//   " + command);
  line(out, 0, "#version 3.7;");
  out += '\n';
}

void writeGlobalSettings(std::string& out, const Scene& scene) {
  const Environment& env = scene.environment;
  line(out, 0, "global_settings {");
  line(out, 1, "assumed_gamma 1.0  // linear maths, like PRT; the output file is sRGB-encoded");
  line(out, 1, "ambient_light " + rgb(env.ambient) + "  // Hall's I_a");
  line(out, 1,
       "max_trace_level " + std::to_string(povMaxTraceLevel(env.maxDepth)) + "  // PRT max_depth " +
           std::to_string(env.maxDepth) + " traces generations 0.." + std::to_string(env.maxDepth));
  line(out, 1, "adc_bailout 0  // PRT drops only rays below 2^-16 of a pixel, which change no 8-bit pixel");
  line(out, 0, "}");
  line(out, 0, "background { " + rgb(env.background) + " }");
  out += '\n';
}

// PRT's pinhole camera (trace/camera.cpp) in POV-Ray's usual form. Both are left-handed
// (right = up x forward), both shoot one ray through each pixel's centre, and POV-Ray's
// `angle` is the horizontal field of view: with right = aspect and up = 1 the image plane is
// PRT's. `sky` is PRT's approximate up vector, which look_at orthogonalises as PRT does.
void writeCamera(std::string& out, const Scene& scene) {
  const Camera& c = scene.camera;
  const double aspect = static_cast<double>(scene.image.width) / scene.image.height;
  if (c.orthoHeight > 0) {  // parallel rays: right and up span the image plane
    line(out, 0, "camera {  // PRT: orthographic, " + num(c.orthoHeight) + " units high");
    line(out, 1, "orthographic");
    line(out, 1, "location " + vec(c.eye));
    line(out, 1, "right x*" + num(c.orthoHeight * aspect));
    line(out, 1, "up y*" + num(c.orthoHeight));
    line(out, 1, "sky " + vec(c.up));
    line(out, 1, "look_at " + vec(c.lookAt));
    line(out, 0, "}");
    out += '\n';
    return;
  }
  line(out, 0, "camera {  // PRT: vertical field of view " + num(c.fovDegrees) + " degrees");
  line(out, 1, "perspective");
  line(out, 1, "location " + vec(c.eye));
  line(out, 1, "right x*" + num(aspect) + "  // width / height");
  line(out, 1, "up y");
  line(out, 1, "sky " + vec(c.up));
  line(out, 1, "angle " + num(horizontalFovDegrees(c.fovDegrees, aspect)) + "  // horizontal");
  line(out, 1, "look_at " + vec(c.lookAt));
  line(out, 0, "}");
  out += '\n';
}

// POV-Ray's light fading, 2 / (1 + (d / fade_distance)^2), is 2 fade_distance^2 / d^2 to a
// relative 1e-6 at a thousand fade distances: the inverse-square law, once the colour is
// divided by 2 fade_distance^2.
constexpr double kFadeDistance = 1e-3;

std::string fading(const Light& light) {
  if (light.falloff != Falloff::inverseSquare) return "";
  return " fade_distance " + num(kFadeDistance) + " fade_power 2";
}
Color povColor(const Light& light) {
  return light.falloff == Falloff::inverseSquare
             ? light.color / (2 * kFadeDistance * kFadeDistance)
             : light.color;
}

void writeLight(std::string& out, const Light& light, int grid, const Bounds& scene) {
  if (const auto* p = std::get_if<PointLight>(&light.shape)) {
    line(out, 0, "light_source { " + vec(p->position) + " color " + rgb(povColor(light)) +
                     fading(light) + " }");
    return;
  }
  if (const auto* spot = std::get_if<SpotLight>(&light.shape)) {
    // POV-Ray fades a spot between `radius` and `falloff` by the same smooth step of the
    // cosines as PRT (tightness 0: no further narrowing).
    line(out, 0, "light_source { " + vec(spot->position) + " color " + rgb(povColor(light)) +
                     fading(light));
    line(out, 1, "spotlight point_at " + vec(spot->position + spot->direction) + " radius " +
                     num(spot->innerDegrees) + " falloff " + num(spot->outerDegrees) +
                     " tightness 0");
    line(out, 0, "}");
    return;
  }
  if (const auto* sun = std::get_if<DirectionalLight>(&light.shape)) {
    // Parallel rays from far beyond everything, along the direction.
    const Vec3 center = scene.lo.x <= scene.hi.x ? scene.centroid() : Vec3();
    const double reach = scene.lo.x <= scene.hi.x ? 1e3 * (1 + length(scene.diagonal())) : 1e6;
    line(out, 0, "light_source { " + vec(center - reach * sun->direction) + " color " +
                     rgb(light.color) + " parallel point_at " + vec(center) + " }");
    return;
  }
  const auto* s = std::get_if<SphereLight>(&light.shape);
  const auto* r = std::get_if<RectLight>(&light.shape);
  const Vec3 center = s ? s->center : r->corner + 0.5 * r->edge1 + 0.5 * r->edge2;
  line(out, 0,
       s ? "light_source {  // sphere light, radius " + num(s->radius)
         : "light_source {  // rectangle light, corner " + vec(r->corner));
  line(out, 1, vec(center) + " color " + rgb(povColor(light)) + fading(light));
  if (grid <= 1) {
    line(out, 1, "// one sample: a point light at the centre");
    line(out, 0, "}");
    return;
  }
  // POV-Ray's area-light sampling recursively splits the grid and averages the corners of
  // each part; `adaptive` at the depth of the recursion traces every sample. With a grid of
  // 2^k + 1 samples that average is the trapezoid rule over the light's whole extent.
  const int levels = static_cast<int>(std::ceil(std::log2(grid - 1)));
  const std::string sampling = std::to_string(grid) + ", " + std::to_string(grid) + " adaptive " +
                               std::to_string(levels) + " area_illumination on";
  if (s) {
    // PRT samples the disc of the sphere that faces the shaded point: circular + orient.
    line(out, 1,
         "area_light " + vec(Vec3(2 * s->radius, 0, 0)) + ", " + vec(Vec3(0, 2 * s->radius, 0)) +
             ", " + sampling + " circular orient");
  } else {
    line(out, 1, "area_light " + vec(r->edge1) + ", " + vec(r->edge2) + ", " + sampling);
  }
  line(out, 0, "}");
}

// Hall's surface in POV-Ray terms. POV-Ray multiplies ambient and diffuse (not phong) by the
// opacity 1 - transmit, so both are divided by it here; transmit itself matches k_t for the
// transmitted ray and for shadow rays (POV-Ray, like PRT, multiplies the light by transmit at
// every surface crossed). `pigment`, when given, replaces the material's colour (an image map,
// or a vertex's colour); it must already carry the transmit. POV-Ray multiplies emission by
// the pigment, PRT does not: the emission is divided by the colour, or, on a surface lit by
// nothing else, becomes the pigment.
void writeMaterial(std::string& out, const Material& m, const std::string& pigment = "",
                   int indent = 1) {
  const bool localLight = m.ambient > 0 || m.diffuse > 0;
  const double transmit =
      localLight ? std::min(m.transmissivity, kMaxTransmitWithLocalLight) : m.transmissivity;
  const double opacity = 1.0 - transmit;
  const double ambient = localLight ? m.ambient / opacity : 0.0;
  const double diffuse = localLight ? m.diffuse / opacity : 0.0;
  const bool emits = m.emission != Color();
  const bool unlit = emits && !localLight && m.specular == 0 && pigment.empty();

  line(out, indent, "texture {");
  if (unlit) {
    line(out, indent + 1, "pigment { " + rgb(m.emission) + " }");
  } else if (!pigment.empty()) {
    line(out, indent + 1, pigment);
  } else if (transmit > 0) {
    line(out, indent + 1,
         "pigment { rgbt <" + num(m.color.x) + ", " + num(m.color.y) + ", " + num(m.color.z) +
             ", " + num(transmit) + "> }");
  } else {
    line(out, indent + 1, "pigment { " + rgb(m.color) + " }");
  }
  std::string finish =
      "finish { ambient " + num(ambient) + " diffuse " + num(diffuse) + " brilliance 1";
  if (unlit) {
    finish += " emission 1";
  } else if (emits) {
    auto over = [](double e, double c) { return c > 0 ? e / c : 0.0; };
    finish += " emission " + rgb(Color(over(m.emission.x, m.color.x), over(m.emission.y, m.color.y),
                                       over(m.emission.z, m.color.z)));
  }
  const std::string metallic = m.metallic > 0 ? " metallic " + num(m.metallic) : "";
  if (m.specular > 0) {
    finish += " phong " + num(m.specular) + " phong_size " + num(m.phongExponent) + metallic;
  }
  if (m.reflectivity > 0) finish += " reflection { " + num(m.reflectivity) + metallic + " }";
  line(out, indent + 1, finish + " }");
  line(out, indent, "}");
  if (indent > 1) return;  // a vertex's texture: the object has the interior
  if (m.transmissivity > 0) line(out, indent, "interior { ior " + num(m.ior) + " }");
  if (m.glossDegrees > 0 && m.reflectivity > 0) {
    line(out, indent, "// gloss " + num(m.glossDegrees) + " degrees: POV-Ray reflects as a mirror");
  }
  if (m.translucencyDegrees > 0 && m.transmissivity > 0) {
    line(out, indent,
         "// translucency " + num(m.translucencyDegrees) +
             " degrees: POV-Ray transmits without blur");
  }
  if (transmit != m.transmissivity) {
    line(out, indent,
         "// transmit " + num(m.transmissivity) + " capped at " + num(transmit) +
             " to keep ambient and diffuse");
  }
}

// Rows of items, a few to a line.
void rows(std::string& out, int indent, size_t count, const std::function<std::string(size_t)>& item) {
  std::string row;
  for (size_t i = 0; i < count; ++i) {
    row += item(i);
    if (i + 1 < count) row += ", ";
    if (row.size() > 90 || i + 1 == count) {
      line(out, indent, row);
      row.clear();
    }
  }
}

std::string triple(const std::array<uint32_t, 3>& t) {
  return "<" + std::to_string(t[0]) + ", " + std::to_string(t[1]) + ", " + std::to_string(t[2]) + ">";
}

// What a mesh2 carries besides its triangles: texture coordinates (already mapped by the
// material's transform, in POV-Ray's v-up convention), and per-vertex textures (the material
// at each vertex's colour).
struct MeshExtras {
  const UvTransform* uv = nullptr;    // write the mesh's uv_vectors through this
  const Material* vertexColors = nullptr;  // write a texture per vertex of this material
};

// POV-Ray's mesh2: the vertices (and normals, for smooth shading) once each, then the
// triangles by index. POV-Ray, like PRT, refracts at each triangle a ray crosses.
void writeMesh(std::string& out, const TriangleMesh& mesh, const MeshExtras& extras = {}) {
  line(out, 0, "mesh2 {");
  auto vectors = [&](const char* name, const std::vector<Vec3>& values) {
    line(out, 1, std::string(name) + " { " + std::to_string(values.size()) + ",");
    rows(out, 2, values.size(), [&](size_t i) { return vec(values[i]); });
    line(out, 1, "}");
  };
  vectors("vertex_vectors", mesh.vertices);
  // A zero normal (a vertex whose faces cancel) would make POV-Ray's interpolation undefined:
  // the mesh is then written flat.
  bool smooth = !mesh.normals.empty();
  for (const Vec3& n : mesh.normals) smooth = smooth && n != Vec3();
  if (smooth) vectors("normal_vectors", mesh.normals);
  const bool uvs = extras.uv != nullptr && !mesh.uvs.empty();
  if (uvs) {
    line(out, 1, "uv_vectors { " + std::to_string(mesh.uvs.size()) + ",");
    const auto& t = extras.uv->m;
    rows(out, 2, mesh.uvs.size(), [&](size_t i) {
      const double u = mesh.uvs[i][0], v = mesh.uvs[i][1];
      const double a = t[0] * u + t[1] * v + t[2], b = t[3] * u + t[4] * v + t[5];
      return "<" + num(a) + ", " + num(1 - b) + ">";  // v down (PRT) to v up (POV-Ray)
    });
    line(out, 1, "}");
  }
  const bool perVertex = extras.vertexColors != nullptr && !mesh.colors.empty();
  if (perVertex) {
    line(out, 1, "texture_list { " + std::to_string(mesh.colors.size()) + ",");
    for (const auto& c : mesh.colors) {
      Material at = *extras.vertexColors;
      at.color = at.color * Color(c[0], c[1], c[2]);
      const double transmit = std::min(at.transmissivity, kMaxTransmitWithLocalLight);
      writeMaterial(out, at,
                    transmit > 0 ? "pigment { rgbt <" + num(at.color.x) + ", " + num(at.color.y) +
                                       ", " + num(at.color.z) + ", " + num(transmit) + "> }"
                                 : "pigment { " + rgb(at.color) + " }",
                    2);
    }
    line(out, 1, "}");
  }
  line(out, 1, "face_indices { " + std::to_string(mesh.triangles.size()) + ",");
  rows(out, 2, mesh.triangles.size(), [&](size_t i) {
    const auto& t = mesh.triangles[i];
    return perVertex ? triple(t) + ", " + std::to_string(t[0]) + ", " + std::to_string(t[1]) +
                           ", " + std::to_string(t[2])
                     : triple(t);
  });
  line(out, 1, "}");
  if (uvs) {  // the uv coordinates of each corner are those of its vertex
    line(out, 1, "uv_indices { " + std::to_string(mesh.triangles.size()) + ",");
    rows(out, 2, mesh.triangles.size(), [&](size_t i) { return triple(mesh.triangles[i]); });
    line(out, 1, "}");
  }
}

// The export of one scene: declared meshes and written texture images kept so that each is
// written once.
class PovWriter {
 public:
  PovWriter(const Scene& scene, const PovOptions& options) : scene_(scene), options_(options) {
    const std::string& f = options.fileName;
    const size_t dot = f.rfind('.');
    stem_ = f.substr(0, dot == 0 || dot == std::string::npos ? f.size() : dot);
  }

  void object(std::string& out, const Object& object) {
    if (const auto* i = std::get_if<InstanceShape>(&object.shape)) {
      return instance(out, *i, object.material);  // writes its own material and braces
    }
    std::visit(Overloaded{
                   [&](const SphereShape& s) {
                     line(out, 0, "sphere {");
                     line(out, 1, vec(s.center) + ", " + num(s.radius));
                   },
                   [&](const BoxShape& b) {
                     line(out, 0, "box {");
                     line(out, 1, vec(b.min) + ", " + vec(b.max));
                   },
                   [&](const MeshShape& m) { writeMesh(out, *m.mesh); },
                   [&](const PlaneShape& p) {
                     const Vec3 n = normalize(p.normal);
                     // POV-Ray's plane is the solid half-space below it, visible from both
                     // sides; PRT's is visible, and casts shadows, only from the side its
                     // normal faces.
                     line(out, 0, "plane {  // through " + vec(p.point) + "; PRT's plane is one-sided");
                     line(out, 1, vec(n) + ", " + num(dot(p.point, n)));
                   },
                   [](const InstanceShape&) {},  // above
               },
               object.shape);
    writeMaterial(out, object.material);
    line(out, 0, "}");
  }

  std::vector<PovImage> takeImages() { return std::move(images_); }

 private:
  // A mesh placed by a matrix, its mesh2 declared once for each way it is textured.
  void instance(std::string& out, const InstanceShape& instance, const Material& m) {
    const TriangleMesh& mesh = *instance.mesh;
    const bool textured = m.colorTexture.texture >= 0 && !mesh.uvs.empty();
    const bool perVertex = !mesh.colors.empty();
    MeshExtras extras;
    const UvTransform uv = textured ? povUv(m.colorTexture) : UvTransform();
    if (textured) extras.uv = &uv;
    if (perVertex) extras.vertexColors = &m;
    std::string key = std::to_string(reinterpret_cast<uintptr_t>(&mesh));
    if (textured) {
      for (const double v : uv.m) key += " " + num(v);
    }
    if (perVertex) key += " material " + std::to_string(declared_.size());  // its own each time
    auto [at, added] = declared_.try_emplace(key, "PRT_mesh_" + std::to_string(declared_.size()));
    if (added) {
      std::string text;
      writeMesh(text, mesh, extras);
      line(text, 0, "}");
      out += "#declare " + at->second + " =\n" + text;
    }
    const auto& t = instance.worldFromMesh.m;
    line(out, 0, "object { " + at->second);
    // POV-Ray's rows are the images of x, y and z, then the translation.
    line(out, 1, "matrix <" + num(t[0][0]) + ", " + num(t[1][0]) + ", " + num(t[2][0]) + ", " +
                     num(t[0][1]) + ", " + num(t[1][1]) + ", " + num(t[2][1]) + ", " +
                     num(t[0][2]) + ", " + num(t[1][2]) + ", " + num(t[2][2]) + ", " +
                     num(t[0][3]) + ", " + num(t[1][3]) + ", " + num(t[2][3]) + ">");
    if (!perVertex) writeMaterial(out, m, textured ? imagePigment(m) : "");
    else if (m.transmissivity > 0) line(out, 1, "interior { ior " + num(m.ior) + " }");
    if (m.emissionTexture.texture >= 0) {
      line(out, 1, "// emission texture: POV-Ray gets the emission colour only");
    }
    line(out, 0, "}");
  }

  // POV-Ray's image maps repeat, and it has no mirrored repeat: a texture mirrored along u
  // (v) is written with its mirror image beside (below) it, twice as wide (high), and its
  // coordinates are halved along that axis, which repeats as the mirrored texture does.
  UvTransform povUv(const TextureRef& ref) const {
    const Texture& texture = scene_.textures[static_cast<size_t>(ref.texture)];
    UvTransform uv = ref.uv;
    for (int i = 0; i < 3; ++i) {
      if (texture.wrapU == TextureWrap::mirror) uv.m[static_cast<size_t>(i)] *= 0.5;
      if (texture.wrapV == TextureWrap::mirror) uv.m[static_cast<size_t>(3 + i)] *= 0.5;
    }
    return uv;
  }

  // The material's texture times its colour as an image map: POV-Ray's pigments cannot be
  // multiplied by a colour, so the product is written as the image (with its mirror images
  // for a mirrored texture, povUv).
  std::string imagePigment(const Material& m) {
    const Texture& texture = scene_.textures[static_cast<size_t>(m.colorTexture.texture)];
    std::string key = std::to_string(m.colorTexture.texture) + " " + vec(m.color);
    auto [at, added] = imageFiles_.try_emplace(key, "");
    if (added) {
      at->second = stem_ + "_texture" + std::to_string(images_.size()) + ".png";
      const TextureImage& source = *texture.image;
      const bool mirrorU = texture.wrapU == TextureWrap::mirror;
      const bool mirrorV = texture.wrapV == TextureWrap::mirror;
      const int width = source.width, height = source.height;
      Image image(mirrorU ? 2 * width : width, mirrorV ? 2 * height : height);
      for (int y = 0; y < image.height(); ++y) {
        for (int x = 0; x < image.width(); ++x) {
          const int sx = x < width ? x : 2 * width - 1 - x;
          const int sy = y < height ? y : 2 * height - 1 - y;
          const size_t i = static_cast<size_t>(sy) * static_cast<size_t>(width) + static_cast<size_t>(sx);
          const uint8_t* p = source.texels.data() + i * static_cast<size_t>(source.channels);
          const Color c = source.channels >= 3
                              ? Color(srgbToLinear(p[0]), srgbToLinear(p[1]), srgbToLinear(p[2]))
                              : Color(srgbToLinear(p[0]));
          image.set(x, y, c * m.color);
        }
      }
      images_.push_back({at->second, std::move(image)});
    }
    const bool localLight = m.ambient > 0 || m.diffuse > 0;
    const double transmit =
        localLight ? std::min(m.transmissivity, kMaxTransmitWithLocalLight) : m.transmissivity;
    std::string map = "pigment { uv_mapping image_map { png \"" + at->second + "\" interpolate 2";
    if (transmit > 0) map += " transmit all " + num(transmit);
    map += " } }";
    if (texture.wrapU == TextureWrap::clamp || texture.wrapV == TextureWrap::clamp) {
      map += "  // PRT clamps this texture; POV-Ray repeats it";
    }
    return map;
  }

  const Scene& scene_;
  const PovOptions& options_;
  std::string stem_;
  std::map<std::string, std::string> declared_;    // mesh and texturing -> declared name
  std::map<std::string, std::string> imageFiles_;  // texture and colour -> file name
  std::vector<PovImage> images_;
};

}  // namespace

double horizontalFovDegrees(double verticalDegrees, double widthOverHeight) {
  const double halfHeight = std::tan(verticalDegrees * kRadiansPerDegree / 2);
  return 2 * std::atan(halfHeight * widthOverHeight) / kRadiansPerDegree;
}

int povMaxTraceLevel(int maxDepth) {
  return maxDepth + 1;
}

int povAreaLightGrid(const RenderSettings& settings, const PovOptions& options) {
  if (options.areaLightGrid > 0) return options.areaLightGrid;
  const long samples = static_cast<long>(settings.samplesPerPixel) * settings.drtRate;
  int n = 9;
  while (static_cast<long>(n) * n < samples && n < 65) n = 2 * n - 1;
  return n;
}

int povAntialiasDepth(int samplesPerPixel) {
  if (samplesPerPixel <= 1) return 0;
  int best = 1;
  for (int n = 2; n <= 9; ++n) {
    if (std::abs(n * n + 1 - samplesPerPixel) < std::abs(best * best + 1 - samplesPerPixel)) {
      best = n;
    }
  }
  return best;
}

std::vector<std::string> povrayArguments(const PovRun& run) {
  const bool ppm =
      run.imageFile.size() >= 4 && run.imageFile.compare(run.imageFile.size() - 4, 4, ".ppm") == 0;
  std::vector<std::string> args = {
      "+I" + run.sceneFile,
      "+O" + run.imageFile,
      "+W" + std::to_string(run.width),
      "+H" + std::to_string(run.height),
      ppm ? "+FP" : "+FN",
      "-D",               // no preview window
      "File_Gamma=sRGB",  // encode the file as PRT does
      "-J",               // no antialiasing jitter: deterministic
  };
  const int depth = povAntialiasDepth(run.samplesPerPixel);
  if (depth == 0) {
    args.push_back("-A");
  } else {
    // Method 1 at threshold 0 supersamples every pixel with depth^2 samples plus its centre.
    args.insert(args.end(), {"+A0.0", "+AM1", "+R" + std::to_string(depth)});
  }
  if (run.threads > 0) args.push_back("+WT" + std::to_string(run.threads));
  return args;
}

PovExport exportPovray(const Scene& scene, const RenderSettings& settings,
                       const PovOptions& options) {
  PRT_CHECK(scene.image.width > 0 && scene.image.height > 0);
  PovExport result;
  std::string& out = result.text;
  writeHeader(out, scene, settings, options);
  writeGlobalSettings(out, scene);
  writeCamera(out, scene);
  const int grid = povAreaLightGrid(settings, options);
  Bounds box;
  for (const Object& o : scene.objects) {
    if (isBounded(o.shape)) box.extend(boundsOf(o.shape));
  }
  for (const Light& light : scene.lights) writeLight(out, light, grid, box);
  out += '\n';
  PovWriter writer(scene, options);
  for (const Object& object : scene.objects) writer.object(out, object);
  result.images = writer.takeImages();
  return result;
}

std::string toPovray(const Scene& scene, const RenderSettings& settings,
                     const PovOptions& options) {
  return exportPovray(scene, settings, options).text;
}

}  // namespace prt
