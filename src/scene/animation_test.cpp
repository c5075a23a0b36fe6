// Keyframes of the scene format and the curves behind every animation: what the parser reads,
// what sceneAt makes of it, what the writer gives back, and the samplers' arithmetic.

#include "scene/animation.h"

#include <gtest/gtest.h>

#include <cmath>

#include "core/input_error.h"
#include "scene/scene_file.h"

namespace prt {
namespace {

const char* kKeyed =
    "camera { eye 0 1 -5 look_at 0 0 0 key 2 { eye 4 1 -5 fov 60 } }\n"
    "image { width 8 height 6 }\n"
    "light point { position 0 5 0 color 1 1 1 key 1 { color 0 0 1 } }\n"
    "sphere { center 0 0 0 radius 1 key 1 { center 2 0 0 } key 3 { radius 2 } }\n"
    "box { min -1 -1 4 max 1 1 5 key 2 { max 1 3 5 } }\n";

TEST(SceneKeyframes, KeysMoveTheirParametersLinearlyAndHoldAfterTheLast) {
  const Scene scene = parseScene(kKeyed, "k.scene");
  ASSERT_TRUE(scene.animation);
  EXPECT_EQ(scene.animation->duration, 3);
  const Scene half = sceneAt(scene, 1.0);
  EXPECT_EQ(half.camera.eye, Vec3(2, 1, -5));
  EXPECT_EQ(half.camera.fovDegrees, 45 + (60 - 45) * 0.5);
  EXPECT_EQ(half.lights[0].color, Color(0, 0, 1));
  const auto& sphere = std::get<SphereShape>(half.objects[0].shape);
  EXPECT_EQ(sphere.center, Vec3(2, 0, 0));
  EXPECT_EQ(sphere.radius, 1 + (2 - 1) / 3.0);  // its own track: keys at 0 and 3
  EXPECT_EQ(std::get<BoxShape>(half.objects[1].shape).max, Vec3(1, 2, 5));
  const Scene late = sceneAt(scene, 10.0);
  EXPECT_EQ(late.camera.eye, Vec3(4, 1, -5));
  EXPECT_EQ(std::get<SphereShape>(late.objects[0].shape).radius, 2);
  const Scene early = sceneAt(scene, -1.0);  // before the first key: the block's own values
  EXPECT_EQ(early.camera.eye, Vec3(0, 1, -5));
  EXPECT_FALSE(late.animation);
}

TEST(SceneKeyframes, TheWriterGivesTheKeysBackBitForBit) {
  const Scene scene = parseScene(kKeyed, "k.scene");
  const std::string text = writeScene(scene);
  const Scene again = parseScene(text, "again.scene");
  ASSERT_TRUE(again.animation);
  EXPECT_EQ(*again.animation, *scene.animation) << text;
  EXPECT_EQ(writeScene(again), text);
}

TEST(SceneKeyframes, MalformedKeysAreLocatedErrors) {
  struct Case {
    const char* block;
    const char* message;
  };
  const Case cases[] = {
      {"sphere { center 0 0 0 radius 1 key 2 { center 1 0 0 } key 1 { center 0 0 0 } }",
       "increasing time"},
      {"sphere { center 0 0 0 radius 1 key 0 { center 1 0 0 } }", "increasing time"},
      {"sphere { center 0 0 0 radius 1 key 1 { color 1 0 0 } }", "keyed parameters: center, radius"},
      {"sphere { center 0 0 0 radius 1 key 1 { } }", "gives no parameter"},
      {"sphere { center 0 0 0 radius 1 key 1 { radius -1 } }", "radius"},
      {"sphere { center 0 0 0 radius 1 key 1 { center 1 0 0 center 2 0 0 } }", "duplicate"},
      {"light point { position 0 1 0 key 1 { radius 2 } }", "cannot be keyed"},
      {"plane { point 0 0 0 normal 0 1 0 key 1 { point 0 1 0 } }", "unknown parameter"},
      {"sphere { center 0 0 0 radius 1 key 1e7 { radius 2 } }", "key"},
  };
  for (const Case& c : cases) {
    const std::string text =
        std::string("camera { eye 0 0 -5 look_at 0 0 0 }\nimage { width 4 height 4 }\n") +
        c.block + "\n";
    try {
      parseScene(text, "bad.scene");
      ADD_FAILURE() << c.block;
    } catch (const InputError& e) {
      EXPECT_NE(e.format().find(c.message), std::string::npos) << c.block << "\n" << e.format();
      EXPECT_NE(e.format().find("bad.scene:3:"), std::string::npos) << e.format();
    }
  }
}

TEST(SceneKeyframes, AFrameThatCannotRenderIsNamed) {
  const Scene scene = parseScene(
      "camera { eye 0 0 -5 look_at 0 0 0 key 2 { eye 0 0 5 } }\nimage { width 4 height 4 }\n",
      "c.scene");
  EXPECT_EQ(frameProblem(sceneAt(scene, 0.5)), "");
  EXPECT_NE(frameProblem(sceneAt(scene, 1.0)).find("look_at"), std::string::npos);
}

TEST(Curves, StepLinearAndCubicSplineAsGltfDefinesThem) {
  Curve c;
  c.width = 1;
  c.times = {0, 1, 3};
  c.values = {0, 10, 30};
  double v = 0;
  c.interpolation = Interpolation::linear;
  c.evaluate(2, &v);
  EXPECT_EQ(v, 20);
  c.interpolation = Interpolation::step;
  c.evaluate(2.9, &v);
  EXPECT_EQ(v, 10);
  c.evaluate(3, &v);
  EXPECT_EQ(v, 30);
  EXPECT_TRUE(c.wellFormed());
  // Hermite: tangents of 10 per second make the spline through (0, 0) and (1, 10) a line.
  Curve h;
  h.width = 1;
  h.interpolation = Interpolation::cubicSpline;
  h.times = {0, 1};
  h.values = {0, 0, 10, 10, 10, 0};  // in, value, out per key
  ASSERT_TRUE(h.wellFormed());
  h.evaluate(0.25, &v);
  EXPECT_NEAR(v, 2.5, 1e-12);
  h.values = {0, 0, 0, 0, 10, 0};  // flat tangents: an ease in and out, 1/2 at the middle
  h.evaluate(0.5, &v);
  EXPECT_NEAR(v, 5, 1e-12);
  h.evaluate(0.25, &v);
  EXPECT_NEAR(v, 10 * (3 * 0.0625 - 2 * 0.015625), 1e-12);
}

TEST(Curves, RotationsSlerpAlongTheShorterArc) {
  Curve r;
  r.width = 4;
  r.rotation = true;
  r.times = {0, 1};
  const double s = std::sqrt(0.5);
  r.values = {0, 0, 0, 1, 0, s, 0, s};  // identity to 90 degrees about y
  double q[4];
  r.evaluate(0.5, q);
  EXPECT_NEAR(q[1], std::sin(M_PI / 8), 1e-12);  // 45 degrees about y
  EXPECT_NEAR(q[3], std::cos(M_PI / 8), 1e-12);
  r.values = {0, 0, 0, 1, 0, -s, 0, -s};  // the same rotation, the quaternion negated
  r.evaluate(0.5, q);
  EXPECT_NEAR(std::abs(q[1]), std::sin(M_PI / 8), 1e-12);
  EXPECT_NEAR(std::abs(q[3]), std::cos(M_PI / 8), 1e-12);
  EXPECT_GT(q[1] * q[3], 0);  // the short way round, not 270 degrees the other way
}

TEST(Curves, MalformedCurvesAreNotWellFormed) {
  Curve c;
  c.width = 3;
  c.times = {0, 1};
  c.values = {0, 0, 0};
  EXPECT_FALSE(c.wellFormed());  // two keys, one value
  c.values = {0, 0, 0, 1, 1, 1};
  EXPECT_TRUE(c.wellFormed());
  c.times = {1, 1};
  EXPECT_FALSE(c.wellFormed());
  c.times = {0, NAN};
  EXPECT_FALSE(c.wellFormed());
  c.times = {};
  c.values = {};
  EXPECT_FALSE(c.wellFormed());
}

}  // namespace
}  // namespace prt
