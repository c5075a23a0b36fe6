#pragma once
// Animation: how a scene moves with time, and the scene at a given time (sceneAt).
//
// Two sources feed it, kept in one description so that every driver evaluates them alike:
//  - keyframes of PRT's own format (`key T { ... }` inside camera, light, sphere, box and
//    import blocks; docs/scene-format.md), held as FieldTracks: one parameter of one block
//    as a curve of time, interpolated linearly and held before the first key and after the last;
//  - the animations of imported model files (glTF 2.0 node translation, rotation and scale,
//    with STEP, LINEAR and CUBICSPLINE samplers): the file's node tree as Rig nodes, and the
//    objects, lights and camera that hang from them as bindings, placed by their import.
//
// A scene without either has no animation (Scene::animation is null) and is the same at every
// time. sceneAt is pure and deterministic: the same base scene and time give the same doubles
// on every machine (core/portable_math.h for the trigonometry), which is what keeps a frame
// rendered anywhere bit-identical to the same frame rendered serially.

#include <array>
#include <cstdint>
#include <string>
#include <vector>

#include "core/transform.h"
#include "trace/scene.h"

namespace prt {

enum class Interpolation : uint8_t { step, linear, cubicSpline };

// A sampled function of time (a glTF sampler): `width` numbers per key, in `values` one key
// after another (for cubicSpline three groups per key: in-tangent, value, out-tangent). A curve
// of width 4 marked `rotation` holds unit quaternions (x, y, z, w): linear keys are slerped and
// every result is normalised. Times are seconds, strictly increasing, at least one key.
struct Curve {
  Interpolation interpolation = Interpolation::linear;
  uint8_t width = 3;  // 1, 3 or 4
  bool rotation = false;
  std::vector<double> times;
  std::vector<double> values;

  // Writes `width` numbers for time t into out: the first key's value before it, the last's
  // after it.
  void evaluate(double t, double* out) const;
  // Whether the sizes agree (width, key count, values per key), the times are finite and
  // strictly increasing and the values finite: what every curve must be before use.
  bool wellFormed() const;
  bool operator==(const Curve&) const = default;
};

// One parameter of one block of the scene text animated by `key` entries.
struct FieldTrack {
  enum class Target : uint8_t { camera, light, object, import };
  Target target = Target::camera;
  uint32_t index = 0;  // the light, object or import (Scene::lights, objects, imports); 0 for the camera
  std::string field;   // the block's parameter name: "eye", "center", "translate", ...
  Curve curve;         // linear, width 1 or 3; its first key is at time 0 (the block's own value)
  bool operator==(const FieldTrack&) const = default;
};

// A node of an imported file's tree: its local transform is a matrix, or translation, rotation
// and scale each fixed or following a curve (an index into SceneAnimation::curves, -1: fixed).
struct RigNode {
  int32_t parent = -1;  // an earlier node, or -1: placed directly by its import
  bool hasMatrix = false;
  Transform matrix;     // the local transform when hasMatrix (never animated)
  Vec3 translation{0, 0, 0};
  std::array<double, 4> rotation{0, 0, 0, 1};  // unit quaternion x, y, z, w
  Vec3 scale{1, 1, 1};
  int32_t translationCurve = -1, rotationCurve = -1, scaleCurve = -1;
  bool operator==(const RigNode&) const = default;
};

// An object of an animated import: at time t its InstanceShape's worldFromMesh is
// placement(import, t) * world(node, t) * local (node -1: no node, world the identity).
struct ObjectBinding {
  uint32_t object = 0;  // in Scene::objects
  uint32_t import = 0;  // in Scene::imports
  int32_t node = -1;    // in SceneAnimation::nodes
  Transform local;
  bool operator==(const ObjectBinding&) const = default;
};
// A light of an animated import, given in its node's coordinates (the file's intensity, before
// the import's light scale).
struct LightBinding {
  uint32_t light = 0;  // in Scene::lights
  uint32_t import = 0;
  int32_t node = -1;
  Light local;
  bool operator==(const LightBinding&) const = default;
};
// The scene's camera when it is an animated import's.
struct CameraBinding {
  uint32_t import = 0;
  int32_t node = -1;
  Camera local;
  bool operator==(const CameraBinding&) const = default;
};

struct SceneAnimation {
  std::vector<FieldTrack> fields;
  std::vector<Curve> curves;      // the rigs' curves
  std::vector<RigNode> nodes;     // every import's nodes, parents before their children
  std::vector<ObjectBinding> objects;
  std::vector<LightBinding> lights;
  std::vector<CameraBinding> camera;  // none or one
  double duration = 0;            // seconds: the last key of any curve

  bool empty() const { return fields.empty() && objects.empty() && lights.empty() && camera.empty(); }
  bool operator==(const SceneAnimation&) const = default;
};

// The transform an import block's placement gives (its scale, rotations and translation, then
// the turn from the file's right-handed coordinates); sceneAt applies the block's keys first.
Transform importPlacement(const ImportSource& import);

// The scene's animation, made if it has none, for the parser to add to: copied first when
// another scene shares it, so that no scene sees another's change.
SceneAnimation& editAnimation(Scene& scene);

// The scene at `seconds`: every animated parameter evaluated, every bound object, light and
// camera placed. The base scene itself when it has no animation. The result has no animation.
Scene sceneAt(const Scene& base, double seconds);

// A node's local transform from its translation, rotation (a quaternion x, y, z, w, normalised
// here) and scale: T * R * S, leaving out a rotation or scale that does nothing. The one
// function for it, so that a glTF node read at rest and the same node of a rig evaluated at any
// time give the same doubles.
Transform nodeTransform(const Vec3& translation, const std::array<double, 4>& rotation,
                        const Vec3& scale);

// Adds `rig`'s curves, nodes and bindings (an import's, or all that a master shipped) to the
// scene's animation, making it if there is none: its nodes' parents, curve indices and the
// bindings' nodes are `rig`'s own and are moved past what the scene's animation already
// holds; the bindings' objects, lights and imports are the scene's. A binding for an object
// or light already bound, or a camera when one is, takes that one's place. `rig.fields` is not
// used. Throws std::invalid_argument for a rig inconsistent with itself or the scene (indices
// out of range, a bound object that is no instance of its import, a curve not wellFormed or of
// the wrong width for what it drives).
void addRig(Scene& scene, const SceneAnimation& rig);
// What is wrong with a rig on its own (the checks of addRig that need no scene), or "".
std::string rigProblem(const SceneAnimation& rig);

// What makes a scene evaluated by sceneAt unrenderable, as the parser's checks would say it
// ("the camera's 'look_at' equals its 'eye'"); empty when it renders. Keys are each checked
// as they are read, but a motion between them can still pass a camera through what it looks
// at or turn a box inside out.
std::string frameProblem(const Scene& scene);

// The keyframe fields each block accepts, for the parser and the writer.
bool isKeyedField(FieldTrack::Target target, const std::string& blockTitle, const std::string& field);

}  // namespace prt
