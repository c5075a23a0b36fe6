#include "export/pov_exporter.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <numbers>
#include <variant>

#include "core/check.h"

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

void writeLight(std::string& out, const Light& light, int grid) {
  if (const auto* p = std::get_if<PointLight>(&light.shape)) {
    line(out, 0, "light_source { " + vec(p->position) + " color " + rgb(light.color) + " }");
    return;
  }
  const auto* s = std::get_if<SphereLight>(&light.shape);
  const auto* r = std::get_if<RectLight>(&light.shape);
  const Vec3 center = s ? s->center : r->corner + 0.5 * r->edge1 + 0.5 * r->edge2;
  line(out, 0,
       s ? "light_source {  // sphere light, radius " + num(s->radius)
         : "light_source {  // rectangle light, corner " + vec(r->corner));
  line(out, 1, vec(center) + " color " + rgb(light.color));
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
// every surface crossed).
void writeMaterial(std::string& out, const Material& m) {
  const bool localLight = m.ambient > 0 || m.diffuse > 0;
  const double transmit =
      localLight ? std::min(m.transmissivity, kMaxTransmitWithLocalLight) : m.transmissivity;
  const double opacity = 1.0 - transmit;
  const double ambient = localLight ? m.ambient / opacity : 0.0;
  const double diffuse = localLight ? m.diffuse / opacity : 0.0;

  line(out, 1, "texture {");
  if (transmit > 0) {
    line(out, 2,
         "pigment { rgbt <" + num(m.color.x) + ", " + num(m.color.y) + ", " + num(m.color.z) +
             ", " + num(transmit) + "> }");
  } else {
    line(out, 2, "pigment { " + rgb(m.color) + " }");
  }
  std::string finish =
      "finish { ambient " + num(ambient) + " diffuse " + num(diffuse) + " brilliance 1";
  if (m.specular > 0) {
    finish += " phong " + num(m.specular) + " phong_size " + num(m.phongExponent);
  }
  if (m.reflectivity > 0) finish += " reflection { " + num(m.reflectivity) + " }";
  line(out, 2, finish + " }");
  line(out, 1, "}");
  if (m.transmissivity > 0) line(out, 1, "interior { ior " + num(m.ior) + " }");
  if (m.glossDegrees > 0 && m.reflectivity > 0) {
    line(out, 1, "// gloss " + num(m.glossDegrees) + " degrees: POV-Ray reflects as a mirror");
  }
  if (m.translucencyDegrees > 0 && m.transmissivity > 0) {
    line(out, 1,
         "// translucency " + num(m.translucencyDegrees) +
             " degrees: POV-Ray transmits without blur");
  }
  if (transmit != m.transmissivity) {
    line(out, 1,
         "// transmit " + num(m.transmissivity) + " capped at " + num(transmit) +
             " to keep ambient and diffuse");
  }
}

// POV-Ray's mesh2: the vertices (and normals, for smooth shading) once each, then the
// triangles by index. POV-Ray, like PRT, refracts at each triangle a ray crosses.
void writeMesh(std::string& out, const TriangleMesh& mesh) {
  line(out, 0, "mesh2 {");
  auto vectors = [&](const char* name, const std::vector<Vec3>& values) {
    std::string head = name;
    head += " { ";
    head += std::to_string(values.size());
    head += ',';
    line(out, 1, head);
    std::string row;
    for (size_t i = 0; i < values.size(); ++i) {
      row += vec(values[i]);
      if (i + 1 < values.size()) row += ", ";
      if (row.size() > 90 || i + 1 == values.size()) {
        line(out, 2, row);
        row.clear();
      }
    }
    line(out, 1, "}");
  };
  vectors("vertex_vectors", mesh.vertices);
  // A zero normal (a vertex whose faces cancel) would make POV-Ray's interpolation undefined:
  // the mesh is then written flat.
  bool smooth = !mesh.normals.empty();
  for (const Vec3& n : mesh.normals) smooth = smooth && n != Vec3();
  if (smooth) vectors("normal_vectors", mesh.normals);
  std::string faces = "face_indices { ";
  faces += std::to_string(mesh.triangles.size());
  faces += ',';
  line(out, 1, faces);
  std::string row;
  for (size_t i = 0; i < mesh.triangles.size(); ++i) {
    const auto& t = mesh.triangles[i];
    row += '<';
    row += std::to_string(t[0]);
    row += ", ";
    row += std::to_string(t[1]);
    row += ", ";
    row += std::to_string(t[2]);
    row += i + 1 < mesh.triangles.size() ? ">, " : ">";
    if (row.size() > 90 || i + 1 == mesh.triangles.size()) {
      line(out, 2, row);
      row.clear();
    }
  }
  line(out, 1, "}");
}

void writeObject(std::string& out, const Object& object) {
  if (const auto* s = std::get_if<SphereShape>(&object.shape)) {
    line(out, 0, "sphere {");
    line(out, 1, vec(s->center) + ", " + num(s->radius));
  } else if (const auto* b = std::get_if<BoxShape>(&object.shape)) {
    line(out, 0, "box {");
    line(out, 1, vec(b->min) + ", " + vec(b->max));
  } else if (const auto* m = std::get_if<MeshShape>(&object.shape)) {
    writeMesh(out, *m->mesh);
  } else {
    const auto& p = std::get<PlaneShape>(object.shape);
    const Vec3 n = normalize(p.normal);
    // POV-Ray's plane is the solid half-space below it, visible from both sides; PRT's is
    // visible, and casts shadows, only from the side its normal faces.
    line(out, 0, "plane {  // through " + vec(p.point) + "; PRT's plane is one-sided");
    line(out, 1, vec(n) + ", " + num(dot(p.point, n)));
  }
  writeMaterial(out, object.material);
  line(out, 0, "}");
}

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

std::string toPovray(const Scene& scene, const RenderSettings& settings,
                     const PovOptions& options) {
  PRT_CHECK(scene.image.width > 0 && scene.image.height > 0);
  std::string out;
  writeHeader(out, scene, settings, options);
  writeGlobalSettings(out, scene);
  writeCamera(out, scene);
  const int grid = povAreaLightGrid(settings, options);
  for (const Light& light : scene.lights) writeLight(out, light, grid);
  out += '\n';
  for (const Object& object : scene.objects) writeObject(out, object);
  return out;
}

}  // namespace prt
