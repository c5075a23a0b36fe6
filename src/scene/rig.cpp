// The rigs of imported model files in a scene's animation (animation.h): a node's local
// transform, and adding one rig (an import's as the parser reads it, or every import's as a
// master ships them) to the scene with its indices checked.

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

#include "scene/animation.h"

namespace prt {
namespace {

[[noreturn]] void refuse(const std::string& why) { throw std::invalid_argument("animation rig: " + why); }

bool finite(const Transform& t) {
  for (const auto& row : t.m) {
    for (const double v : row) {
      if (!std::isfinite(v)) return false;
    }
  }
  return true;
}

// A curve index of a node: none, or a curve of `rig` holding what the path needs.
void checkCurve(const SceneAnimation& rig, int32_t curve, bool rotation) {
  if (curve == -1) return;
  if (curve < 0 || static_cast<size_t>(curve) >= rig.curves.size()) refuse("a curve index out of range");
  const Curve& c = rig.curves[static_cast<size_t>(curve)];
  if (rotation ? (c.width != 4 || !c.rotation) : (c.width != 3 || c.rotation)) {
    refuse("a curve of the wrong width for what it drives");
  }
}

void checkNode(const SceneAnimation& rig, int32_t node) {
  if (node < -1 || (node >= 0 && static_cast<size_t>(node) >= rig.nodes.size())) {
    refuse("a binding's node out of range");
  }
}

void checkImport(const Scene& scene, uint32_t import) {
  if (import >= scene.imports.size()) refuse("a binding's import out of range");
}

// What the rig must be on its own: its curves well formed, its nodes' parents before them, its
// indices in range.
void checkShape(const SceneAnimation& rig) {
  for (const Curve& c : rig.curves) {
    if (!c.wellFormed()) refuse("a curve that is not well formed");
  }
  for (size_t i = 0; i < rig.nodes.size(); ++i) {
    const RigNode& n = rig.nodes[i];
    if (n.parent < -1 || (n.parent >= 0 && static_cast<size_t>(n.parent) >= i)) {
      refuse("a node whose parent does not come before it");
    }
    checkCurve(rig, n.translationCurve, false);
    checkCurve(rig, n.rotationCurve, true);
    checkCurve(rig, n.scaleCurve, false);
    if (!finite(n.matrix) || !isFinite(n.translation) || !isFinite(n.scale) ||
        !std::isfinite(n.rotation[0] + n.rotation[1] + n.rotation[2] + n.rotation[3])) {
      refuse("a node whose transform is not finite");
    }
  }
  for (const ObjectBinding& b : rig.objects) {
    checkNode(rig, b.node);
    if (!finite(b.local)) refuse("an object's transform that is not finite");
  }
  for (const LightBinding& b : rig.lights) checkNode(rig, b.node);
  if (rig.camera.size() > 1) refuse("more than one camera binding");
  for (const CameraBinding& b : rig.camera) checkNode(rig, b.node);
  if (!(std::isfinite(rig.duration) && rig.duration >= 0)) refuse("a duration that is not finite");
}

void checkRig(const Scene& scene, const SceneAnimation& rig) {
  checkShape(rig);
  for (const ObjectBinding& b : rig.objects) {
    checkImport(scene, b.import);
    const ImportSource& import = scene.imports[b.import];
    if (b.object < import.firstObject || b.object - import.firstObject >= import.objectCount ||
        b.object >= scene.objects.size() ||
        !std::holds_alternative<InstanceShape>(scene.objects[b.object].shape)) {
      refuse("a bound object that is not one its import placed");
    }
  }
  for (const LightBinding& b : rig.lights) {
    checkImport(scene, b.import);
    if (b.light >= scene.lights.size()) refuse("a bound light out of range");
  }
  for (const CameraBinding& b : rig.camera) checkImport(scene, b.import);
}

}  // namespace

Transform nodeTransform(const Vec3& translation, const std::array<double, 4>& rotation,
                        const Vec3& scale) {
  Transform t = Transform::translation(translation);
  if (rotation != std::array<double, 4>{0, 0, 0, 1}) {
    t = t * Transform::rotation(rotation[0], rotation[1], rotation[2], rotation[3]);
  }
  if (!(scale == Vec3(1, 1, 1))) t = t * Transform::scaling(scale);
  return t;
}

std::string rigProblem(const SceneAnimation& rig) {
  try {
    checkShape(rig);
  } catch (const std::invalid_argument& e) {
    return e.what();
  }
  return {};
}

void addRig(Scene& scene, const SceneAnimation& rig) {
  if (rig.curves.empty() && rig.nodes.empty() && rig.objects.empty() && rig.lights.empty() &&
      rig.camera.empty()) {
    return;
  }
  checkRig(scene, rig);
  SceneAnimation& a = editAnimation(scene);
  const auto curveBase = static_cast<int32_t>(a.curves.size());
  const auto nodeBase = static_cast<int32_t>(a.nodes.size());
  const auto moved = [](int32_t index, int32_t base) { return index >= 0 ? index + base : index; };
  a.curves.insert(a.curves.end(), rig.curves.begin(), rig.curves.end());
  for (RigNode n : rig.nodes) {
    n.parent = moved(n.parent, nodeBase);
    n.translationCurve = moved(n.translationCurve, curveBase);
    n.rotationCurve = moved(n.rotationCurve, curveBase);
    n.scaleCurve = moved(n.scaleCurve, curveBase);
    a.nodes.push_back(n);
  }
  // Where each object and light already bound has its binding, so that a new one replaces it.
  std::vector<int64_t> objectAt(scene.objects.size(), -1), lightAt(scene.lights.size(), -1);
  for (size_t i = 0; i < a.objects.size(); ++i) {
    if (a.objects[i].object < objectAt.size()) objectAt[a.objects[i].object] = static_cast<int64_t>(i);
  }
  for (size_t i = 0; i < a.lights.size(); ++i) {
    if (a.lights[i].light < lightAt.size()) lightAt[a.lights[i].light] = static_cast<int64_t>(i);
  }
  for (ObjectBinding b : rig.objects) {
    b.node = moved(b.node, nodeBase);
    if (objectAt[b.object] >= 0) {
      a.objects[static_cast<size_t>(objectAt[b.object])] = b;
    } else {
      objectAt[b.object] = static_cast<int64_t>(a.objects.size());
      a.objects.push_back(b);
    }
  }
  for (LightBinding b : rig.lights) {
    b.node = moved(b.node, nodeBase);
    if (lightAt[b.light] >= 0) {
      a.lights[static_cast<size_t>(lightAt[b.light])] = b;
    } else {
      lightAt[b.light] = static_cast<int64_t>(a.lights.size());
      a.lights.push_back(b);
    }
  }
  for (CameraBinding b : rig.camera) {
    b.node = moved(b.node, nodeBase);
    a.camera = {b};
  }
  a.duration = std::max(a.duration, rig.duration);
}

}  // namespace prt
