// The animations of a glTF file as Blender wrote them (scenes/models/animated.glb, made by
// scripts/make-animated-models.py, whose keys the numbers here repeat): the rig the reader
// makes of them, the rig an `import` block adds to the scene with the bindings of its objects,
// light and camera, the scene at a few times, and the rig sent to a worker in the asset pack
// and read back there bit for bit.

#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <filesystem>
#include <functional>
#include <limits>

#include "scene/animation.h"
#include "scene/asset_pack.h"
#include "scene/model_file.h"
#include "scene/scene_file.h"

namespace prt {
namespace {

namespace fs = std::filesystem;

const fs::path kAnimSource(PRT_SOURCE_DIR);
const std::string kAnimated = (kAnimSource / "scenes" / "models" / "animated.glb").string();
const std::string kScene = (kAnimSource / "scenes" / "animated.scene").string();

// The rig's nodes in the order the reader walks the file's tree (roots Base, Stepper, Slider,
// Spinner with its child Moon, Camera, Lamp): every node places something, so all are kept.
enum Node { base, stepper, slider, spinner, moon, camera, lamp, nodeCount };

Vec3 translationOf(const Transform& t) { return {t.m[0][3], t.m[1][3], t.m[2][3]}; }

void expectNear(const Vec3& a, const Vec3& b, double tolerance = 1e-6) {
  EXPECT_NEAR(a.x, b.x, tolerance);
  EXPECT_NEAR(a.y, b.y, tolerance);
  EXPECT_NEAR(a.z, b.z, tolerance);
}

const Transform& placementOf(const Object& o) { return std::get<InstanceShape>(o.shape).worldFromMesh; }

// The rig part of an animation: what the asset pack carries.
SceneAnimation rigOf(const SceneAnimation& a) {
  SceneAnimation rig = a;
  rig.fields.clear();
  return rig;
}

TEST(GltfAnimation, BlendersKeysBecomeTheRigOfTheFile) {
  const ImportedModel model = readModelFile(kAnimated);
  const ModelRig& rig = model.rig;
  ASSERT_EQ(rig.nodes.size(), size_t{nodeCount});
  ASSERT_EQ(rig.curves.size(), 7u);  // 5 animations: Stepper 1, Slider 2, Spinner 2, Camera 1, Lamp 1
  EXPECT_EQ(rig.duration, 2);
  for (const char* w : {"animations are not played", "channel"}) {
    for (const std::string& line : model.warnings) EXPECT_EQ(line.find(w), std::string::npos) << line;
  }

  const RigNode& step = rig.nodes[stepper];
  ASSERT_GE(step.translationCurve, 0);
  EXPECT_EQ(step.rotationCurve, -1);
  const Curve& jump = rig.curves[static_cast<size_t>(step.translationCurve)];
  EXPECT_EQ(jump.interpolation, Interpolation::step);
  EXPECT_EQ(jump.times, (std::vector<double>{0, 1, 2}));
  // Blender's (-1.5, 1, 0.25) at frame 24, y up in glTF: (-1.5, 0.25, -1).
  EXPECT_NEAR(jump.values[3], -1.5, 1e-6);
  EXPECT_NEAR(jump.values[4], 0.25, 1e-6);
  EXPECT_NEAR(jump.values[5], -1.0, 1e-6);

  const RigNode& slide = rig.nodes[slider];
  ASSERT_GE(slide.rotationCurve, 0);
  const Curve& turn = rig.curves[static_cast<size_t>(slide.rotationCurve)];
  EXPECT_EQ(turn.interpolation, Interpolation::linear);
  EXPECT_TRUE(turn.rotation);
  EXPECT_EQ(turn.width, 4);
  EXPECT_EQ(rig.curves[static_cast<size_t>(slide.translationCurve)].interpolation, Interpolation::linear);

  const RigNode& spin = rig.nodes[spinner];
  ASSERT_GE(spin.scaleCurve, 0);
  const Curve& swell = rig.curves[static_cast<size_t>(spin.scaleCurve)];
  EXPECT_EQ(swell.interpolation, Interpolation::cubicSpline);
  ASSERT_EQ(swell.values.size(), 3u * 3u * 3u);  // in-tangent, value, out-tangent per key
  EXPECT_NEAR(swell.values[3 * 3 + 3], 1.5, 1e-6);  // key 1's value
  EXPECT_EQ(rig.curves[static_cast<size_t>(spin.rotationCurve)].interpolation, Interpolation::cubicSpline);
  EXPECT_EQ(rig.curves[static_cast<size_t>(rig.nodes[lamp].translationCurve)].interpolation,
            Interpolation::cubicSpline);
  EXPECT_EQ(rig.curves[static_cast<size_t>(rig.nodes[camera].translationCurve)].interpolation,
            Interpolation::linear);

  // The Moon is never keyed: it moves as the Spinner's child.
  EXPECT_EQ(rig.nodes[moon].parent, spinner);
  EXPECT_EQ(rig.nodes[moon].translationCurve, -1);
  EXPECT_EQ(rig.nodes[base].translationCurve, -1);
  EXPECT_EQ(rig.nodes[base].parent, -1);

  EXPECT_EQ(rig.objectNodes, (std::vector<int32_t>{base, stepper, slider, spinner, moon}));
  EXPECT_EQ(rig.objectLocal.size(), model.objects.size());
  EXPECT_EQ(rig.lightNodes, (std::vector<int32_t>{lamp}));
  EXPECT_EQ(rig.cameraNodes, (std::vector<int32_t>{camera}));
  ASSERT_EQ(rig.lightLocal.size(), 1u);
  EXPECT_EQ(std::get<PointLight>(rig.lightLocal[0].shape).position, Vec3(0, 0, 0));
  EXPECT_EQ(rig.lightLocal[0].color, model.lights[0].color);
  EXPECT_EQ(rig.cameraLocal[0].lookAt, Vec3(0, 0, -1));
}

TEST(GltfAnimation, ObjectsAsReadAreTheNodesAtRestInTheRigsOwnArithmetic) {
  const ImportedModel model = readModelFile(kAnimated);
  const auto local = [&](Node n) {
    const RigNode& r = model.rig.nodes[n];
    return nodeTransform(r.translation, r.rotation, r.scale);
  };
  ASSERT_EQ(model.objects.size(), 5u);
  EXPECT_EQ(placementOf(model.objects[0]), Transform::identity() * local(base));
  EXPECT_EQ(placementOf(model.objects[4]), (Transform::identity() * local(spinner)) * local(moon));
}

TEST(GltfAnimation, FilesWithoutAnimationsHaveNoRig) {
  const ImportedModel model = readModelFile((kAnimSource / "scenes" / "models" / "crate.glb").string());
  EXPECT_TRUE(model.rig.empty());
  EXPECT_TRUE(model.rig.nodes.empty());
  EXPECT_TRUE(model.rig.objectNodes.empty());
  const Scene scene = loadSceneFile((kAnimSource / "scenes" / "crate.scene").string());
  EXPECT_EQ(scene.animation, nullptr);
}

TEST(GltfAnimation, AnimationsMovingOnlyBonesGiveNoRig) {
  const ImportedModel model =
      readModelFile((kAnimSource / "tests" / "models" / "blender-skinned.glb").string());
  EXPECT_TRUE(model.rig.empty());
}

TEST(GltfAnimation, AnImportBindsItsObjectsLightAndCameraToTheSceneAnimation) {
  const Scene scene = loadSceneFile(kScene);
  ASSERT_NE(scene.animation, nullptr);
  const SceneAnimation& a = *scene.animation;
  EXPECT_EQ(a.nodes.size(), size_t{nodeCount});
  EXPECT_EQ(a.curves.size(), 7u);
  EXPECT_EQ(a.duration, 2);
  ASSERT_EQ(a.objects.size(), 5u);
  for (size_t i = 0; i < a.objects.size(); ++i) {
    EXPECT_EQ(a.objects[i].object, scene.imports[0].firstObject + i);
    EXPECT_EQ(a.objects[i].import, 0u);
  }
  EXPECT_EQ(a.objects[4].node, moon);
  ASSERT_EQ(a.lights.size(), 1u);
  EXPECT_EQ(a.lights[0].light, scene.imports[0].firstLight);
  EXPECT_EQ(a.lights[0].node, lamp);
  ASSERT_EQ(a.camera.size(), 1u);  // the file's camera, chosen as the scene has none
  EXPECT_EQ(a.camera[0].node, camera);
}

TEST(GltfAnimation, TheSceneAtTimeZeroIsTheSceneAsRead) {
  const Scene scene = loadSceneFile(kScene);
  const Scene still = sceneAt(scene, 0);
  ASSERT_EQ(still.objects.size(), scene.objects.size());
  for (size_t i = 0; i < scene.objects.size(); ++i) {
    EXPECT_EQ(placementOf(still.objects[i]), placementOf(scene.objects[i])) << i;
  }
  expectNear(std::get<PointLight>(still.lights[0].shape).position,
             std::get<PointLight>(scene.lights[0].shape).position, 1e-12);
  expectNear(still.camera.eye, scene.camera.eye, 1e-12);
}

TEST(GltfAnimation, TheSceneMovesAsBlenderKeyedIt) {
  const Scene scene = loadSceneFile(kScene);
  const size_t first = scene.imports[0].firstObject;
  // STEP: the jump holds until its next key, then happens at once (PRT's z is glTF's negated).
  expectNear(translationOf(placementOf(sceneAt(scene, 0.9).objects[first + stepper])), {-1.5, 0.25, 0});
  expectNear(translationOf(placementOf(sceneAt(scene, 1.5).objects[first + stepper])), {-1.5, 0.25, 1});
  // LINEAR: halfway along.
  expectNear(translationOf(placementOf(sceneAt(scene, 1).objects[first + slider])), {0, 0.3, 0});
  // The camera dollies in linearly: glTF (0, 3, 6) to (0, 2.5, 4.5).
  expectNear(sceneAt(scene, 1).camera.eye, {0, 2.75, -5.25});
  // CUBICSPLINE with Blender's flat end tangents: Hermite's 0.15625 of the way at a quarter.
  const Scene quarter = sceneAt(scene, 0.5);
  expectNear(std::get<PointLight>(quarter.lights[0].shape).position, {-2 + 4 * 0.15625, 3, -2});
  // The Moon rides on the Spinner, 0.7 from its centre, turned by it: at 2 s a quarter turn
  // about y, and the Spinner's scale back at 1.
  const Scene end = sceneAt(scene, 2);
  const Vec3 centre = translationOf(placementOf(end.objects[first + spinner]));
  const Vec3 moonAt = translationOf(placementOf(end.objects[first + moon]));
  expectNear(centre, {1.5, 0.5, 0});
  expectNear(moonAt - centre, {0, 0, 0.7});
}

TEST(GltfAnimation, TheRigTravelsInTheAssetPackAndAWorkerReadsTheSameAnimation) {
  const Scene master = loadSceneFile(kScene);
  const ShippedAssets shipped = unpackAssets(packAssets(master));
  EXPECT_EQ(shipped.rig, rigOf(*master.animation));
  const Scene worker = parseScene(writeScene(master), kScene, shipped);
  ASSERT_NE(worker.animation, nullptr);
  EXPECT_EQ(*worker.animation, *master.animation);
  for (const double t : {0.0, 0.7, 1.3, 2.5}) {
    const Scene a = sceneAt(master, t), b = sceneAt(worker, t);
    ASSERT_EQ(a.objects.size(), b.objects.size());
    for (size_t i = 0; i < a.objects.size(); ++i) EXPECT_EQ(a.objects[i], b.objects[i]) << t;
    EXPECT_EQ(a.lights, b.lights) << t;
    EXPECT_EQ(a.camera, b.camera) << t;
  }
}

// A packed scene whose rig is changed after the pack was made, for unpackAssets to refuse.
std::vector<uint8_t> packWith(const Scene& scene, const std::function<void(SceneAnimation&)>& change) {
  Scene changed = scene;
  SceneAnimation a = *scene.animation;
  change(a);
  changed.animation = std::make_shared<const SceneAnimation>(a);
  return packAssets(changed);
}

TEST(GltfAnimation, PackedRigsThatDoNotHoldTogetherAreRefused) {
  const Scene scene = loadSceneFile(kScene);
  const std::vector<std::pair<std::string, std::function<void(SceneAnimation&)>>> changes = {
      {"a parent after its child", [](SceneAnimation& a) { a.nodes[0].parent = 3; }},
      {"a parent out of range", [](SceneAnimation& a) { a.nodes[4].parent = -7; }},
      {"a curve index out of range", [](SceneAnimation& a) { a.nodes[1].translationCurve = 99; }},
      {"a rotation driven by a 3-vector", [](SceneAnimation& a) {
         a.nodes[2].rotationCurve = a.nodes[2].translationCurve;
       }},
      {"times that do not increase", [](SceneAnimation& a) { a.curves[0].times = {0, 2, 1}; }},
      {"a time that is not finite", [](SceneAnimation& a) { a.curves[0].times[1] = std::nan(""); }},
      {"too few values", [](SceneAnimation& a) { a.curves[0].values.pop_back(); }},
      {"a binding's node out of range", [](SceneAnimation& a) { a.objects[0].node = 7; }},
      {"a binding's import out of range", [](SceneAnimation& a) { a.lights[0].import = 1; }},
      {"two cameras", [](SceneAnimation& a) { a.camera.push_back(a.camera[0]); }},
      {"an unknown interpolation", [](SceneAnimation& a) {
         a.curves[0].interpolation = static_cast<Interpolation>(7);
       }},
      {"a duration that is not finite", [](SceneAnimation& a) { a.duration = std::numeric_limits<double>::infinity(); }},
  };
  for (const auto& [why, change] : changes) {
    EXPECT_THROW(unpackAssets(packWith(scene, change)), std::runtime_error) << why;
  }
  // Every prefix of a good pack is refused, as is a huge count in place of the rig's.
  const std::vector<uint8_t> good = packAssets(scene);
  Scene still = scene;
  still.animation = nullptr;
  const size_t rigAt = packAssets(still).size() - 6 * 8;  // five empty counts and the duration
  for (size_t n = rigAt; n < good.size(); n += 7) {
    EXPECT_THROW(unpackAssets(std::vector<uint8_t>(good.begin(), good.begin() + static_cast<long>(n))),
                 std::runtime_error) << n;
  }
  std::vector<uint8_t> huge = good;
  const uint64_t big = uint64_t{1} << 60;
  std::memcpy(huge.data() + rigAt, &big, 8);  // the curve count
  EXPECT_THROW(unpackAssets(huge), std::runtime_error);
  // A worker's scene whose rig binds what the text does not hold is refused as well.
  ShippedAssets wrong = unpackAssets(good);
  wrong.rig.lights[0].light = 5;
  EXPECT_THROW(parseScene(writeScene(scene), kScene, wrong), std::exception);
}

}  // namespace
}  // namespace prt
