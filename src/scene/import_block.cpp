#include "scene/import_block.h"

#include <cmath>
#include <stdexcept>
#include <numbers>

#include "core/portable_math.h"
#include "scene/block_reader.h"
#include "scene/key_frames.h"
#include "scene/mesh_block.h"
#include "scene/value_reader.h"
#include "trace/shapes.h"

namespace prt {
namespace {

// The file's objects placed, their texture references moved past the scene's textures.
void addObjects(Scene& scene, const std::vector<Object>& objects, const Transform* placement,
                int32_t textureOffset) {
  for (Object o : objects) {
    auto& instance = std::get<InstanceShape>(o.shape);
    if (placement != nullptr) instance.worldFromMesh = *placement * instance.worldFromMesh;
    PbrSurface& pbr = o.material.pbr;
    for (TextureRef* ref : {&o.material.colorTexture, &o.material.emissionTexture,
                            &pbr.metallicRoughnessTexture, &pbr.normalTexture, &pbr.transmissionTexture}) {
      if (ref->texture >= 0) ref->texture += textureOffset;
    }
    scene.objects.push_back(std::move(o));
  }
}

}  // namespace

Light placeLight(Light light, const Transform& t, double scale, double lightScale) {
  light.color = light.color * lightScale;
  if (light.falloff == Falloff::inverseSquare) light.color = light.color * (scale * scale);
  std::visit(
      [&](auto& shape) {
        using T = std::decay_t<decltype(shape)>;
        if constexpr (std::is_same_v<T, PointLight>) {
          shape.position = t.point(shape.position);
        } else if constexpr (std::is_same_v<T, SpotLight>) {
          shape.position = t.point(shape.position);
          shape.direction = normalize(t.vector(shape.direction));
        } else if constexpr (std::is_same_v<T, DirectionalLight>) {
          shape.direction = normalize(t.vector(shape.direction));
        } else if constexpr (std::is_same_v<T, SphereLight>) {
          shape.center = t.point(shape.center);
          shape.radius *= scale;
        } else {
          shape.corner = t.point(shape.corner);
          shape.edge1 = t.vector(shape.edge1);
          shape.edge2 = t.vector(shape.edge2);
        }
      },
      light.shape);
  return light;
}

Camera placeCamera(Camera camera, const Transform& t, double scale) {
  camera.eye = t.point(camera.eye);
  camera.lookAt = t.point(camera.lookAt);
  camera.up = t.vector(camera.up);
  camera.orthoHeight *= scale;
  return camera;
}

Transform fromRightHanded() { return Transform::scaling({1, 1, -1}); }

namespace {

bool inRange(const Vec3& v) {
  return isFinite(v) && std::abs(v.x) <= kMaxCoordinate && std::abs(v.y) <= kMaxCoordinate &&
         std::abs(v.z) <= kMaxCoordinate;
}

// Whether a placed light is one a light block can say: what the master takes in, its workers
// must read back from the text it writes.
bool lawful(const Light& light) {
  const Color& c = light.color;
  if (!(isFinite(c) && c.x >= 0 && c.y >= 0 && c.z >= 0 && maxComponent(c) <= kMaxColorComponent)) {
    return false;
  }
  return std::visit(
      [](const auto& shape) {
        using T = std::decay_t<decltype(shape)>;
        if constexpr (std::is_same_v<T, PointLight>) return inRange(shape.position);
        if constexpr (std::is_same_v<T, SpotLight>) {
          return inRange(shape.position) && inRange(shape.direction) && length(shape.direction) > 0;
        }
        if constexpr (std::is_same_v<T, DirectionalLight>) {
          return inRange(shape.direction) && length(shape.direction) > 0;
        }
        if constexpr (std::is_same_v<T, SphereLight>) {
          return inRange(shape.center) && shape.radius > 0 && shape.radius <= kMaxCoordinate;
        }
        if constexpr (std::is_same_v<T, RectLight>) {
          return inRange(shape.corner) && inRange(shape.edge1) && inRange(shape.edge2) &&
                 length(cross(shape.edge1, shape.edge2)) > 0;
        }
      },
      light.shape);
}

// The same for a camera, by the camera block's rules.
bool lawful(const Camera& c) {
  if (!inRange(c.eye) || !inRange(c.lookAt) || !inRange(c.up)) return false;
  const Vec3 view = c.lookAt - c.eye;
  if (!(length(view) > 0) || !(length(c.up) > 0)) return false;
  if (!(length(cross(normalize(view), normalize(c.up))) >= 1e-6)) return false;
  if (!(c.fovDegrees > 0 && c.fovDegrees < 180)) return false;
  return c.orthoHeight == 0 || (c.orthoHeight > 0 && c.orthoHeight <= kMaxCoordinate);
}

}  // namespace

Transform placementTransform(const Vec3& scale, const Vec3& rotateDegrees, const Vec3& translate) {
  Transform t = Transform::scaling(scale);
  for (int axis = 0; axis < 3; ++axis) {
    if (rotateDegrees[axis] == 0) continue;
    double s = 0, c = 1;
    sinCosRadians(rotateDegrees[axis] * std::numbers::pi / 180.0, s, c);
    Transform r;
    const int a = (axis + 1) % 3, b = (axis + 2) % 3;  // the plane turned: y z, z x, x y
    r.m[a][a] = c, r.m[a][b] = -s, r.m[b][a] = s, r.m[b][b] = c;
    t = r * t;
  }
  return Transform::translation(translate) * t;
}

void readImportBlock(ImportBlocks& b, const Token& keyword) {
  ImportSource source;
  BlockReader block(b.in, keyword, "import",
                    {"file", "scale", "rotate", "translate", "no_lights", "light_scale", "key"});
  // The placement may be keyed: the whole file then moves (on top of its own animation).
  KeyFrames keys("import", FieldTrack::Target::import, {"scale", "rotate", "translate"});
  const auto put = [](const Vec3& v, double* out) {
    out[0] = v.x, out[1] = v.y, out[2] = v.z;
    return 3;
  };
  const ValueReader readKeyed = [&](const std::string& name, double* out) {
    if (name == "scale") return put(readMeshScale(b.in, name, "import"), out);
    if (name == "rotate") return put(readVector(b.in, name, Range::closed(-36000, 36000)), out);
    return put(readVector(b.in, name, kCoordinate), out);
  };
  while (const Token* param = block.next()) {
    const std::string& name = param->text;
    if (name == "key") keys.read(b.in, *param, readKeyed);
    if (name == "file") source.file = readString(b.in, name);
    if (name == "scale") source.scale = readMeshScale(b.in, name, "import");
    if (name == "rotate") source.rotateDegrees = readVector(b.in, name, Range::closed(-36000, 36000));
    if (name == "translate") source.translate = readVector(b.in, name, kCoordinate);
    if (name == "no_lights") source.lights = false;
    if (name == "light_scale") source.lightScale = readNumber(b.in, name, Range::closed(0, 1e9));
  }
  block.require({"file"});
  const Token& fileToken = block.valueToken("file");
  if (source.file.empty()) b.in.fail(fileToken, "the import's 'file' must not be empty");
  std::filesystem::path path(source.file);
  if (path.is_relative()) path = b.directory / path;
  source.file = std::filesystem::absolute(path).lexically_normal().string();
  // Model files are right-handed (glTF, and assimp makes every format so); PRT, as POV-Ray,
  // is left-handed: the file's z is turned over first, so that a model keeps its shape and a
  // file's camera sees it as the tool that made it did, not mirrored.
  const Transform placement =
      placementTransform(source.scale, source.rotateDegrees, source.translate) * fromRightHanded();
  // The size factor of the placement: the cube root of its volume factor.
  const double scale = std::cbrt(std::abs(placement.determinant()));
  Scene& scene = b.scene;
  source.firstObject = scene.objects.size();
  source.firstLight = scene.lights.size();
  source.firstTexture = scene.textures.size();
  const auto textureOffset = static_cast<int32_t>(scene.textures.size());
  SceneAnimation rig;  // the file's animation, in this import's terms (node indices its own)

  if (b.shipped != nullptr) {
    const size_t k = scene.imports.size();
    if (k >= b.shipped->imports.size()) {
      b.in.fail(fileToken, "the scene has more imports than were sent with it (" +
                               std::to_string(b.shipped->imports.size()) + ")");
    }
    const ShippedImport& shipped = b.shipped->imports[k];
    addObjects(scene, shipped.objects, nullptr, textureOffset);  // placed by the master
    scene.textures.insert(scene.textures.end(), shipped.textures.begin(), shipped.textures.end());
    source.lights = false;  // the master wrote them out as light blocks
  } else {
    std::shared_ptr<const ImportedModel> model;
    if (const auto found = b.models.find(source.file); found != b.models.end()) {
      model = found->second;
    } else {
      try {
        model = std::make_shared<const ImportedModel>(readModelFile(source.file, b.options));
      } catch (const ModelFileError& e) {
        b.in.fail(fileToken, e.what());
      }
      b.models.emplace(source.file, model);
    }
    if (b.warned.insert(source.file).second) {  // once per file, however often imported
      for (const std::string& w : model->warnings) {
        scene.warnings.push_back(b.in.source().fileName() + ":" + std::to_string(keyword.line) +
                                 ": " + w);
      }
    }
    addObjects(scene, model->objects, &placement, textureOffset);
    scene.textures.insert(scene.textures.end(), model->textures.begin(), model->textures.end());
    const ModelRig& r = model->rig;
    const auto importIndex = static_cast<uint32_t>(scene.imports.size());
    const auto nodeBase = static_cast<int32_t>(scene.animation ? scene.animation->nodes.size() : 0);
    // A keyed placement moves everything of a file without an animation of its own: each
    // object, light and camera is bound to no node, in the file's coordinates.
    const bool bindAll = r.empty() && !keys.empty();
    if (!r.empty()) {
      rig.curves = r.curves;
      rig.nodes = r.nodes;
      rig.duration = r.duration;
      for (size_t i = 0; i < model->objects.size(); ++i) {
        rig.objects.push_back({static_cast<uint32_t>(source.firstObject + i), importIndex,
                               r.objectNodes[i], r.objectLocal[i]});
      }
    } else if (bindAll) {
      for (size_t i = 0; i < model->objects.size(); ++i) {
        rig.objects.push_back({static_cast<uint32_t>(source.firstObject + i), importIndex, -1,
                               std::get<InstanceShape>(model->objects[i].shape).worldFromMesh});
      }
    }
    // Lights and cameras a light or camera block could not say (beyond the coordinates a
    // scene allows, once placed) are left out, with a warning.
    size_t leftOut = 0;
    if (source.lights) {
      for (size_t i = 0; i < model->lights.size(); ++i) {
        const Light l = placeLight(model->lights[i], placement, scale, source.lightScale);
        if (lawful(l)) {
          if (!r.empty()) {
            rig.lights.push_back({static_cast<uint32_t>(scene.lights.size()), importIndex,
                                  r.lightNodes[i], r.lightLocal[i]});
          } else if (bindAll) {
            rig.lights.push_back({static_cast<uint32_t>(scene.lights.size()), importIndex, -1,
                                  model->lights[i]});
          }
          scene.lights.push_back(l);
        } else {
          ++leftOut;
        }
      }
    }
    for (size_t i = 0; i < model->cameras.size(); ++i) {
      ModelCamera offered = model->cameras[i];
      offered.camera = placeCamera(offered.camera, placement, scale);
      if (lawful(offered.camera)) {
        std::optional<CameraBinding> binding;
        if (!r.empty()) {
          const int32_t node = r.cameraNodes[i];
          binding = CameraBinding{importIndex, node >= 0 ? node + nodeBase : -1, r.cameraLocal[i]};
        } else if (bindAll) {
          binding = CameraBinding{importIndex, -1, model->cameras[i].camera};
        }
        b.cameras.push_back({std::move(offered), source.file, binding});
      } else {
        ++leftOut;
      }
    }
    if (leftOut > 0) {
      scene.warnings.push_back(b.in.source().fileName() + ":" + std::to_string(keyword.line) +
                               ": model file \"" + source.file + "\": " + std::to_string(leftOut) +
                               (leftOut == 1 ? " light or camera" : " lights or cameras") +
                               " left out: placed beyond the coordinates, intensities or angles "
                               "a scene allows");
    }
  }
  // Every vertex once placed must stay within the coordinates a scene allows.
  for (size_t i = source.firstObject; i < scene.objects.size(); ++i) {
    const Bounds box = boundsOf(scene.objects[i].shape);
    if (!(box.largestMagnitude() <= kMaxCoordinate)) {
      b.in.fail(fileToken, "the model reaches beyond " + std::to_string(static_cast<long>(kMaxCoordinate)) +
                               " world units once placed");
    }
  }
  source.objectCount = scene.objects.size() - source.firstObject;
  source.lightCount = scene.lights.size() - source.firstLight;
  source.textureCount = scene.textures.size() - source.firstTexture;
  const ImportSource base = source;
  scene.imports.push_back(std::move(source));
  keys.finish(scene, static_cast<uint32_t>(scene.imports.size() - 1),
              [&](const std::string& name, double* out) {
                if (name == "scale") return put(base.scale, out);
                if (name == "rotate") return put(base.rotateDegrees, out);
                return put(base.translate, out);
              });
  try {
    addRig(scene, rig);
  } catch (const std::invalid_argument& e) {
    b.in.fail(fileToken, std::string("the model file's animation cannot be played: ") + e.what());
  }
}

Camera framingCamera(const Scene& scene) {
  Bounds box;
  for (const Object& o : scene.objects) {
    if (isBounded(o.shape)) box.extend(boundsOf(o.shape));
  }
  Camera camera;
  camera.fovDegrees = 40;
  if (!(box.lo.x <= box.hi.x)) return camera;  // nothing bounded
  const Vec3 center = box.centroid();
  const double radius = std::max(0.5 * length(box.diagonal()), 1e-6);
  const double distance = radius / std::sin(0.5 * camera.fovDegrees * std::numbers::pi / 180.0);
  camera.lookAt = center;
  // Models face +z in their files (glTF's convention), -z once imported.
  camera.eye = center + distance * normalize(Vec3(0.55, 0.45, -1.0));
  camera.up = {0, 1, 0};
  return camera;
}

}  // namespace prt
