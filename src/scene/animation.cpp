#include "scene/animation.h"

#include <algorithm>
#include <cmath>
#include <optional>

#include "core/portable_math.h"
#include "scene/import_block.h"

namespace prt {
namespace {

// The key interval [k, k + 1] holding t and the fraction u of the way through it; k is the
// last key when t is at or past it (u = 0).
size_t keyInterval(const std::vector<double>& times, double t, double& u) {
  u = 0;
  if (!(t > times.front())) return 0;
  if (t >= times.back()) return times.size() - 1;
  const size_t k = static_cast<size_t>(std::upper_bound(times.begin(), times.end(), t) -
                                       times.begin()) - 1;
  u = (t - times[k]) / (times[k + 1] - times[k]);
  return k;
}

void normalise4(double* q) {
  const double size = std::sqrt(q[0] * q[0] + q[1] * q[1] + q[2] * q[2] + q[3] * q[3]);
  if (size > 0) {
    for (int i = 0; i < 4; ++i) q[i] /= size;
  } else {
    q[0] = q[1] = q[2] = 0, q[3] = 1;
  }
}

// Spherical linear interpolation of unit quaternions along the shorter arc, as glTF viewers do.
void slerp(const double* a, const double* b, double u, double* out) {
  double dot = a[0] * b[0] + a[1] * b[1] + a[2] * b[2] + a[3] * b[3];
  double sign = 1;
  if (dot < 0) dot = -dot, sign = -1;
  double wa = 1 - u, wb = u;
  if (dot < 0.9995) {  // else the arc is so short that the straight line is as good
    const double theta = std::acos(dot);
    double s = 0, c = 0, sa = 0, ca = 0, sb = 0, cb = 0;
    sinCosRadians(theta, s, c);
    sinCosRadians((1 - u) * theta, sa, ca);
    sinCosRadians(u * theta, sb, cb);
    wa = sa / s, wb = sb / s;
  }
  for (int i = 0; i < 4; ++i) out[i] = wa * a[i] + sign * wb * b[i];
  normalise4(out);
}

Vec3 vec3Of(const double* v) { return {v[0], v[1], v[2]}; }

Vec3 evaluate3(const Curve& curve, double t) {
  double v[4] = {};
  curve.evaluate(t, v);
  return vec3Of(v);
}

// A node's local transform at t: T * R * S, or its fixed matrix.
Transform nodeLocal(const RigNode& node, const std::vector<Curve>& curves, double t) {
  if (node.hasMatrix) return node.matrix;
  Vec3 translation = node.translation, scale = node.scale;
  std::array<double, 4> rotation = node.rotation;
  if (node.translationCurve >= 0) translation = evaluate3(curves[node.translationCurve], t);
  if (node.scaleCurve >= 0) scale = evaluate3(curves[node.scaleCurve], t);
  if (node.rotationCurve >= 0) curves[node.rotationCurve].evaluate(t, rotation.data());
  return nodeTransform(translation, rotation, scale);
}

Vec3 unitOr(const Vec3& v, const Vec3& fallback) {
  const double size = length(v);
  return size > 0 ? v / size : fallback;
}

void applyCameraField(Camera& camera, const std::string& field, const double* v) {
  if (field == "eye") camera.eye = vec3Of(v);
  if (field == "look_at") camera.lookAt = vec3Of(v);
  if (field == "up") camera.up = vec3Of(v);
  if (field == "fov") camera.fovDegrees = v[0];
}

void applyLightField(Light& light, const std::string& field, const double* v) {
  if (field == "color") {
    light.color = vec3Of(v);
    return;
  }
  std::visit(
      [&](auto& shape) {
        using T = std::decay_t<decltype(shape)>;
        if constexpr (std::is_same_v<T, PointLight>) {
          if (field == "position") shape.position = vec3Of(v);
        } else if constexpr (std::is_same_v<T, SphereLight>) {
          if (field == "center") shape.center = vec3Of(v);
          if (field == "radius") shape.radius = v[0];
        } else if constexpr (std::is_same_v<T, SpotLight>) {
          if (field == "position") shape.position = vec3Of(v);
          if (field == "direction") shape.direction = unitOr(vec3Of(v), shape.direction);
        } else if constexpr (std::is_same_v<T, DirectionalLight>) {
          if (field == "direction") shape.direction = unitOr(vec3Of(v), shape.direction);
        } else if constexpr (std::is_same_v<T, RectLight>) {
          if (field == "corner") shape.corner = vec3Of(v);
        }
      },
      light.shape);
}

void applyObjectField(Object& object, const std::string& field, const double* v) {
  if (auto* sphere = std::get_if<SphereShape>(&object.shape)) {
    if (field == "center") sphere->center = vec3Of(v);
    if (field == "radius") sphere->radius = v[0];
  } else if (auto* box = std::get_if<BoxShape>(&object.shape)) {
    if (field == "min") box->min = vec3Of(v);
    if (field == "max") box->max = vec3Of(v);
  }
}

void applyImportField(ImportSource& import, const std::string& field, const double* v) {
  if (field == "scale") import.scale = vec3Of(v);
  if (field == "rotate") import.rotateDegrees = vec3Of(v);
  if (field == "translate") import.translate = vec3Of(v);
}

}  // namespace

void Curve::evaluate(double t, double* out) const {
  double u = 0;
  const size_t k = keyInterval(times, t, u);
  const size_t n = width;
  const bool cubic = interpolation == Interpolation::cubicSpline;
  const size_t stride = cubic ? 3 * n : n;
  const double* value = values.data() + k * stride + (cubic ? n : 0);
  if (u == 0 || interpolation == Interpolation::step) {
    std::copy(value, value + n, out);
  } else if (interpolation == Interpolation::linear) {
    const double* next = value + stride;
    if (rotation) {
      slerp(value, next, u, out);
      return;
    }
    for (size_t i = 0; i < n; ++i) out[i] = value[i] + (next[i] - value[i]) * u;
  } else {
    // Hermite spline (glTF 2.0, Appendix C): the value and out-tangent of key k, the in-tangent
    // and value of key k + 1, the tangents scaled by the interval's length.
    const double d = times[k + 1] - times[k];
    const double* outTangent = value + n;
    const double* nextIn = value + stride - n;
    const double* next = value + stride;
    const double u2 = u * u, u3 = u2 * u;
    const double h00 = 2 * u3 - 3 * u2 + 1, h10 = u3 - 2 * u2 + u, h01 = -2 * u3 + 3 * u2,
                 h11 = u3 - u2;
    for (size_t i = 0; i < n; ++i) {
      out[i] = h00 * value[i] + h10 * d * outTangent[i] + h01 * next[i] + h11 * d * nextIn[i];
    }
  }
  if (rotation) normalise4(out);
}

bool Curve::wellFormed() const {
  if (!(width == 1 || width == 3 || width == 4) || (rotation && width != 4)) return false;
  if (times.empty()) return false;
  const size_t perKey = (interpolation == Interpolation::cubicSpline ? 3u : 1u) * width;
  if (values.size() / perKey != times.size() || values.size() % perKey != 0) return false;
  for (size_t k = 0; k < times.size(); ++k) {
    if (!std::isfinite(times[k]) || (k > 0 && !(times[k] > times[k - 1]))) return false;
  }
  return std::all_of(values.begin(), values.end(), [](double v) { return std::isfinite(v); });
}

Transform importPlacement(const ImportSource& import) {
  return placementTransform(import.scale, import.rotateDegrees, import.translate) *
         fromRightHanded();
}

Scene sceneAt(const Scene& base, double seconds) {
  if (!base.animation) return base;
  const SceneAnimation& a = *base.animation;
  Scene scene = base;
  scene.animation = nullptr;
  double v[4] = {};
  for (const FieldTrack& f : a.fields) {
    f.curve.evaluate(seconds, v);
    switch (f.target) {
      case FieldTrack::Target::camera: applyCameraField(scene.camera, f.field, v); break;
      case FieldTrack::Target::light: applyLightField(scene.lights.at(f.index), f.field, v); break;
      case FieldTrack::Target::object: applyObjectField(scene.objects.at(f.index), f.field, v); break;
      case FieldTrack::Target::import: applyImportField(scene.imports.at(f.index), f.field, v); break;
    }
  }
  std::vector<Transform> world(a.nodes.size());
  for (size_t i = 0; i < a.nodes.size(); ++i) {
    const RigNode& node = a.nodes[i];
    const Transform local = nodeLocal(node, a.curves, seconds);
    world[i] = node.parent >= 0 ? world[static_cast<size_t>(node.parent)] * local : local;
  }
  // Placements, computed once per import that has bindings.
  std::vector<std::optional<Transform>> placements(scene.imports.size());
  const auto placement = [&](uint32_t import) -> const Transform& {
    std::optional<Transform>& p = placements.at(import);
    if (!p) p = importPlacement(scene.imports.at(import));
    return *p;
  };
  const auto carried = [&](uint32_t import, int32_t node) {
    const Transform& p = placement(import);
    return node >= 0 ? p * world.at(static_cast<size_t>(node)) : p;
  };
  std::vector<bool> hidden(scene.objects.size(), false);
  for (const ObjectBinding& b : a.objects) {
    auto& instance = std::get<InstanceShape>(scene.objects.at(b.object).shape);
    instance.worldFromMesh = carried(b.import, b.node) * b.local;
    // A node scaled to nothing hides what hangs from it (animations do that).
    if (!instance.worldFromMesh.isUsable()) hidden[b.object] = true;
  }
  for (const LightBinding& b : a.lights) {
    const Transform& p = placement(b.import);
    const double scale = std::cbrt(std::abs(p.determinant()));
    scene.lights.at(b.light) =
        placeLight(b.local, carried(b.import, b.node), scale, scene.imports[b.import].lightScale);
  }
  for (const CameraBinding& b : a.camera) {
    const double scale = std::cbrt(std::abs(placement(b.import).determinant()));
    scene.camera = placeCamera(b.local, carried(b.import, b.node), scale);
  }
  if (std::find(hidden.begin(), hidden.end(), true) != hidden.end()) {
    std::vector<Object> shown;
    shown.reserve(scene.objects.size());
    for (size_t i = 0; i < scene.objects.size(); ++i) {
      if (!hidden[i]) shown.push_back(std::move(scene.objects[i]));
    }
    scene.objects = std::move(shown);
  }
  return scene;
}

std::string frameProblem(const Scene& scene) {
  const Camera& c = scene.camera;
  const Vec3 view = c.lookAt - c.eye;
  if (!(length(view) > 0)) return "the camera's 'look_at' equals its 'eye'";
  if (!(length(c.up) > 0)) return "the camera's 'up' is zero";
  if (!(length(cross(normalize(view), normalize(c.up))) >= 1e-6)) {
    return "the camera's 'up' is parallel to its view direction";
  }
  if (!(c.fovDegrees > 0 && c.fovDegrees < 180)) return "the camera's 'fov' is not in (0, 180)";
  for (size_t i = 0; i < scene.objects.size(); ++i) {
    const Shape& shape = scene.objects[i].shape;
    if (const auto* box = std::get_if<BoxShape>(&shape)) {
      for (int axis = 0; axis < 3; ++axis) {
        if (!(box->max[axis] > box->min[axis])) {
          return "a box's 'max' does not exceed its 'min' (object " + std::to_string(i) + ")";
        }
      }
    } else if (const auto* sphere = std::get_if<SphereShape>(&shape)) {
      if (!(sphere->radius > 0)) return "a sphere's radius is not positive";
    }
  }
  for (const Light& light : scene.lights) {
    if (const auto* sphere = std::get_if<SphereLight>(&light.shape); sphere && !(sphere->radius > 0)) {
      return "a sphere light's radius is not positive";
    }
  }
  return {};
}

bool isKeyedField(FieldTrack::Target target, const std::string& blockTitle, const std::string& field) {
  using T = FieldTrack::Target;
  const auto among = [&](std::initializer_list<const char*> names) {
    return std::any_of(names.begin(), names.end(), [&](const char* n) { return field == n; });
  };
  switch (target) {
    case T::camera: return among({"eye", "look_at", "up", "fov"});
    case T::import: return among({"scale", "rotate", "translate"});
    case T::object:
      if (blockTitle == "sphere") return among({"center", "radius"});
      if (blockTitle == "box") return among({"min", "max"});
      return false;
    case T::light:
      if (blockTitle == "light point") return among({"position", "color"});
      if (blockTitle == "light sphere") return among({"center", "radius", "color"});
      if (blockTitle == "light spot") return among({"position", "direction", "color"});
      if (blockTitle == "light directional") return among({"direction", "color"});
      if (blockTitle == "light rect") return among({"corner", "color"});
      return false;
  }
  return false;
}

SceneAnimation& editAnimation(Scene& scene) {
  if (!scene.animation || scene.animation.use_count() > 1) {
    scene.animation = scene.animation ? std::make_shared<SceneAnimation>(*scene.animation)
                                      : std::make_shared<SceneAnimation>();
  }
  // Made here as a mutable object and held by this scene alone.
  return const_cast<SceneAnimation&>(*scene.animation);
}

}  // namespace prt
